// test_empty_parts_output.cpp - what is made of a scene with empty parts (empty_parts_scene.h):
// its levels of detail are the plain scene's, with the empty parts empty at every level and no
// level for a geometry without triangles; the glTF export holds the parts with triangles and
// loads back as the plain scene's export; --stats counts the empty parts, and an object
// without triangles has no box in --properties.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include "app/scene_source.h"
#include "empty_parts_scene.h"
#include "scene/bounds.h"
#include "scene/gltf/gltf_loader.h"
#include "scene/gltf/gltf_writer.h"
#include "scene/inspect.h"
#include "scene/lod.h"
#include "scene/mesh_inspect.h"

using namespace scene;
using testing_support::emptySlots;
using testing_support::fourObjectScene;
using testing_support::withEmptyParts;

namespace {

// `scene` written and loaded back; where `kept`, to the file the glTF validator's test checks
// (IDVIEW_KEEP_EXPORT, tests/CMakeLists.txt) when that is set, else to a temporary file.
LoadResult writeAndLoad(const Scene& scene, const std::string& name, bool kept = false) {
    const char* keep = kept ? std::getenv("IDVIEW_KEEP_EXPORT") : nullptr;
    const std::filesystem::path path =
        keep ? std::filesystem::path(keep)
             : std::filesystem::temp_directory_path() /
                   ("idview-" + name + "-" + std::to_string(getpid()) + ".glb");
    writeGlb(scene, path.string());
    LoadResult loaded = loadGltf(path.string());
    if (!keep) std::filesystem::remove(path);
    return loaded;
}

// The member `"name":` of a JSON line, as written (up to the next ',' or '}').
std::string member(const std::string& json, const std::string& name) {
    const size_t at = json.find("\"" + name + "\":");
    if (at == std::string::npos) return "missing";
    const size_t from = at + name.size() + 3;
    return json.substr(from, json.find_first_of(",}", from) - from);
}

} // namespace

// With a budget that holds every level wanted, the levels do not depend on the empty parts:
// each level is the plain scene's, triangle for triangle, with empty parts in the same slots.
TEST(EmptyParts, LevelsOfDetailAreThoseOfThePlainScene) {
    Scene plain = fourObjectScene();
    Scene s = withEmptyParts(plain).scene;
    LodOptions options;
    options.memory = 100.0f; // the empty parts' bytes would otherwise weigh in the budget
    buildLevels(plain, options);
    buildLevels(s, options);
    size_t levels = 0;
    for (uint32_t g = 0; g < 3; ++g) {
        const Geometry& full = plain.geometries[g];
        ASSERT_EQ(s.geometries[g].levels.size(), full.levels.size()) << full.name;
        for (size_t l = 0; l < full.levels.size(); ++l, ++levels) {
            const Geometry& a = plain.geometries[full.levels[l]];
            const Geometry& b = s.geometries[s.geometries[g].levels[l]];
            EXPECT_EQ(b.lodError, a.lodError) << a.name;
            ASSERT_EQ(b.triangleCount, a.triangleCount) << a.name;
            ASSERT_EQ(b.vertexCount, a.vertexCount) << a.name;
            for (uint32_t v = 0; v < a.vertexCount; ++v)
                EXPECT_EQ(s.vertices[b.firstVertex + v].position,
                          plain.vertices[a.firstVertex + v].position);
            for (uint32_t i = 0; i < 3 * a.triangleCount; ++i)
                EXPECT_EQ(s.indices[b.firstIndex + i], plain.indices[a.firstIndex + i]);
            uint32_t next = 0, slot = 0;
            for (bool empty : emptySlots(full.partCount)) {
                const Part& part = s.parts[b.firstPart + slot++];
                const Part& was = plain.parts[a.firstPart + (empty ? 0 : next++)];
                EXPECT_EQ(part.triangleCount, empty ? 0u : was.triangleCount) << a.name;
            }
        }
    }
    EXPECT_GT(levels, 0u) << "no level to compare: is the turned part simplified?";
    EXPECT_TRUE(s.geometries[3].levels.empty()); // the geometry not meshed
}

// The export holds no empty part (a glTF primitive has triangles) and no mesh for the object
// without triangles: loaded back, it is the plain scene's export. scripts/validate-gltf.sh
// checks the file (the test gltf_validator_empty_parts).
TEST(EmptyParts, GltfExportHoldsThePartsWithTriangles) {
    const Scene plain = fourObjectScene();
    const LoadResult back = writeAndLoad(withEmptyParts(plain).scene, "empty-parts", true);
    const LoadResult plainBack = writeAndLoad(plain, "plain-parts");
    const Scene& a = back.scene;
    const Scene& b = plainBack.scene;
    EXPECT_TRUE(back.warnings.empty());
    ASSERT_EQ(a.objects.size(), plain.objects.size());
    EXPECT_EQ(a.uniquePartCount(), plain.uniquePartCount());
    ASSERT_EQ(a.parts.size(), b.parts.size());
    for (size_t p = 0; p < a.parts.size(); ++p) {
        EXPECT_EQ(a.parts[p].firstTriangle, b.parts[p].firstTriangle);
        EXPECT_EQ(a.parts[p].triangleCount, b.parts[p].triangleCount);
    }
    EXPECT_EQ(a.indices, b.indices);
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    for (size_t v = 0; v < a.vertices.size(); ++v)
        EXPECT_EQ(a.vertices[v].position, b.vertices[v].position);
    for (size_t o = 0; o < a.objects.size(); ++o) {
        EXPECT_EQ(a.objects[o].name, plain.objects[o].name);
        EXPECT_EQ(a.objects[o].world, b.objects[o].world);
    }
}

TEST(EmptyParts, StatsCountThemAndPropertiesGiveNoBoxWithoutTriangles) {
    const Scene plain = fourObjectScene();
    const testing_support::WithEmptyParts e = withEmptyParts(plain);
    app::LoadedScene loaded, plainLoaded;
    loaded.scene = e.scene;
    plainLoaded.scene = plain;
    const std::string stats = app::statsJson(loaded, {}, std::nullopt);
    const std::string plainStats = app::statsJson(plainLoaded, {}, std::nullopt);
    EXPECT_EQ(member(stats, "parts"), std::to_string(e.plainId.size()));
    EXPECT_EQ(member(stats, "empty_parts"), "14"); // 3 + 3 + 2 + 3 and 3 not meshed
    EXPECT_EQ(member(plainStats, "empty_parts"), "0");
    for (const char* same : {"triangles", "draws", "drawn_triangles"})
        EXPECT_EQ(member(stats, same), member(plainStats, same)) << same;

    const auto none = meshProperties(e.scene, e.emptyObject);
    ASSERT_TRUE(none);
    EXPECT_EQ(none->area, 0.0);
    EXPECT_TRUE(isEmpty(none->bbox));
    EXPECT_EQ(member(propertiesJson(*none), "bbox"), "null");
    std::vector<SolidProperties> each, plainEach;
    for (uint32_t o = 0; o < e.scene.objects.size(); ++o)
        each.push_back(*meshProperties(e.scene, o));
    for (uint32_t o = 0; o < plain.objects.size(); ++o)
        plainEach.push_back(*meshProperties(plain, o));
    const SolidProperties sum = sumProperties(each), plainSum = sumProperties(plainEach);
    EXPECT_DOUBLE_EQ(sum.area, plainSum.area);
    EXPECT_EQ(sum.bbox.min, plainSum.bbox.min);
    EXPECT_EQ(sum.bbox.max, plainSum.bbox.max);
}
