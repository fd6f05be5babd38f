// test_cad_cache.cpp - the CAD tessellation cache (scene/cad/cad_cache.h) in a private
// XDG_CACHE_HOME: a second load is a hit with the very scene of the first; --no-cache neither
// reads nor writes; a truncated entry, a flipped payload byte, another format version and a
// changed file are each a miss whose entry is written anew and then valid. And --max-triangles
// (scene::loadCad): the mesher stops between faces once the budget is spent, and the refusal
// is one line naming the file and a larger deflection, which leads under the limit.
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <random>
#include <set>
#include <tuple>
#include <unistd.h>

#include <gtest/gtest.h>

// Before Open CASCADE's headers, whose Handle macro would rewrite vk::Handle.
#include "app/scene_source.h"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>

#include "cad_test_parts.h"
#include "scene/cad/brep_occt.h"
#include "scene/cad/cad_cache.h"
#include "scene/cad/cad_mesh.h"
#include "scene/lod.h"
#include "test_data.h"
#include "util/hash64.h"

namespace {

namespace fs = std::filesystem;
using namespace scene;

const fs::path kMotor = "/usr/share/opencascade/data/occ/Motor-c.brep";

// Each test gets an empty cache folder of its own as XDG_CACHE_HOME, and the previous value
// back afterwards.
class CadCache : public ::testing::Test {
  protected:
    void SetUp() override {
        REQUIRE_DATA(kMotor);
        root_ = fs::temp_directory_path() /
                ("idview_cache_" + std::to_string(::getpid()) + "_" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root_);
        fs::create_directories(root_);
        cacheHome_.emplace(root_);
    }
    void TearDown() override {
        cacheHome_.reset();
        std::error_code ignored;
        fs::remove_all(root_, ignored);
    }
    fs::path folder() const { return root_ / "idview"; }
    std::vector<fs::path> entries() const {
        std::vector<fs::path> found;
        if (fs::exists(folder()))
            for (const auto& e : fs::directory_iterator(folder())) found.push_back(e.path());
        return found;
    }
    fs::path root_;
    std::optional<cadtest::CacheHome> cacheHome_;
};

// Every array, name, per-part list and placement equal.
void expectSameScene(const Scene& a, const Scene& b) {
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    for (size_t i = 0; i < a.vertices.size(); ++i) {
        ASSERT_EQ(a.vertices[i].position, b.vertices[i].position) << i;
        ASSERT_EQ(a.vertices[i].normal, b.vertices[i].normal) << i;
    }
    EXPECT_EQ(a.indices, b.indices);
    ASSERT_EQ(a.parts.size(), b.parts.size());
    for (size_t i = 0; i < a.parts.size(); ++i) {
        EXPECT_EQ(a.parts[i].firstTriangle, b.parts[i].firstTriangle);
        EXPECT_EQ(a.parts[i].triangleCount, b.parts[i].triangleCount);
    }
    ASSERT_EQ(a.geometries.size(), b.geometries.size());
    for (size_t i = 0; i < a.geometries.size(); ++i) {
        const Geometry &g = a.geometries[i], &h = b.geometries[i];
        EXPECT_EQ(g.name, h.name);
        EXPECT_EQ(std::tie(g.firstVertex, g.vertexCount, g.firstIndex, g.triangleCount, g.firstPart,
                           g.partCount, g.level),
                  std::tie(h.firstVertex, h.vertexCount, h.firstIndex, h.triangleCount, h.firstPart,
                           h.partCount, h.level));
        EXPECT_EQ(g.lodError, h.lodError);
        EXPECT_EQ(g.partFaces, h.partFaces);
        EXPECT_EQ(g.partMaterials, h.partMaterials);
        EXPECT_EQ(g.levels, h.levels);
        ASSERT_EQ(g.partSurfaces.size(), h.partSurfaces.size());
        for (size_t p = 0; p < g.partSurfaces.size(); ++p) {
            const SurfaceInfo &s = g.partSurfaces[p], &t = h.partSurfaces[p];
            EXPECT_EQ(s.kind, t.kind);
            EXPECT_EQ(s.area, t.area);
            EXPECT_EQ(s.normal, t.normal);
            EXPECT_EQ(s.d, t.d);
            EXPECT_EQ(s.radius, t.radius);
            EXPECT_EQ(s.axisOrigin, t.axisOrigin);
            EXPECT_EQ(s.axisDirection, t.axisDirection);
        }
    }
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (size_t i = 0; i < a.materials.size(); ++i) {
        EXPECT_EQ(a.materials[i].name, b.materials[i].name);
        EXPECT_EQ(a.materials[i].color, b.materials[i].color);
    }
    ASSERT_EQ(a.objects.size(), b.objects.size());
    for (size_t i = 0; i < a.objects.size(); ++i) {
        const Object &o = a.objects[i], &p = b.objects[i];
        EXPECT_EQ(std::tie(o.geometry, o.material, o.uniquePartOffset, o.name, o.path),
                  std::tie(p.geometry, p.material, p.uniquePartOffset, p.name, p.path));
        EXPECT_EQ(o.world, p.world);
    }
}

// The kept B-rep (Scene::brep) names each part's face: the face's exact area, measured now,
// is the one the load recorded for that part (Geometry::partSurfaces) before any cache.
void expectBrepFacesMatchParts(const Scene& scene) {
    ASSERT_TRUE(scene.brep);
    ASSERT_EQ(scene.brep->geometryCount(), scene.geometries.size());
    for (uint32_t g = 0; g < scene.geometries.size(); ++g)
        EXPECT_EQ(scene.brep->has(g), scene.geometries[g].level == 0) << "geometry " << g;
    for (uint32_t id = 0; id < scene.uniquePartCount(); ++id) {
        const auto face = partFace(scene, id);
        ASSERT_TRUE(face) << "part " << id;
        const auto ref = scene.locate(id);
        const Geometry& g = scene.geometries[scene.objects[ref->object].geometry];
        GProp_GProps props;
        BRepGProp::SurfaceProperties(*face, props);
        EXPECT_NEAR(props.Mass(), g.partSurfaces[ref->localPart].area,
                    1e-9 * std::max(1.0, props.Mass()))
            << "part " << id;
    }
}

TEST(Hash64, EveryBitOfTheInputCounts) {
    std::vector<unsigned char> bytes(67); // whole words and a tail
    for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<unsigned char>(i * 37);
    const uint64_t base = util::hash64(bytes.data(), bytes.size());
    std::set<uint64_t> seen{base};
    for (size_t bit = 0; bit < 8 * bytes.size(); ++bit) {
        bytes[bit / 8] ^= static_cast<unsigned char>(1u << (bit % 8));
        EXPECT_TRUE(seen.insert(util::hash64(bytes.data(), bytes.size())).second) << "bit " << bit;
        bytes[bit / 8] ^= static_cast<unsigned char>(1u << (bit % 8));
    }
    // The top bits of two words flipped together: plain word-wise FNV-1a cancels them.
    bytes[7] ^= 0x80;
    bytes[15] ^= 0x80;
    EXPECT_NE(util::hash64(bytes.data(), bytes.size()), base);
    EXPECT_NE(util::hash64(bytes.data(), bytes.size() - 1), base); // length counts
}

// IGES faces are sewn, which leaves them in another order than the shape's own face map; the
// cache keeps the parts' order all the same.
TEST_F(CadCache, ASewnShapeComesBackFaceForFace) {
    const std::string bearing = "/usr/share/opencascade/data/iges/bearing.iges";
    REQUIRE_DATA(bearing);
    const CadLoadResult first = loadCadCached(bearing, {}, {}, 1);
    const CadLoadResult second = loadCadCached(bearing, {}, {}, 1);
    ASSERT_EQ(second.cache, "hit");
    expectBrepFacesMatchParts(first.scene);
    expectBrepFacesMatchParts(second.scene);
}

TEST_F(CadCache, SecondLoadIsAHitWithTheSameScene) {
    const CadLoadResult first = loadCadCached(kMotor.string(), {}, {}, maxLevels);
    EXPECT_EQ(first.cache, "miss");
    EXPECT_EQ(first.cacheNote, "no entry");
    ASSERT_EQ(entries().size(), 1u);
    bool progressed = false;
    const CadLoadResult second = loadCadCached(
        kMotor.string(), {}, [&](const char*, double) { progressed = true; }, maxLevels);
    EXPECT_EQ(second.cache, "hit");
    EXPECT_FALSE(progressed); // Open CASCADE never ran
    expectSameScene(first.scene, second.scene);
    EXPECT_EQ(first.warnings, second.warnings);
    EXPECT_EQ(first.deflection, second.deflection);
    EXPECT_EQ(first.faces, second.faces);
    EXPECT_EQ(first.facesFailed, second.facesFailed);
    // And both are what the loader makes without a cache, levels of detail included.
    const CadLoadResult plain = loadCad(kMotor.string(), {}, {}, maxLevels);
    expectSameScene(plain.scene, second.scene);
    expectBrepFacesMatchParts(first.scene);
    expectBrepFacesMatchParts(second.scene);
    // Levels of detail came back, several deep.
    size_t levels = 0, deepest = 0;
    for (const Geometry& g : second.scene.geometries) {
        levels += g.level > 0;
        deepest = std::max<size_t>(deepest, g.level);
    }
    EXPECT_GT(levels, 0u);
    EXPECT_GE(deepest, 2u);
    // Other settings are another entry.
    EXPECT_EQ(loadCadCached(kMotor.string(), {}, {}, 1).cache, "miss");
    EXPECT_EQ(entries().size(), 2u);
}

TEST_F(CadCache, NoCacheNeitherReadsNorWrites) {
    app::SceneSettings settings;
    settings.model = kMotor.string();
    settings.cadCache = false;
    const app::LoadedScene off = app::loadScene(settings);
    EXPECT_EQ(off.cadLoad.cache, "off");
    EXPECT_TRUE(entries().empty());
    // An entry that says something else: the cache serves it, --no-cache does not read it.
    const auto key = cadCacheKey(kMotor.string(), {}, 1);
    ASSERT_TRUE(key);
    CadLoadResult planted = loadCad(kMotor.string());
    planted.scene.objects[0].name = "planted";
    const fs::path entry = cadCacheEntry(folder(), *key);
    ASSERT_EQ(writeCadCache(entry, *key, planted), "");
    const auto written = fs::last_write_time(entry);
    const uintmax_t size = fs::file_size(entry);
    EXPECT_NE(app::loadScene(settings).scene.objects[0].name, "planted");
    EXPECT_EQ(fs::last_write_time(entry), written);
    EXPECT_EQ(fs::file_size(entry), size);
    EXPECT_EQ(entries().size(), 1u);
    settings.cadCache = true;
    const app::LoadedScene on = app::loadScene(settings);
    EXPECT_EQ(on.cadLoad.cache, "hit");
    EXPECT_EQ(on.scene.objects[0].name, "planted");
}

std::string readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
}
void writeBytes(const fs::path& file, const std::string& bytes) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

