// test_cad_loader.cpp - the STEP, IGES and BREP loader on the sample data Debian ships in
// occt-misc (objects and parts against Open CASCADE's own counts), on an assembly written
// here with OCCT (instancing, names, colours, placements), on malformed files, and through
// the glTF export.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <random>
#include <set>
#include <unistd.h>

#include <gtest/gtest.h>

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include "cad_test_parts.h"
#include "rig_step.h"
#include "scene/cad/cad_loader.h"
#include "scene/gltf/gltf_loader.h"
#include "scene/gltf/gltf_writer.h"
#include "test_data.h"

namespace {

namespace fs = std::filesystem;
using scene::CadLoadResult;
using scene::ModelError;

const fs::path kData = "/usr/share/opencascade/data";

fs::path tempDir() {
    return cadtest::scratchFolder("cad");
}

// What OCCT itself says a file holds: leaf objects and faces, each located instance counted.
struct OcctCounts {
    size_t objects = 0;
    uint32_t faces = 0;
};
uint32_t facesOf(const TopoDS_Shape& shape) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    return uint32_t(faces.Extent());
}

// The STEP samples' leaves are single solids.
OcctCounts stepCounts(const fs::path& path) {
    std::optional<scene::OcctLeaksIgnored> ignored(std::in_place); // first reader's setup
    STEPControl_Reader reader;
    ignored.reset();
    EXPECT_EQ(reader.ReadFile(path.c_str()), IFSelect_RetDone);
    reader.TransferRoots();
    TopTools_IndexedMapOfShape solids;
    TopExp::MapShapes(reader.OneShape(), TopAbs_SOLID, solids);
    return {size_t(solids.Extent()), facesOf(reader.OneShape())};
}

// IGES: one object per root entity that has faces.
OcctCounts igesCounts(const fs::path& path) {
    std::optional<scene::OcctLeaksIgnored> ignored(std::in_place);
    IGESControl_Reader reader;
    ignored.reset();
    EXPECT_EQ(reader.ReadFile(path.c_str()), IFSelect_RetDone);
    reader.TransferRoots();
    OcctCounts counts;
    for (Standard_Integer i = 1; i <= reader.NbShapes(); ++i)
        counts.objects += facesOf(reader.Shape(i)) > 0;
    counts.faces = facesOf(reader.OneShape());
    return counts;
}

OcctCounts brepCounts(const fs::path& path) {
    TopoDS_Shape shape;
    BRep_Builder builder;
    EXPECT_TRUE(BRepTools::Read(shape, path.c_str(), builder));
    return {1, facesOf(shape)};
}

// The scene is consistent, and each part's triangles lie in its geometry's range.
void expectWellFormed(const scene::Scene& s) {
    EXPECT_NO_THROW(scene::validate(s));
    for (const scene::Geometry& g : s.geometries) {
        uint32_t covered = 0;
        for (uint32_t p = 0; p < g.partCount; ++p) {
            const scene::Part& part = s.parts[g.firstPart + p];
            EXPECT_GT(part.triangleCount, 0u);
            EXPECT_EQ(part.firstTriangle, covered);
            EXPECT_LE(part.firstTriangle + part.triangleCount, g.triangleCount);
            covered += part.triangleCount;
        }
        EXPECT_EQ(covered, g.triangleCount);
        // Each part names its B-rep face; the numbers only go up (failed faces skip one).
        ASSERT_EQ(g.partFaces.size(), g.partCount) << g.name;
        for (uint32_t p = 1; p < g.partCount; ++p) EXPECT_GT(g.partFaces[p], g.partFaces[p - 1]);
        for (uint32_t i = 0; i < 3 * g.triangleCount; ++i)
            ASSERT_LT(s.indices[g.firstIndex + i], g.vertexCount);
    }
    for (const scene::Object& o : s.objects) {
        EXPECT_FALSE(o.name.empty());
        EXPECT_TRUE(o.path.ends_with(o.name)) << o.path;
    }
}

CadLoadResult loadSample(const fs::path& path) {
    if (!fs::exists(path)) throw std::runtime_error(testing_support::missingData(path));
    return scene::loadCad(path.string());
}

