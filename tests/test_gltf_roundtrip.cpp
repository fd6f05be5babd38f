// test_gltf_roundtrip.cpp - a scene written as .glb and loaded back keeps its parts,
// triangles, unique part IDs, transforms, materials and object names.
#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

#include "scene/copies.h"
#include "scene/procedural/generator.h"
#include "scene/gltf/gltf_loader.h"
#include "scene/gltf/gltf_writer.h"

using namespace scene;

namespace {

// `scene` written to a temporary .glb and loaded back.
LoadResult writeAndLoad(const Scene& scene) {
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("idview-rt-" + std::to_string(getpid()) + ".glb"))
                                 .string();
    writeGlb(scene, path);
    LoadResult loaded = loadGltf(path);
    std::filesystem::remove(path);
    return loaded;
}

} // namespace

TEST(GltfRoundTrip, WrittenSceneLoadsBackUnchanged) {
    const Scene original = replicate(makeAssembly(), 2);
    LoadResult loaded = writeAndLoad(original);
    const Scene& s = loaded.scene;
    EXPECT_TRUE(loaded.warnings.empty());
    ASSERT_EQ(s.objects.size(), original.objects.size());
    EXPECT_EQ(s.uniquePartCount(), original.uniquePartCount());
    EXPECT_EQ(s.drawnTriangleCount(), original.drawnTriangleCount());
    for (size_t o = 0; o < s.objects.size(); ++o) {
        const Object& a = original.objects[o];
        const Object& b = s.objects[o];
        EXPECT_EQ(b.uniquePartOffset, a.uniquePartOffset);
        const Geometry& ga = original.geometries[a.geometry];
        const Geometry& gb = s.geometries[b.geometry];
        ASSERT_EQ(gb.partCount, ga.partCount);
        for (uint32_t p = 0; p < ga.partCount; ++p) {
            const Part& pa = original.parts[ga.firstPart + p];
            const Part& pb = s.parts[gb.firstPart + p];
            ASSERT_EQ(pb.triangleCount, pa.triangleCount);
            // The first corner of the part's first triangle lands in the same world position,
            // turned from z-up to y-up.
            auto corner = [](const Scene& sc, const Object& obj, const Geometry& g,
                             const Part& part) {
                uint32_t v = sc.indices[g.firstIndex + 3 * part.firstTriangle];
                return glm::vec3(obj.world * glm::vec4(sc.vertices[g.firstVertex + v].position, 1));
            };
            glm::vec3 d = glm::vec3(zUpToYUp() * glm::vec4(corner(original, a, ga, pa), 1)) -
                          corner(s, b, gb, pb);
            ASSERT_LT(glm::length(d), 1e-4f) << "object " << o << " part " << p;
        }
        EXPECT_EQ(s.materials[b.material].color, original.materials[a.material].color);
    }
    // Instancing survives: objects sharing a geometry still share one.
    EXPECT_EQ(s.geometries.size(), original.geometries.size());
}

TEST(GltfRoundTrip, ObjectNamesSurviveAndPathsComeBackFlat) {
    const Scene original = replicate(makeAssembly(), 2);
    LoadResult loaded = writeAndLoad(original);
    const Scene& s = loaded.scene;
    ASSERT_EQ(s.objects.size(), original.objects.size());
    for (size_t o = 0; o < s.objects.size(); ++o) {
        EXPECT_EQ(s.objects[o].name, original.objects[o].name) << o;
        EXPECT_EQ(s.objects[o].path, original.objects[o].name) << o; // flat: just the name
    }
    EXPECT_EQ(s.objects[6].name, "bolt M10 #1");
    EXPECT_EQ(describePart(s, s.objects[6].uniquePartOffset)->name, "bolt M10 #1");
}