// The entry's head: magic (8), version (4), key length (8) and key, payload length (8),
// payload checksum (8); then the payload, then the shapes' bytes.
uint64_t keySizeOf(const std::string& entry) {
    uint64_t size = 0;
    std::memcpy(&size, entry.data() + 12, 8);
    return size;
}
size_t payloadAt(const std::string& entry) {
    return 36 + keySizeOf(entry);
}
uint64_t payloadSizeOf(const std::string& entry) {
    uint64_t size = 0;
    std::memcpy(&size, entry.data() + 20 + keySizeOf(entry), 8);
    return size;
}

// A hit reads no shape: each is read back from the entry when a query first asks for it, and
// so is every shape of a load once its entry is written (the bytes it held go).
TEST_F(CadCache, ShapesAreReadFromTheEntryWhenAsked) {
    const CadLoadResult first = loadCadCached(kMotor.string(), {});
    ASSERT_EQ(first.cache, "miss");
    for (const CadLoadResult* r : {&first}) {
        EXPECT_EQ(r->scene.brep->decodedCount(), 0u);
        for (uint32_t g = 0; g < r->scene.geometries.size(); ++g)
            EXPECT_TRUE(r->scene.brep->stored(g).bytes.empty()) << "geometry " << g;
    }
    const CadLoadResult hit = loadCadCached(kMotor.string(), {});
    ASSERT_EQ(hit.cache, "hit");
    EXPECT_EQ(hit.scene.brep->decodedCount(), 0u);
    ASSERT_TRUE(partFace(hit.scene, 5));
    EXPECT_EQ(hit.scene.brep->decodedCount(), 1u);
    expectBrepFacesMatchParts(hit.scene);
    EXPECT_EQ(hit.scene.brep->decodedCount(), hit.scene.geometries.size());
}