TEST(CadLoader, KnowsItsExtensionsInAnyCase) {
    for (const char* name : {"a.step", "b.STP", "c.Iges", "d.igs", "e.BREP", "dir.x/f.stp"})
        EXPECT_TRUE(scene::isCadPath(name)) << name;
    for (const char* name : {"a.glb", "b.gltf", "step", "c.stl", "d.brep.txt"})
        EXPECT_FALSE(scene::isCadPath(name)) << name;
}

// Loads a sample and compares it with OCCT's own counts: every face triangulated, one object
// per leaf, one part per face.
CadLoadResult expectMatches(const fs::path& path, OcctCounts (*count)(const fs::path&)) {
    const OcctCounts want = count(path);
    CadLoadResult r = loadSample(path);
    expectWellFormed(r.scene);
    EXPECT_EQ(r.facesFailed, 0u) << path;
    EXPECT_EQ(r.scene.objects.size(), want.objects) << path;
    EXPECT_EQ(r.scene.uniquePartCount(), want.faces) << path;
    EXPECT_GT(r.deflection, 0.0) << path;
    for (const scene::Geometry& g : r.scene.geometries) // every face has its part: i is face i
        for (uint32_t p = 0; p < g.partFaces.size(); ++p) EXPECT_EQ(g.partFaces[p], p) << path;
    return r;
}

TEST(CadLoader, StepSamplesMatchOcctCounts) {
    for (const char* name : {"step/screw.step", "step/linkrods.step"}) {
        REQUIRE_DATA(kData / name);
        expectMatches(kData / name, stepCounts);
    }
}

TEST(CadLoader, IgesBearingMatchesOcctCounts) {
    REQUIRE_DATA(kData / "iges/bearing.iges");
    expectMatches(kData / "iges/bearing.iges", igesCounts);
}

TEST(CadLoader, BrepIsOneObjectNamedAfterTheFile) {
    const fs::path path = kData / "occ/bottle.brep";
    REQUIRE_DATA(path);
    const CadLoadResult r = expectMatches(path, brepCounts);
    ASSERT_EQ(r.scene.objects.size(), 1u);
    EXPECT_EQ(r.scene.objects[0].name, "bottle");
    EXPECT_EQ(r.scene.objects[0].path, "bottle");
}

TEST(CadLoader, FinerDeflectionMakesMoreTriangles) {
    const fs::path path = kData / "occ/bottle.brep";
    REQUIRE_DATA(path);
    const CadLoadResult coarse = scene::loadCad(path.string(), {1.0, 0.8});
    const CadLoadResult fine = scene::loadCad(path.string(), {0.01, 0.2});
    EXPECT_DOUBLE_EQ(coarse.deflection, 1.0);
    EXPECT_EQ(coarse.scene.uniquePartCount(), fine.scene.uniquePartCount());
    EXPECT_LT(coarse.scene.drawnTriangleCount(), fine.scene.drawnTriangleCount());
}

TEST(CadLoader, ReportsProgressByStage) {
    const fs::path path = kData / "occ/bottle.brep";
    REQUIRE_DATA(path);
    std::vector<std::string> stages;
    bool inRange = true;
    scene::loadCad(path.string(), {}, [&](const char* stage, double fraction) {
        if (stages.empty() || stages.back() != stage) stages.push_back(stage);
        inRange &= fraction >= 0.0 && fraction <= 1.0;
    });
    EXPECT_EQ(stages, (std::vector<std::string>{"reading", "tessellating", "building"}));
    EXPECT_TRUE(inRange);
}

// ---- an assembly written here -----------------------------------------------------------

fs::path writeRig() {
    const fs::path path = tempDir() / "rig.step";
    cadtest::writeRigStep(path);
    return path;
}

const scene::Object* objectNamed(const scene::Scene& s, const std::string& name) {
    for (const scene::Object& o : s.objects)
        if (o.name == name) return &o;
    return nullptr;
}

