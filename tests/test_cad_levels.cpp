// test_cad_levels.cpp - CAD levels of detail (scene/cad/cad_mesh.h): coarser tessellations of the
// same faces, one part each, as close to full detail as their recorded error says, and as
// free of cracks between faces as full detail.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <tuple>

#include "scene/cad/cad_loader.h"
#include "scene/lod.h"

namespace fs = std::filesystem;
using namespace scene;

namespace {

const fs::path kData = "/usr/share/opencascade/data";

using Point = std::tuple<float, float, float>;

Point pointOf(const Scene& s, const Geometry& g, uint32_t index) {
    const glm::vec3 p = s.vertices[g.firstVertex + index].position;
    return {p.x, p.y, p.z};
}

// Edges of `g` (by position) that only one triangle has: where a surface is open or cracked.
size_t openEdges(const Scene& s, const Geometry& g) {
    std::map<std::pair<Point, Point>, int> uses;
    for (uint32_t t = 0; t < g.triangleCount; ++t)
        for (int k = 0; k < 3; ++k) {
            Point a = pointOf(s, g, s.indices[g.firstIndex + 3 * t + k]);
            Point b = pointOf(s, g, s.indices[g.firstIndex + 3 * t + (k + 1) % 3]);
            if (b < a) std::swap(a, b);
            ++uses[{a, b}];
        }
    return size_t(std::count_if(uses.begin(), uses.end(), [](auto& u) { return u.second == 1; }));
}

// Distance from `p` to the triangle a, b, c.
float distanceToTriangle(glm::vec3 p, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const glm::vec3 ab = b - a, ac = c - a, n = glm::cross(ab, ac);
    const float area2 = glm::dot(n, n);
    if (area2 > 0.0f) {
        // Inside the prism over the triangle: the distance to its plane.
        const glm::vec3 q = p - n * (glm::dot(p - a, n) / area2);
        const float u = glm::dot(glm::cross(b - q, c - q), n) / area2;
        const float v = glm::dot(glm::cross(c - q, a - q), n) / area2;
        if (u >= 0.0f && v >= 0.0f && u + v <= 1.0f) return glm::length(p - q);
    }
    auto toSegment = [&](glm::vec3 s0, glm::vec3 s1) {
        const glm::vec3 d = s1 - s0;
        const float len2 = glm::dot(d, d);
        const float t = len2 > 0.0f ? std::clamp(glm::dot(p - s0, d) / len2, 0.0f, 1.0f) : 0.0f;
        return glm::length(p - (s0 + t * d));
    };
    return std::min({toSegment(a, b), toSegment(b, c), toSegment(c, a)});
}

// The largest distance from a full-detail vertex of a part to the level's triangles of that
// part, over every part, as a share of the level's error.
float worstDistanceOverError(const Scene& s, const Geometry& full, const Geometry& level) {
    float worst = 0.0f;
    for (uint32_t p = 0; p < full.partCount; ++p) {
        const Part& fp = s.parts[full.firstPart + p];
        const Part& lp = s.parts[level.firstPart + p];
        for (uint32_t i = 3 * fp.firstTriangle; i < 3 * (fp.firstTriangle + fp.triangleCount);
             ++i) {
            const glm::vec3 v =
                s.vertices[full.firstVertex + s.indices[full.firstIndex + i]].position;
            float nearest = INFINITY;
            for (uint32_t t = lp.firstTriangle; t < lp.firstTriangle + lp.triangleCount; ++t) {
                const uint32_t* c = &s.indices[level.firstIndex + 3 * t];
                nearest = std::min(
                    nearest, distanceToTriangle(v, s.vertices[level.firstVertex + c[0]].position,
                                                s.vertices[level.firstVertex + c[1]].position,
                                                s.vertices[level.firstVertex + c[2]].position));
            }
            worst = std::max(worst, nearest / level.lodError);
        }
    }
    return worst;
}

} // namespace

TEST(CadLevels, CoarserTessellationsOfTheSameFaces) {
    for (const char* name : {"iges/bearing.iges", "step/linkrods.step", "occ/Motor-c.brep"}) {
        const fs::path path = kData / name;
        if (!fs::exists(path)) GTEST_SKIP() << path << " missing (package occt-misc)";
        const CadLoadResult r = loadCad(path.string(), {}, {}, maxLevels);
        const Scene& s = r.scene;
        validate(s);
        size_t levels = 0;
        for (uint32_t gi = 0; gi < s.geometries.size(); ++gi) {
            const Geometry& g = s.geometries[gi];
            if (g.level != 0) continue;
            const size_t fullOpen = openEdges(s, g);
            const Geometry* finer = &g;
            for (size_t k = 0; k < g.levels.size(); ++k) {
                const Geometry& level = s.geometries[g.levels[k]];
                ++levels;
                EXPECT_EQ(level.level, k + 1);
                EXPECT_EQ(level.partFaces, g.partFaces);
                EXPECT_EQ(level.partMaterials, g.partMaterials);
                // At least what the mesher was asked for, and no full-detail vertex further.
                EXPECT_GE(level.lodError, float(r.deflection * std::pow(4.0, double(k + 1))));
                EXPECT_GE(level.lodError, finer->lodError);
                EXPECT_LE(worstDistanceOverError(s, g, level), 1.0f) << name << " level " << k + 1;
                EXPECT_LE(double(level.triangleCount),
                          double(scene::LodOptions{}.keepAtMost) * double(finer->triangleCount));
                // Faces share their edges' points within one tessellation: no new open edge.
                EXPECT_LE(openEdges(s, level), fullOpen) << name << " level " << k + 1;
                finer = &level;
            }
        }
        EXPECT_GE(levels, 1u) << name;
    }
}