// A shape's bytes damaged in the entry: the scene still opens from it (the shapes are checked
// when read), and asking for that shape is refused in words, never a wrong face.
TEST_F(CadCache, ADamagedShapeIsRefusedWhenAsked) {
    loadCadCached(kMotor.string(), {});
    ASSERT_EQ(entries().size(), 1u);
    const fs::path entry = entries()[0];
    std::string bytes = readBytes(entry);
    bytes[bytes.size() - 20] ^= 0x20; // inside the last geometry's shape
    writeBytes(entry, bytes);
    const CadLoadResult hit = loadCadCached(kMotor.string(), {});
    ASSERT_EQ(hit.cache, "hit");
    const uint32_t last = uint32_t(hit.scene.geometries.size() - 1);
    EXPECT_NO_THROW(hit.scene.brep->shape(0));
    try {
        hit.scene.brep->shape(last);
        ADD_FAILURE() << "a damaged shape was decoded";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "the tessellation cache's entry changed under the scene");
    }
}

TEST_F(CadCache, DamagedEntriesAreMissesAndWrittenAnew) {
    const CadLoadResult original = loadCadCached(kMotor.string(), {});
    ASSERT_EQ(entries().size(), 1u);
    const fs::path entry = entries()[0];
    const std::string good = readBytes(entry);
    const auto key = cadCacheKey(kMotor.string(), {}, 1);
    ASSERT_TRUE(key);
    struct Damage {
        const char* what;
        std::function<std::string(std::string)> apply;
        const char* note; // how the miss says it, a prefix
    };
    const std::vector<Damage> damages = {
        {"truncated", [](std::string b) { return b.substr(0, b.size() / 2); }, "damaged"},
        {"cut before the checksum", [](std::string b) { return b.substr(0, b.size() - 3); },
         "damaged"},
        {"a payload byte flipped",
         [](std::string b) {
             b[payloadAt(b) + 10] ^= 0x10; // inside the scene's arrays
             return b;
         },
         "checksum mismatch"},
        {"another version",
         [](std::string b) {
             b[8] ^= 0x01; // the format version follows the 8-byte magic
             return b;
         },
         "format version"},
        {"not an entry", [](std::string) { return std::string("junk"); }, "damaged"},
        {"empty", [](std::string) { return std::string(); }, "damaged"},
    };
    for (const Damage& d : damages) {
        writeBytes(entry, d.apply(good));
        const CadLoadResult r = loadCadCached(kMotor.string(), {});
        EXPECT_EQ(r.cache, "miss") << d.what;
        EXPECT_TRUE(r.cacheNote.starts_with(d.note)) << d.what << ": " << r.cacheNote;
        expectSameScene(original.scene, r.scene);
        // Written anew: valid, and the next load a hit.
        std::string why;
        const auto reread = readCadCache(entry, *key, why);
        ASSERT_TRUE(reread) << d.what << ": " << why;
        expectSameScene(original.scene, reread->scene);
        EXPECT_EQ(loadCadCached(kMotor.string(), {}).cache, "hit") << d.what;
    }
    EXPECT_EQ(entries().size(), 1u); // no temporary file left behind
}