TEST(CadLoader, WrittenAssemblyKeepsInstancesNamesColoursAndPlacements) {
    const fs::path path = writeRig();
    std::set<std::string> stages;
    const CadLoadResult r =
        scene::loadCad(path.string(), {}, [&](const char* stage, double) { stages.insert(stage); });
    // The stages of a STEP file the splitter cuts (scene/step/step_split.h): its skeleton,
    // then its pieces, meshed as they are read.
    EXPECT_EQ(stages, (std::set<std::string>{"reading", "reading the assembly structure",
                                             "loading solids", "building"}));
    const scene::Scene& s = r.scene;
    expectWellFormed(s);
    ASSERT_EQ(s.objects.size(), 4u);
    const scene::Object* left = objectNamed(s, "left box");
    const scene::Object* right = objectNamed(s, "right box");
    const scene::Object* pin = objectNamed(s, "pin");
    ASSERT_TRUE(left && right && pin);
    EXPECT_EQ(left->path, "rig/left box");
    EXPECT_EQ(pin->path, "rig/pin");
    // One geometry for both boxes, with a part per face.
    EXPECT_EQ(left->geometry, right->geometry);
    EXPECT_NE(left->geometry, pin->geometry);
    EXPECT_EQ(s.geometries.size(), 2u);
    EXPECT_EQ(s.geometries[left->geometry].partCount, 6u);
    EXPECT_EQ(s.geometries[left->geometry].name, "box");
    EXPECT_EQ(s.geometries[pin->geometry].partCount, 3u);
    EXPECT_EQ(s.uniquePartCount(), 21u);
    // World translations.
    EXPECT_EQ(glm::vec3(left->world[3]), glm::vec3(100.0f, 0.0f, 0.0f));
    EXPECT_EQ(glm::vec3(right->world[3]), glm::vec3(0.0f, 200.0f, 0.0f));
    EXPECT_EQ(glm::vec3(pin->world[3]), glm::vec3(0.0f, 0.0f, 50.0f));
    // Nested placements compose parent first: the sub-assembly's turn moves the box's offset.
    const scene::Object* armBox = objectNamed(s, "arm box");
    ASSERT_TRUE(armBox);
    EXPECT_EQ(armBox->path, "rig/raised arm/arm box");
    EXPECT_EQ(armBox->geometry, left->geometry);
    const glm::vec3 armAt(armBox->world[3]);
    EXPECT_NEAR(glm::distance(armAt, glm::vec3(0.0f, 5.0f, 100.0f)), 0.0f, 1e-4f) << armAt.x;
    const glm::vec3 armX(armBox->world[0]); // the box's x axis, turned onto y
    EXPECT_NEAR(glm::distance(armX, glm::vec3(0.0f, 1.0f, 0.0f)), 0.0f, 1e-6f);
    // Colours: instance colours for the boxes, the product's for the pin.
    auto colorOf = [&](const scene::Object* o) {
        return glm::vec3(s.materials[o->material].color);
    };
    EXPECT_EQ(colorOf(left), glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(colorOf(right), glm::vec3(0.0f, 0.0f, 1.0f));
    EXPECT_EQ(colorOf(pin), glm::vec3(0.0f, 1.0f, 0.0f));
    // Face, then shape, then product: the pin's second face keeps its own yellow, its other
    // faces take the object's; the boxes' faces have no colours of their own.
    const scene::Geometry& pinShape = s.geometries[pin->geometry];
    ASSERT_EQ(pinShape.partMaterials.size(), 3u);
    EXPECT_EQ(pinShape.partMaterials[0], gpu::OBJECT_MATERIAL);
    EXPECT_EQ(pinShape.partMaterials[2], gpu::OBJECT_MATERIAL);
    ASSERT_LT(pinShape.partMaterials[1], s.materials.size());
    EXPECT_EQ(glm::vec3(s.materials[pinShape.partMaterials[1]].color), glm::vec3(1, 1, 0));
    EXPECT_TRUE(s.geometries[left->geometry].partMaterials.empty());
    // The box's local bounds: 10 x 20 x 30 from the origin.
    const scene::Geometry& g = s.geometries[left->geometry];
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (uint32_t v = 0; v < g.vertexCount; ++v) {
        lo = glm::min(lo, s.vertices[g.firstVertex + v].position);
        hi = glm::max(hi, s.vertices[g.firstVertex + v].position);
    }
    EXPECT_EQ(lo, glm::vec3(0.0f));
    EXPECT_EQ(hi, glm::vec3(10.0f, 20.0f, 30.0f));
}

TEST(CadLoader, ExportKeepsObjectNames) {
    const fs::path path = writeRig();
    const CadLoadResult r = scene::loadCad(path.string());
    const fs::path glb = tempDir() / "rig.glb";
    scene::writeGlb(r.scene, glb.string());
    const scene::LoadResult back = scene::loadGltf(glb.string());
    std::multiset<std::string> before, after;
    for (const scene::Object& o : r.scene.objects) before.insert(o.name);
    for (const scene::Object& o : back.scene.objects) after.insert(o.name);
    EXPECT_EQ(before, after);
    EXPECT_EQ(back.scene.uniquePartCount(), r.scene.uniquePartCount());
}

// ---- bad input ----------------------------------------------------------------------------

void expectRefused(const fs::path& path, const std::string& needle = {}) {
    try {
        scene::loadCad(path.string());
        ADD_FAILURE() << path << " loaded";
    } catch (const ModelError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(path.string() + ": ", 0), 0u) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        EXPECT_NE(what.find(needle), std::string::npos) << what;
    }
}

