// test_units.cpp - lengths with their units (scene/units.h): the formatter's strings, the
// unit each importer gives its scene (STEP and IGES in Open CASCADE's millimetres, BREP with
// none, glTF in metres, generated scenes with none), and the unit in the face descriptions
// and the JSON that carry lengths.
#include <gtest/gtest.h>

#include <array>
#include <optional>

#include "app/headless.h"
#include "app/measure_json.h"
#include "app/scene_source.h"
#include "scene/face_info.h"
#include "scene/mesh_builder.h"
#include "scene/units.h"
#include "test_data.h"
#include "util/json_writer.h"

namespace {

using scene::LengthUnit;

const LengthUnit mm{"mm", "test"};

TEST(Units, LengthsAreasAndPointsCarryTheirUnit) {
    const scene::Precision p{1e-4}; // a CAD part of about 100 mm
    EXPECT_EQ(scene::formatLength(12.5, mm, p), "12.5 mm");
    EXPECT_EQ(scene::formatLength(1.0 / 3.0, mm, p), "0.3333 mm");
    EXPECT_EQ(scene::formatLength(2.0, scene::gltfUnit(), p), "2 m");
    EXPECT_EQ(scene::formatArea(628.3185307, mm, p), "628.32 mm\u00b2");
    EXPECT_EQ(scene::formatVolume(1570.796327, mm, p), "1570.8 mm\u00b3");
    EXPECT_EQ(scene::formatPoint({1, -2.5, 0}, mm, p), "(1, -2.5, 0) mm");
    // A point at map coordinates keeps its centimetres (issue 35): a float there resolves
    // 0.5 m, but a double scene at 0.01 keeps them.
    EXPECT_EQ(
        scene::formatPoint({458002.4259, 5439009.5708, 121.9374771}, scene::gltfUnit(), {0.01}),
        "(458002.43, 5439009.57, 121.94) m");
    // No unit: bare numbers, the panel's heading says "lengths: no unit" once.
    EXPECT_EQ(scene::formatLength(3.0, scene::generatedUnit(), p), "3");
    EXPECT_EQ(scene::formatArea(3.0, scene::generatedUnit(), p), "3");
    EXPECT_EQ(scene::formatVolume(3.0, scene::generatedUnit(), p), "3");
    EXPECT_EQ(scene::unitHeading(mm), "lengths in mm");
    EXPECT_EQ(scene::unitHeading(scene::generatedUnit()), "lengths: no unit");
    auto unitObject = [](const scene::LengthUnit& unit) {
        util::JsonWriter json;
        json.beginObject();
        scene::unitMember(json, unit);
        return json.endObject().text();
    };
    EXPECT_EQ(unitObject(mm), R"({"unit":"mm"})");
    EXPECT_EQ(unitObject(scene::generatedUnit()), R"({"unit":"none"})");
}

TEST(Units, CadFilesTakeOpenCascadesUnitAndBrepNone) {
    EXPECT_EQ(scene::cadUnit("/tmp/a.step").symbol, "mm");
    EXPECT_EQ(scene::cadUnit("/tmp/a.IGS").symbol, "mm");
    EXPECT_EQ(scene::cadUnit("/tmp/a.brep").symbol, "");
    EXPECT_NE(scene::cadUnit("/tmp/a.brep").source.find("no unit"), std::string::npos);
}

// Each source through loadScene, as the viewer and headless load it.
TEST(Units, EverySourceSaysItsUnit) {
    auto unitOf = [](app::SceneSettings s) { return app::loadScene(s).scene.unit.symbol; };
    app::SceneSettings step;
    step.model = testing_support::requiredData("/usr/share/opencascade/data/step/screw.step");
    step.cadCache = false;
    EXPECT_EQ(unitOf(step), "mm");
    app::SceneSettings gltf; // the default model
    EXPECT_EQ(unitOf(gltf), "m");
    app::SceneSettings procedural;
    procedural.builtin = "procedural";
    EXPECT_EQ(unitOf(procedural), "");
    procedural.copies = 2; // copies keep it
    EXPECT_EQ(app::loadScene(procedural).scene.unit, scene::generatedUnit());
}

// A 1 x 1 x 1 box in millimetres: a face's line and JSON say mm, the area mm².
TEST(Units, FaceDescriptionsAndJsonCarryTheUnit) {
    scene::Scene s;
    s.unit = mm;
    scene::MeshBuilder mb;
    mb.addBox({0, 0, 0}, {1, 1, 1});
    scene::addMaterial(s, "m", {1, 1, 1, 1});
    scene::addObject(s, mb.finish(s, "box"), 0, glm::mat4(1), "box", "box");
    const auto face = scene::faceReport(s, 0);
    ASSERT_TRUE(face);
    EXPECT_EQ(face->unit, mm);
    const std::string line = scene::describeSurface(*face);
    EXPECT_NE(line.find(" mm\u00b2"), std::string::npos) << line;
    EXPECT_EQ(line.find("no unit"), std::string::npos) << line;
    EXPECT_NE(scene::faceReportJson(*face).find("\"unit\":\"mm\""), std::string::npos);
    const std::array<std::optional<glm::dvec3>, 2> points = {glm::dvec3(0), glm::dvec3(3, 4, 0)};
    const std::string measure = app::measureJson(points, {0u, 1u}, mm);
    EXPECT_NE(measure.find("\"distance\":5,"), std::string::npos) << measure;
    EXPECT_NE(measure.find("\"unit\":\"mm\""), std::string::npos) << measure;
}

} // namespace