// Damage the checksum cannot see (bytes changed and the checksum recomputed, as a bug
// writing entries would): every read either refuses the entry or gives a valid scene.
TEST_F(CadCache, DamageBehindAGoodChecksumNeverGivesABrokenScene) {
    loadCadCached(kMotor.string(), {});
    ASSERT_EQ(entries().size(), 1u);
    const fs::path entry = entries()[0];
    const std::string good = readBytes(entry);
    const auto key = cadCacheKey(kMotor.string(), {}, 1);
    ASSERT_TRUE(key);
    const size_t at0 = payloadAt(good);
    const uint64_t payloadSize = payloadSizeOf(good);
    ASSERT_LT(at0 + payloadSize, good.size()); // the shapes' bytes follow
    std::mt19937 random(7);
    size_t refused = 0;
    for (int trial = 0; trial < 300; ++trial) {
        std::string bad = good;
        // The first bytes hold the counts and sizes that steer the decoding.
        const size_t at = at0 + (trial < 150 ? random() % 64 : random() % payloadSize);
        bad[at] = static_cast<char>(random());
        const uint64_t checksum = util::hash64(bad.data() + at0, payloadSize);
        std::memcpy(bad.data() + at0 - 8, &checksum, 8);
        writeBytes(entry, bad);
        std::string why;
        if (const auto r = readCadCache(entry, *key, why))
            EXPECT_NO_THROW(validate(r->scene)) << "byte " << at;
        else
            ++refused;
    }
    EXPECT_GT(refused, 0u);
}