fs::path writeFile(const std::string& name, const std::string& bytes) {
    const fs::path path = tempDir() / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

std::string randomBytes(size_t n, uint32_t seed) {
    std::mt19937 random(seed);
    std::string bytes(n, '\0');
    for (char& c : bytes) c = char(random() & 0xFF);
    return bytes;
}

TEST(CadLoader, RefusesMissingAndEmptyFiles) {
    expectRefused(tempDir() / "missing.step", "not found");
    for (const char* name : {"empty.step", "empty.iges", "empty.brep"})
        expectRefused(writeFile(name, ""), "empty");
    const fs::path folder = tempDir() / "folder.step";
    fs::create_directories(folder);
    expectRefused(folder, "not a regular file");
}

TEST(CadLoader, RefusesGarbage) {
    for (const char* ext : {".step", ".igs", ".brep"}) {
        expectRefused(writeFile(std::string("junk") + ext, randomBytes(5000, 7)));
        expectRefused(writeFile(std::string("text") + ext, "hello, this is not CAD\n"));
    }
    // A STEP header, then binary junk.
    expectRefused(
        writeFile("junk_after_header.step", "ISO-10303-21;\nHEADER;\n" + randomBytes(5000, 11)));
}

// The first third of a real file, cut mid-line.
void expectTruncatedRefused(const fs::path& source, const std::string& name) {
    std::ifstream in(source, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    expectRefused(writeFile(name, bytes.substr(0, bytes.size() / 3)));
}

TEST(CadLoader, RefusesTruncatedIgesAndBrep) {
    const fs::path iges = kData / "iges/bearing.iges", brep = kData / "occ/bottle.brep";
    REQUIRE_DATA(iges);
    REQUIRE_DATA(brep);
    expectTruncatedRefused(iges, "truncated.iges");
    expectTruncatedRefused(brep, "truncated.brep");
}

TEST(CadLoader, RefusesTruncatedStep) {
    const fs::path source = kData / "step/screw.step";
    REQUIRE_DATA(source);
    expectTruncatedRefused(source, "truncated.step");
}

TEST(CadLoader, RefusesStepWithoutShapes) {
    const std::string text = "ISO-10303-21;\n"
                             "HEADER;\n"
                             "FILE_DESCRIPTION((''),'2;1');\n"
                             "FILE_NAME('nothing','2024-01-01T00:00:00',(''),(''),'','','');\n"
                             "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\n"
                             "ENDSEC;\n"
                             "DATA;\n"
                             "ENDSEC;\n"
                             "END-ISO-10303-21;\n";
    expectRefused(writeFile("noshapes.step", text), "no");
}

TEST(CadLoader, RefusesBadDeflection) {
    const fs::path path = kData / "occ/bottle.brep";
    REQUIRE_DATA(path);
    EXPECT_THROW(scene::loadCad(path.string(), {-1.0, 0.5}), ModelError);
    EXPECT_THROW(scene::loadCad(path.string(), {0.0, 0.0}), ModelError);
}

} // namespace
