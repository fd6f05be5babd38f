// test_step_exterior.cpp - the STEP export of some of a CAD scene's objects (scene/cad/
// step_exterior.h): the written file, loaded again by idview's loader, holds exactly the kept
// objects, in order, with the source's names, paths, placements, per-face colours and
// triangles; shapes used several times stay one product; assemblies left empty go; split
// compounds keep only their kept solids; the refusals are one line each.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>

#include "cad_test_parts.h"
#include "rig_step.h"
#include "scene/cad/cad_loader.h"
#include "scene/cad/step_exterior.h"
#include "test_data.h"

namespace {

namespace fs = std::filesystem;
using scene::CadLoadResult;

const fs::path kScrew = "/usr/share/opencascade/data/step/screw.step";
const fs::path kMotor = "/usr/share/opencascade/data/occ/Motor-c.brep";

// The box of an object's triangles where it is placed.
scene::Bounds worldBox(const scene::Scene& s, const scene::Object& o) {
    const scene::Geometry& g = s.geometries[o.geometry];
    scene::Bounds box{glm::dvec3(1e300), glm::dvec3(-1e300)};
    for (uint32_t v = 0; v < g.vertexCount; ++v) {
        const glm::dvec3 p(s.vertices[g.firstVertex + v].position);
        const glm::dvec3 w(o.world * glm::dvec4(p, 1.0));
        box.min = glm::min(box.min, w);
        box.max = glm::max(box.max, w);
    }
    return box;
}

fs::path scratch() {
    return cadtest::scratchFolder("step_exterior");
}

// One deflection for the source and the export: the automatic one follows the model's box,
// which a subset changes.
scene::CadOptions fixedDeflection() {
    scene::CadOptions options;
    options.deflection = 0.5;
    return options;
}

CadLoadResult load(const fs::path& path) {
    return scene::loadCad(path.string(), fixedDeflection());
}

// What a person sees of an object: its names, placement, each face's colour and (unless
// `triangles` is false) its triangles.
std::string looks(const scene::Scene& s, const scene::Object& o, bool triangles = true) {
    const scene::Geometry& g = s.geometries[o.geometry];
    std::ostringstream out;
    out << o.path << " | " << o.name << " | triangles " << (triangles ? g.triangleCount : 0)
        << " | at";
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 3; ++r) out << ' ' << std::round(o.world[c][r] * 1e6) / 1e6;
    out << " | faces";
    for (uint32_t p = 0; p < g.partCount; ++p) {
        const uint32_t m = g.partMaterials.empty() ? gpu::OBJECT_MATERIAL : g.partMaterials[p];
        const glm::vec4 c = s.materials[m == gpu::OBJECT_MATERIAL ? o.material : m].color;
        out << ' ' << c.r << ',' << c.g << ',' << c.b << ',' << c.a << '/'
            << (triangles ? s.parts[g.firstPart + p].triangleCount : 0);
    }
    return out.str();
}

std::vector<std::string> looksOf(const scene::Scene& s, bool triangles = true) {
    std::vector<std::string> out;
    for (const scene::Object& o : s.objects) out.push_back(looks(s, o, triangles));
    return out;
}

// The source's objects that `keep` marks, as the source shows them.
std::vector<std::string> keptLooks(const scene::Scene& s, const std::vector<uint8_t>& keep) {
    std::vector<std::string> out;
    for (size_t i = 0; i < s.objects.size(); ++i)
        if (keep[i]) out.push_back(looks(s, s.objects[i]));
    return out;
}

