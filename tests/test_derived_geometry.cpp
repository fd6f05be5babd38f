// test_derived_geometry.cpp - what vertex-fs and the mesh techniques draw instead of the
// scene's indices, checked against the scene without a GPU: every triangle of the part
// vertices leads with a vertex of its own part and keeps its corners and winding; a vertex is
// duplicated only where no rotation could help; meshlets hold every triangle once, within
// their limits, with its corners in order and its part.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <set>

#include "scene/copies.h"
#include "scene/gltf/gltf_loader.h"
#include "scene/meshlets.h"
#include "scene/part_data.h"
#include "scene/part_vertices.h"
#include "scene/procedural/procedural.h"
#include "shared_vertex_gltf.h"
#include "test_data.h"

namespace {

scene::Scene sharedVertexScene() {
    const auto dir = std::filesystem::temp_directory_path() / "idview-derived-geometry";
    return scene::loadGltf(testing_support::writeSharedVertexGltf(dir).string(), {}).scene;
}

std::vector<std::pair<std::string, scene::Scene>> scenes() {
    std::vector<std::pair<std::string, scene::Scene>> all;
    all.emplace_back("small x2", scene::replicate(scene::makeProcedural({"small", 1}), 2));
    all.emplace_back(
        "2CylinderEngine components",
        scene::loadGltf(
            testing_support::requiredData(
                "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"),
            {scene::PartMode::Components})
            .scene);
    all.emplace_back("shared vertices", sharedVertexScene());
    return all;
}

// Tetrahedron faces as parts 0-3 plus a fifth part on face 0's corners: five triangles, four
// vertices, so one vertex must be duplicated (a triangle-to-vertex matching covers only four).
scene::Scene fiveTrianglesOnFourVertices() {
    scene::Scene s;
    for (glm::vec3 p :
         {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)})
        s.vertices.push_back({p, glm::vec3(0, 0, 1)});
    const uint32_t tris[5][3] = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}, {0, 2, 1}};
    for (uint32_t t = 0; t < 5; ++t) {
        s.indices.insert(s.indices.end(), tris[t], tris[t] + 3);
        s.parts.push_back({t, 1});
    }
    s.geometries.push_back({"tetra", 0, 4, 0, 5, 0, 5, {}, {}, {}, {}, 0, 0.0f});
    scene::addMaterial(s, "grey", glm::vec4(0.5f));
    scene::addObject(s, 0, 0, glm::mat4(1.0f));
    scene::validate(s);
    return s;
}

void expectExactPartVertices(const std::string& name, const scene::Scene& s) {
    const scene::PartVertices pv = scene::buildPartVertices(s);
    ASSERT_EQ(pv.indices.size(), s.indices.size()) << name;
    ASSERT_EQ(pv.localPart.size(), pv.vertices.size()) << name;
    uint64_t added = 0;
    for (uint32_t g = 0; g < s.geometries.size(); ++g) {
        const scene::Geometry& geometry = s.geometries[g];
        const uint32_t first = pv.firstVertex[g], count = pv.vertexCount[g];
        ASSERT_GE(count, geometry.vertexCount) << name;
        added += count - geometry.vertexCount;
        // The geometry's own vertices come first, unchanged.
        for (uint32_t v = 0; v < geometry.vertexCount; ++v)
            ASSERT_EQ(pv.vertices[first + v].position,
                      s.vertices[geometry.firstVertex + v].position);
        const auto parts = scene::trianglePartsOf(s, g);
        // Which part leads with each of the geometry's own vertices (ownership).
        std::vector<uint32_t> leads(count, UINT32_MAX);
        for (uint32_t t = 0; t < geometry.triangleCount; ++t)
            leads[pv.indices[geometry.firstIndex + 3 * t]] = parts[t];
        std::set<uint32_t> justified; // duplicates some triangle could not do without
        for (uint32_t t = 0; t < geometry.triangleCount; ++t) {
            const uint32_t* in = &s.indices[geometry.firstIndex + 3 * t];
            const uint32_t* out = &pv.indices[geometry.firstIndex + 3 * t];
            ASSERT_LT(out[0], count) << name;
            ASSERT_EQ(pv.localPart[first + out[0]], parts[t]) << name << " triangle " << t;
            // The lead is a corner or a copy of one; the other two follow it cyclically.
            const uint32_t lead = out[0] < geometry.vertexCount ? out[0] : UINT32_MAX;
            bool rotation = false;
            for (int r = 0; r < 3; ++r) {
                const bool sameLead = lead == UINT32_MAX
                                          ? pv.vertices[first + out[0]].position ==
                                                s.vertices[geometry.firstVertex + in[r]].position
                                          : in[r] == lead;
                rotation |= sameLead && out[1] == in[(r + 1) % 3] && out[2] == in[(r + 2) % 3];
            }
            ASSERT_TRUE(rotation) << name << " triangle " << t << " lost its corners or winding";
            if (lead == UINT32_MAX &&
                std::none_of(in, in + 3, [&](uint32_t v) { return leads[v] == parts[t]; }) &&
                std::all_of(in, in + 3, [&](uint32_t v) { return leads[v] != UINT32_MAX; }))
                justified.insert(out[0]);
        }
        // Every duplicate leads a triangle whose corners all lead triangles of other parts.
        EXPECT_EQ(justified.size(), count - geometry.vertexCount) << name << " geometry " << g;
    }
    EXPECT_EQ(added, pv.addedVertices) << name;
}

} // namespace