TEST_F(CadCache, AChangedFileIsAMissAndReplacesItsEntry) {
    const fs::path copy = root_ / "motor.brep";
    fs::copy_file(kMotor, copy);
    const CadLoadResult first = loadCadCached(copy.string(), {});
    EXPECT_EQ(first.cache, "miss");
    ASSERT_EQ(entries().size(), 1u);
    std::ofstream(copy, std::ios::app) << "\n"; // the same shape, other bytes
    const CadLoadResult second = loadCadCached(copy.string(), {});
    EXPECT_EQ(second.cache, "miss");
    EXPECT_TRUE(second.cacheNote.starts_with("stale")) << second.cacheNote;
    ASSERT_EQ(entries().size(), 1u); // the same entry, rewritten
    std::string why;
    const auto key = cadCacheKey(copy.string(), {}, 1);
    ASSERT_TRUE(key);
    ASSERT_TRUE(readCadCache(entries()[0], *key, why)) << why;
    EXPECT_EQ(loadCadCached(copy.string(), {}).cache, "hit");
}

// Sequential meshing of Motor-c.brep with a budget of 1000 triangles: faces stop being
// meshed right after the one that passes it, and the count is what the faces hold.
TEST(MaxTriangles, TheMesherStopsBetweenFaces) {
    REQUIRE_DATA(kMotor);
    TopoDS_Shape shape;
    BRep_Builder builder;
    ASSERT_TRUE(BRepTools::Read(shape, kMotor.c_str(), builder));
    BRepTools::Clean(shape); // the file holds triangulations: every face is meshed anew
    IMeshTools_Parameters parameters;
    parameters.Deflection = 0.5;
    parameters.Angle = 0.5;
    parameters.InParallel = false;
    MeshBudget budget;
    budget.maxTriangles = 1000;
    meshCounted(shape, parameters, budget, {});
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    uint64_t triangles = 0, largest = 0;
    int meshed = 0;
    for (int f = 1; f <= faces.Extent(); ++f) {
        TopLoc_Location location;
        const auto t = BRep_Tool::Triangulation(TopoDS::Face(faces(f)), location);
        if (t.IsNull()) continue;
        ++meshed;
        triangles += uint64_t(t->NbTriangles());
        largest = std::max(largest, uint64_t(t->NbTriangles()));
    }
    EXPECT_TRUE(budget.over);
    EXPECT_EQ(budget.triangles, triangles);
    EXPECT_EQ(int(budget.facesMeshed), meshed);
    EXPECT_GT(triangles, 1000u);
    EXPECT_LE(triangles, 1000u + largest); // the last face meshed passed it
    EXPECT_LT(meshed, faces.Extent());
}

TEST(MaxTriangles, TheRefusalNamesTheFileAndDeflectionsThatLeadUnderTheLimit) {
    REQUIRE_DATA(kMotor);
    const CadLoadResult full = loadCad(kMotor.string());
    const uint64_t triangles = full.scene.indices.size() / 3;
    CadOptions options;
    options.maxTriangles = triangles / 2;
    std::string message;
    try {
        loadCad(kMotor.string(), options);
    } catch (const ModelError& e) {
        message = e.what();
    }
    const std::string head = kMotor.string() + ": the tessellation passes --max-triangles " +
                             std::to_string(options.maxTriangles);
    EXPECT_TRUE(message.starts_with(head)) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
    // The suggestion is a guess (Open CASCADE's triangles do not always fall as the
    // deflection grows), so following it may take another step or two, never more.
    double deflection = full.deflection;
    for (int step = 0; step < 3 && !message.empty(); ++step) {
        const auto at = message.find("try --deflection ");
        ASSERT_NE(at, std::string::npos) << message;
        options.deflection = std::stod(message.substr(at + 17));
        EXPECT_GT(options.deflection, deflection) << message;
        deflection = options.deflection;
        message.clear();
        try {
            const CadLoadResult coarser = loadCad(kMotor.string(), options);
            EXPECT_LE(coarser.scene.indices.size() / 3, options.maxTriangles);
        } catch (const ModelError& e) {
            message = e.what();
            EXPECT_TRUE(message.starts_with(head)) << message;
        }
    }
    EXPECT_TRUE(message.empty()) << "still refused: " << message;
}

// A cached load above the limit is refused as a fresh one is.
TEST_F(CadCache, AHitAboveTheLimitIsRefused) {
    const CadLoadResult full = loadCadCached(kMotor.string(), {});
    CadOptions options;
    options.maxTriangles = full.scene.indices.size() / 3 - 1;
    try {
        loadCadCached(kMotor.string(), options);
        ADD_FAILURE() << "no refusal";
    } catch (const ModelError& e) {
        EXPECT_TRUE(std::string(e.what()).starts_with(kMotor.string() +
                                                      ": the tessellation passes --max-triangles"))
            << e.what();
    }
}

} // namespace
