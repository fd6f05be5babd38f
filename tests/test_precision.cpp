// test_precision.cpp - the numbers people read (scene/precision.h): rounded to the model's
// precision, Open CASCADE's tolerance for CAD and a float's resolution at the model's size,
// tiny values and -0 shown as 0, unit vectors to a millionth; and each loaded scene's
// precision from its B-rep's tolerance and its bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "app/scene_source.h"
#include "scene/cad/brep_inspect.h"
#include "scene/inspect.h"
#include "scene/precision.h"
#include "test_data.h"

namespace {

using scene::Precision;

// The issue's numbers, on a CAD model of about 100 mm at Open CASCADE's 1e-7: a float there
// resolves 7.6e-6, so lengths are known to 1e-4.
TEST(Precision, CadModelRoundsTheIssuesNumbers) {
    const Precision p = scene::modelPrecision(100.0, 1e-7);
    EXPECT_DOUBLE_EQ(p.length, 1e-4);
    EXPECT_EQ(scene::lengthText(-9.09276772e-15, p), "0");
    EXPECT_EQ(scene::lengthText(1.5000002, p), "1.5");
    EXPECT_EQ(scene::lengthText(-49.9999877, p), "-50");
    EXPECT_EQ(scene::lengthText(12.34567, p), "12.3457");
    EXPECT_EQ(scene::pointText({-9.09276772e-15, 1.5000002, -49.9999877}, p), "(0, 1.5, -50)");
}

// A coarse B-rep (a file's tolerance of 1e-3) rounds coarser than the floats would.
TEST(Precision, TheToleranceWinsWhereItIsCoarser) {
    EXPECT_DOUBLE_EQ(scene::modelPrecision(100.0, 1e-3).length, 1e-3);
    EXPECT_DOUBLE_EQ(scene::modelPrecision(100.0, 2e-3).length, 1e-2);
    EXPECT_EQ(scene::lengthText(10.0004, scene::modelPrecision(100.0, 1e-3)), "10");
}

// A mesh 1e5 across: a float resolves 0.0078 there, four of them 0.03: tenths.
TEST(Precision, MeshFarOutRoundsToTheFloatsResolution) {
    const Precision p = scene::modelPrecision(1e5, 0.0);
    EXPECT_DOUBLE_EQ(p.length, 0.1);
    EXPECT_EQ(scene::lengthText(99999.96875, p), "100000");
    EXPECT_EQ(scene::lengthText(-12345.678, p), "-12345.7");
    // A metre-sized one keeps micrometres.
    EXPECT_DOUBLE_EQ(scene::modelPrecision(1.0, 0.0).length, 1e-6);
}

TEST(Precision, TinyAndNegativeZeroReadZero) {
    const Precision p{1e-4};
    EXPECT_EQ(scene::lengthText(-0.0, p), "0");
    EXPECT_EQ(scene::lengthText(-0.00004, p), "0");
    EXPECT_EQ(scene::lengthText(0.00006, p), "0.0001");
    EXPECT_EQ(scene::rounded(-1e-300, 1e-6), "0");
    // Steps of ten and more round the units too.
    EXPECT_EQ(scene::rounded(123456.7, 10.0), "123460");
    // No precision set: six significant digits, as before.
    EXPECT_EQ(scene::lengthText(1.0 / 3.0, Precision{}), "0.333333");
}

// Areas and volumes follow from the length's step: 628.3 mm² (a side of 25) is known to
// 2 * 25 * 1e-4 = 5e-3, so to hundredths; 1570.8 mm³ to 3 * 135 * 1e-4 = 0.04, tenths.
TEST(Precision, AreasAndVolumesFollowTheLengthsStep) {
    const Precision p{1e-4};
    EXPECT_EQ(scene::areaText(628.3185307, p), "628.32");
    EXPECT_EQ(scene::volumeText(1570.796327, p), "1570.8");
    EXPECT_EQ(scene::areaText(-3e-12, p), "0");
    EXPECT_EQ(scene::volumeText(0.0, p), "0");
}

TEST(Precision, DirectionsAndAngles) {
    EXPECT_EQ(scene::directionText({-2.22e-16, 1e-17, -1.0}), "(0, 0, -1)");
    EXPECT_EQ(scene::directionText({0.7071067811865476, -0.7071067811865476, 0.0}),
              "(0.707107, -0.707107, 0)");
    EXPECT_EQ(scene::angleText(89.99999999), "90");
    EXPECT_EQ(scene::angleText(0.0572957795), "0.0573");
}

// A CAD file's precision: its vertices' tolerance (Open CASCADE's, at least 1e-7) against the
// floats at its size, as loadScene sets it.
TEST(Precision, LoadedScenesCarryTheirs) {
    app::SceneSettings brep;
    brep.model = testing_support::requiredData("/usr/share/opencascade/data/occ/Motor-c.brep");
    brep.cadCache = false;
    const scene::Scene cad = app::loadScene(brep).scene;
    const double tolerance = scene::brepTolerance(cad);
    EXPECT_GE(tolerance, 1e-7);
    const scene::Bounds b = cad.bounds();
    const glm::dvec3 reach = glm::max(glm::abs(b.min), glm::abs(b.max));
    const double size = std::max({reach.x, reach.y, reach.z});
    EXPECT_DOUBLE_EQ(cad.precision.length, scene::modelPrecision(size, tolerance).length);
    EXPECT_GE(cad.precision.length, tolerance);
    app::SceneSettings gltf; // the default model: no B-rep, the floats alone
    const scene::Scene mesh = app::loadScene(gltf).scene;
    EXPECT_EQ(scene::brepTolerance(mesh), 0.0);
    EXPECT_GT(mesh.precision.length, 0.0);
}

} // namespace