std::string textOf(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

size_t countOf(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

fs::path rig() {
    const fs::path path = scratch() / "rig.step";
    if (!fs::exists(path)) cadtest::writeRigStep(path);
    return path;
}

// occt-misc's screw placed three times on a grid by idview-step-copies --instanced: one
// product, three instances "copy 1" to "copy 3" under the assembly "screws".
fs::path threeScrews() {
    const fs::path out = scratch() / "screws.step";
    if (fs::exists(out)) return out;
    if (!fs::exists(kScrew)) ADD_FAILURE() << testing_support::missingData(kScrew);
    const std::string command = std::string(IDVIEW_STEP_COPIES) + " --instanced -n 3 -o '" +
                                out.string() + "' '" + kScrew.string() + "'";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    return out;
}

// Three boxes side by side as one compound in a BREP file: one object per solid.
fs::path threeBoxes() {
    const fs::path path = scratch() / "three boxes.brep";
    if (fs::exists(path)) return path;
    TopoDS_Compound compound;
    BRep_Builder builder;
    builder.MakeCompound(compound);
    for (int i = 0; i < 3; ++i)
        builder.Add(compound,
                    BRepPrimAPI_MakeBox(gp_Pnt(20.0 * i, 0, 0), 10.0 + i, 10.0, 10.0).Shape());
    EXPECT_TRUE(BRepTools::Write(compound, path.c_str()));
    return path;
}

// Writes the kept objects of `source` and loads the file again.
CadLoadResult exported(const fs::path& source, const CadLoadResult& loaded,
                       const std::vector<uint8_t>& keep, const std::string& name) {
    const fs::path out = scratch() / name;
    scene::writeStepSubset(source.string(), loaded.scene, keep, out.string());
    EXPECT_FALSE(fs::exists(out.string() + ".part"));
    return load(out);
}

// What keptAsLoaded wrote: the file loaded, and its text.
struct Written {
    CadLoadResult loaded;
    std::string text;
};

// Writes the objects of `source` that `keep` marks as `name` and checks that the file loads as
// those objects look in the source, one by one.
Written keptAsLoaded(const fs::path& source, const std::vector<uint8_t>& keep,
                     const std::string& name) {
    const CadLoadResult from = load(source);
    EXPECT_EQ(from.scene.objects.size(), keep.size()) << source;
    if (from.scene.objects.size() != keep.size()) return {};
    Written written{exported(source, from, keep, name), textOf(scratch() / name)};
    EXPECT_EQ(looksOf(written.loaded.scene), keptLooks(from.scene, keep));
    return written;
}

// The refusal's text, or "" where it wrote.
std::string refusalOf(const fs::path& source, const scene::Scene& s,
                      const std::vector<uint8_t>& keep, const fs::path& out) {
    try {
        scene::writeStepSubset(source.string(), s, keep, out.string());
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

} // namespace

// The rig: a box placed as "left box" (red) and "right box" (blue) and once more in the turned
// sub-assembly "raised arm", and "pin" (green with a yellow face). Every other object kept:
// left box and pin. The box stays one product; the arm, left empty, goes.
TEST(StepExterior, EveryOtherObjectKeepsItsNamesColoursAndTriangles) {
    const Written written = keptAsLoaded(rig(), {1, 0, 1, 0}, "every other.step");
    EXPECT_EQ(countOf(written.text, "'arm'"), 0u) << "the emptied sub-assembly stays";
    EXPECT_EQ(countOf(written.text, "'right box'"), 0u);
}

// One instance of the box inside the sub-assembly and one outside it: the arm stays, turned,
// and both instances still place one box product.
TEST(StepExterior, KeptInstancesOfOneShapeStayOneProduct) {
    const Written written = keptAsLoaded(rig(), {0, 1, 0, 1}, "instances.step");
    EXPECT_EQ(written.loaded.scene.geometries.size(), 1u) << "the two boxes are one shape";
    EXPECT_EQ(countOf(written.text, "PRODUCT('box'"), 1u);
    EXPECT_EQ(countOf(written.text, "PRODUCT('cylinder'"), 0u);
}

// A real file's part placed three times, the middle instance dropped: the other two still
// place one product.
TEST(StepExterior, ARealPartPlacedThriceLosesOneInstance) {
    const Written written = keptAsLoaded(threeScrews(), {1, 0, 1}, "two screws.step");
    EXPECT_EQ(written.loaded.scene.geometries.size(), 1u);
    EXPECT_EQ(countOf(written.text, "PRODUCT('screw'"), 1u);
    EXPECT_EQ(countOf(written.text, "'copy 1'"), 1u);
    EXPECT_EQ(countOf(written.text, "'copy 2'"), 0u);
    EXPECT_EQ(countOf(written.text, "'copy 3'"), 1u);
}

// Everything kept: the same scene again. screw.step's three toroidal faces come back as
// surfaces of revolution (Open CASCADE's STEP writer restates them so, as idview-step-copies'
// files show), which mesh to other triangles: there the rest must match; a file that has been
// through the writer once (the rig, the copies of the screw) matches triangle for triangle.
TEST(StepExterior, KeepingEverythingGivesTheSameScene) {
    for (const fs::path& file : {kScrew, rig(), threeScrews()}) {
        if (!fs::exists(file)) FAIL() << testing_support::missingData(file);
        const CadLoadResult source = load(file);
        const std::vector<uint8_t> keep(source.scene.objects.size(), 1);
        const CadLoadResult out = exported(file, source, keep, "all.step");
        const bool triangles = file != kScrew;
        EXPECT_EQ(looksOf(out.scene, triangles), looksOf(source.scene, triangles)) << file;
    }
}

// A BREP compound split into three solids, the middle one dropped: the file's two solids load
// as "solid 1" and "solid 2" (the numbers are idview's, given again), with the kept ones'
// triangles and placements, under a product named after the BREP file.
TEST(StepExterior, ASplitCompoundKeepsOnlyItsKeptSolids) {
    const CadLoadResult source = load(threeBoxes());
    ASSERT_EQ(source.scene.objects.size(), 3u);
    const CadLoadResult out = exported(threeBoxes(), source, {1, 0, 1}, "two boxes.step");
    scene::Scene renumbered = source.scene; // the third solid is the second now
    renumbered.objects[2].name = "solid 2";
    renumbered.objects[2].path = "three boxes/solid 2";
    const std::vector<std::string> expected = keptLooks(renumbered, {1, 0, 1});
    EXPECT_EQ(looksOf(out.scene), expected);
}

TEST(StepExterior, RefusalsAreOneLine) {
    const CadLoadResult source = load(rig());
    const std::vector<uint8_t> all(source.scene.objects.size(), 1);
    const fs::path out = scratch() / "refused.step";
    EXPECT_EQ(refusalOf(rig(), source.scene, std::vector<uint8_t>(all.size(), 0), out),
              "nothing to write: no solid was seen");
    EXPECT_EQ(refusalOf(scratch() / "engine.glb", source.scene, all, out),
              "STEP export needs a CAD source (STEP, IGES or BREP); this scene is a mesh "
              "(engine.glb)");
    const std::string unwritable = refusalOf(rig(), source.scene, all, scratch() / "no/x.step");
    EXPECT_NE(unwritable.find("no/x.step: cannot write the STEP file there ("), std::string::npos)
        << unwritable;
    // The scene of another file: its objects are not the rig's.
    const std::string mismatch = refusalOf(kScrew, source.scene, all, out);
    EXPECT_NE(mismatch.find("screw.step: the file no longer gives the scene loaded from it"),
              std::string::npos)
        << mismatch;
    for (const std::string& line : {unwritable, mismatch})
        EXPECT_EQ(line.find('\n'), std::string::npos) << line;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(out.string() + ".part"));
}
// Motor-c.brep's 17 solids, placed inside their compound, the 4th and 8th kept: they come back
// as "solid 1" and "solid 2" with their faces, where they were. Open CASCADE's writer applies
// a solid's placement inside a compound to its geometry (the object's matrix is then the
// identity), and the surfaces it writes mesh a little differently: the boxes agree within
// the deflection.
TEST(StepExterior, ARealCompoundKeepsItsKeptSolidsInPlace) {
    if (!fs::exists(kMotor)) FAIL() << testing_support::missingData(kMotor);
    const CadLoadResult source = load(kMotor);
    ASSERT_EQ(source.scene.objects.size(), 17u);
    std::vector<uint8_t> keep(17, 0);
    keep[3] = keep[7] = 1;
    const CadLoadResult out = exported(kMotor, source, keep, "motor.step");
    ASSERT_EQ(out.scene.objects.size(), 2u);
    const size_t kept[] = {3, 7};
    for (size_t i = 0; i < 2; ++i) {
        const scene::Object& was = source.scene.objects[kept[i]];
        const scene::Object& is = out.scene.objects[i];
        EXPECT_EQ(is.path, "Motor-c/solid " + std::to_string(i + 1));
        EXPECT_EQ(out.scene.geometries[is.geometry].partCount,
                  source.scene.geometries[was.geometry].partCount);
        const scene::Bounds a = worldBox(source.scene, was), b = worldBox(out.scene, is);
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_NEAR(a.min[axis], b.min[axis], fixedDeflection().deflection) << is.path;
            EXPECT_NEAR(a.max[axis], b.max[axis], fixedDeflection().deflection) << is.path;
        }
    }
}