TEST(PartVertices, EveryTriangleLeadsWithItsPartKeepingCornersAndWinding) {
    for (const auto& [name, s] : scenes()) expectExactPartVertices(name, s);
}

TEST(PartVertices, DuplicatesExactlyWhatNoRotationAvoids) {
    const scene::Scene tetra = fiveTrianglesOnFourVertices();
    expectExactPartVertices("five on four", tetra);
    EXPECT_EQ(scene::buildPartVertices(tetra).addedVertices, 1u);
    // Procedural faces have vertices of their own: nothing to duplicate, nothing to rotate.
    const scene::Scene procedural = scenes()[0].second;
    const scene::PartVertices own = scene::buildPartVertices(procedural);
    EXPECT_EQ(own.addedVertices, 0u);
    EXPECT_EQ(own.indices, procedural.indices);
    // The shared-vertex model: no two triangles of one part share a vertex, so a vertex can
    // lead one triangle at most, and the fewest copies possible are the triangles a maximum
    // triangle-to-corner matching leaves out (augmenting paths, computed here).
    const scene::Scene shared = sharedVertexScene();
    const scene::Geometry& g = shared.geometries[0];
    std::vector<int> matchOf(g.vertexCount, -1);
    std::function<bool(uint32_t, std::vector<bool>&)> augment = [&](uint32_t t,
                                                                    std::vector<bool>& seen) {
        for (int c = 0; c < 3; ++c) {
            const uint32_t v = shared.indices[g.firstIndex + 3 * t + c];
            if (seen[v]) continue;
            seen[v] = true;
            if (matchOf[v] < 0 || augment(uint32_t(matchOf[v]), seen)) {
                matchOf[v] = int(t);
                return true;
            }
        }
        return false;
    };
    uint32_t matched = 0;
    for (uint32_t t = 0; t < g.triangleCount; ++t) {
        std::vector<bool> seen(g.vertexCount, false);
        matched += augment(t, seen);
    }
    const uint64_t fewest = g.triangleCount - matched; // per object's geometry, shared by both
    const uint64_t added = scene::buildPartVertices(shared).addedVertices;
    EXPECT_EQ(fewest, 47u); // 128 triangles, 81 vertices, every vertex matched
    EXPECT_EQ(added, fewest);
}

// The loader keeps the file's sharing: three primitives over one accessor pair make one
// geometry of 81 vertices, not three copies.
TEST(PartVertices, GltfPrimitivesOverOneAccessorShareVertices) {
    const scene::Scene s = sharedVertexScene();
    ASSERT_EQ(s.geometries.size(), 1u);
    EXPECT_EQ(s.geometries[0].vertexCount,
              uint32_t(testing_support::sharedGridSide * testing_support::sharedGridSide));
    EXPECT_EQ(s.geometries[0].partCount, uint32_t(testing_support::sharedGridPrimitives));
    EXPECT_EQ(s.geometries[0].triangleCount, uint32_t(testing_support::sharedGridTriangles));
    EXPECT_EQ(s.objects.size(), 2u);
}

TEST(Meshlets, HoldEveryTriangleOnceWithinLimitsCornersInOrder) {
    for (const auto& [name, s] : scenes()) {
        const scene::Meshlets m = scene::buildMeshlets(s);
        ASSERT_EQ(m.firstMeshlet.size(), s.geometries.size());
        for (uint32_t g = 0; g < s.geometries.size(); ++g) {
            const scene::Geometry& geometry = s.geometries[g];
            const auto parts = scene::trianglePartsOf(s, g);
            std::vector<int> seen(geometry.triangleCount, 0);
            uint32_t local = 0;
            for (uint32_t k = 0; k < m.meshletCount[g]; ++k) {
                const scene::Meshlet& meshlet = m.meshlets[m.firstMeshlet[g] + k];
                ASSERT_LE(meshlet.vertexCount, scene::meshletMaxVertices) << name;
                ASSERT_LE(meshlet.triangleCount, scene::meshletMaxTriangles) << name;
                ASSERT_EQ(meshlet.firstLocalTriangle, local) << name;
                ASSERT_EQ(meshlet.firstTriangle, m.geometryFirstTriangle[g] + local) << name;
                for (uint32_t i = 0; i < meshlet.triangleCount; ++i) {
                    const uint32_t at = meshlet.firstTriangle + i;
                    const uint32_t source = m.sourceTriangle[at];
                    ASSERT_LT(source, geometry.triangleCount) << name;
                    ++seen[source];
                    EXPECT_EQ(m.localPart[at], parts[source]) << name;
                    for (int c = 0; c < 3; ++c) {
                        const uint8_t corner = m.corners[3 * at + c];
                        ASSERT_LT(corner, meshlet.vertexCount) << name;
                        EXPECT_EQ(m.vertices[meshlet.firstVertex + corner],
                                  geometry.firstVertex +
                                      s.indices[geometry.firstIndex + 3 * source + c])
                            << name << " triangle " << source << " corner " << c;
                    }
                }
                local += meshlet.triangleCount;
            }
            EXPECT_EQ(local, geometry.triangleCount) << name;
            EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }))
                << name << " geometry " << g;
        }
    }
}
