// test_cad_closed.cpp - closed CAD models tessellate into closed meshes: at every level of
// detail, each edge of the triangles is shared by two of them, its points the same floats on
// both sides. With that, the rasterizer's rules leave no pixel between two triangles.
#include <gtest/gtest.h>

#include <map>
#include <tuple>

#include "closed_cad_files.h"
#include "scene/lod.h"

namespace {

using Point = std::tuple<float, float, float>;

// Edges of `g`'s triangles, by the positions of their ends, that only one triangle has.
size_t edgesUsedOnce(const scene::Scene& s, const scene::Geometry& g) {
    auto point = [&](uint32_t index) {
        const glm::vec3 p = s.vertices[g.firstVertex + s.indices[g.firstIndex + index]].position;
        return Point{p.x, p.y, p.z};
    };
    std::map<std::pair<Point, Point>, int> uses;
    for (uint32_t t = 0; t < g.triangleCount; ++t)
        for (uint32_t k = 0; k < 3; ++k) {
            Point a = point(3 * t + k), b = point(3 * t + (k + 1) % 3);
            if (a == b) continue; // a degenerate triangle's collapsed side
            if (b < a) std::swap(a, b);
            ++uses[{a, b}];
        }
    size_t once = 0;
    for (const auto& [edge, count] : uses) once += count == 1;
    return once;
}

} // namespace

// Every closed sample (closed_cad_files.h), every level: no face left out, no edge of the
// tessellation open. Before the seams were shared, hammer.iges's 0.15 gap (wider than its
// resolution) and the float-apart points of CrankArm.brep and Motor-c.brep left edges open.
TEST(CadClosedSolids, EveryLevelOfAClosedModelIsAClosedMesh) {
    const std::vector<std::string> files = testing_support::closedCadFiles();
    if (files.empty()) GTEST_SKIP() << "no occt-misc samples (package occt-misc)";
    EXPECT_GE(files.size(), 20u); // the criterion keeps most samples: it must not drop them
    size_t levels = 0;
    for (const std::string& path : files) {
        const scene::CadLoadResult r = scene::loadCad(path, {}, {}, scene::maxLevels);
        EXPECT_EQ(r.facesFailed, 0u) << path;
        for (const scene::Geometry& g : r.scene.geometries) {
            levels += g.level > 0;
            EXPECT_EQ(edgesUsedOnce(r.scene, g), 0u)
                << path << ", geometry " << g.name << " level " << g.level;
        }
    }
    EXPECT_GT(levels, files.size()); // coarser levels were built, and checked
}
