// test_cad_levels.cpp - CAD levels of detail (scene/cad/cad_levels.h): coarser tessellations of
// the same faces, one part each, no face lost, as close to full detail as their recorded
// error says (measured here both ways, vertex by vertex), within the memory the policy allows,
// and as free of cracks between faces as full detail; a cancel stops them in words.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <tuple>

#include "scene/cad/cad_loader.h"
#include "scene/lod.h"
#include "test_data.h"

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

// Distance from `p` to the triangle a, b, c, in double: the foot of the perpendicular where
// it falls inside, else the nearest edge.
double distanceToTriangle(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    const glm::dvec3 ab = b - a, ac = c - a, n = glm::cross(ab, ac);
    const double area2 = glm::dot(n, n);
    if (area2 > 0.0) {
        const glm::dvec3 q = p - n * (glm::dot(p - a, n) / area2);
        const double u = glm::dot(glm::cross(b - q, c - q), n) / area2;
        const double v = glm::dot(glm::cross(c - q, a - q), n) / area2;
        if (u >= 0.0 && v >= 0.0 && u + v <= 1.0) return glm::length(p - q);
    }
    auto toSegment = [&](glm::dvec3 s0, glm::dvec3 s1) {
        const glm::dvec3 d = s1 - s0;
        const double len2 = glm::dot(d, d);
        const double t = len2 > 0.0 ? std::clamp(glm::dot(p - s0, d) / len2, 0.0, 1.0) : 0.0;
        return glm::length(p - (s0 + t * d));
    };
    return std::min({toSegment(a, b), toSegment(b, c), toSegment(c, a)});
}

glm::dvec3 at(const Scene& s, const Geometry& g, uint32_t index) {
    return glm::dvec3(s.vertices[g.firstVertex + index].position);
}

// The farthest a vertex of part `p` of `from` lies from the part's triangles in `to`.
double farthestVertex(const Scene& s, const Geometry& from, const Geometry& to, uint32_t p) {
    const Part& fp = s.parts[from.firstPart + p];
    const Part& tp = s.parts[to.firstPart + p];
    double worst = 0.0;
    for (uint32_t i = 3 * fp.firstTriangle; i < 3 * (fp.firstTriangle + fp.triangleCount); ++i) {
        const glm::dvec3 v = at(s, from, s.indices[from.firstIndex + i]);
        double nearest = INFINITY;
        for (uint32_t t = tp.firstTriangle; t < tp.firstTriangle + tp.triangleCount; ++t) {
            const uint32_t* c = &s.indices[to.firstIndex + 3 * t];
            nearest = std::min(
                nearest, distanceToTriangle(v, at(s, to, c[0]), at(s, to, c[1]), at(s, to, c[2])));
        }
        worst = std::max(worst, nearest);
    }
    return worst;
}

// The largest distance from a vertex of a part at either level to the part's triangles at the
// other, over every part.
double farthestEitherWay(const Scene& s, const Geometry& full, const Geometry& level) {
    double worst = 0.0;
    for (uint32_t p = 0; p < full.partCount; ++p)
        worst =
            std::max({worst, farthestVertex(s, full, level, p), farthestVertex(s, level, full, p)});
    return worst;
}

double largestCoordinate(const Scene& s, const Geometry& g) {
    double largest = 0.0;
    for (uint32_t v = 0; v < g.vertexCount; ++v)
        largest = std::max(largest, double(glm::length(s.vertices[g.firstVertex + v].position)));
    return largest;
}

// Whether every part of `g` has a triangle of some area.
bool everyPartDrawn(const Scene& s, const Geometry& g) {
    for (uint32_t p = 0; p < g.partCount; ++p) {
        const Part& part = s.parts[g.firstPart + p];
        bool drawn = false;
        for (uint32_t t = part.firstTriangle; t < part.firstTriangle + part.triangleCount; ++t) {
            const uint32_t* c = &s.indices[g.firstIndex + 3 * t];
            const glm::dvec3 a = at(s, g, c[0]), b = at(s, g, c[1]), d = at(s, g, c[2]);
            drawn = drawn || glm::length(glm::cross(b - a, d - a)) > 0.0;
        }
        if (!drawn) return false;
    }
    return true;
}

} // namespace

TEST(CadLevels, CoarserTessellationsOfTheSameFaces) {
    const LodOptions policy;
    for (const char* name : {"iges/bearing.iges", "step/linkrods.step", "occ/Motor-c.brep"}) {
        const fs::path path = kData / name;
        REQUIRE_DATA(path);
        const CadLoadResult r = loadCad(path.string(), {}, {}, maxLevels);
        const Scene& s = r.scene;
        validate(s);
        size_t levels = 0;
        uint64_t fullBytes = 0, levelBytes = 0;
        for (uint32_t gi = 0; gi < s.geometries.size(); ++gi) {
            const Geometry& g = s.geometries[gi];
            if (g.level != 0) continue;
            fullBytes += geometryBytes(g);
            const size_t fullOpen = openEdges(s, g);
            const double rounding = 1e-6 * largestCoordinate(s, g);
            const Geometry* finer = &g;
            for (size_t k = 0; k < g.levels.size(); ++k) {
                const Geometry& level = s.geometries[g.levels[k]];
                ++levels;
                levelBytes += geometryBytes(level);
                EXPECT_EQ(level.level, k + 1);
                EXPECT_EQ(level.partFaces, g.partFaces);
                EXPECT_EQ(level.partMaterials, g.partMaterials);
                EXPECT_TRUE(everyPartDrawn(s, level)) << name << " level " << k + 1;
                EXPECT_GE(level.lodError, finer->lodError);
                // No vertex of either lies further from the other's triangles of its face than
                // the error says, up to the rounding of the error's float arithmetic (a few
                // units in the last place of the coordinates) where a vertex is the farthest.
                EXPECT_LE(farthestEitherWay(s, g, level), double(level.lodError) + rounding)
                    << name << " level " << k + 1;
                EXPECT_LE(double(level.triangleCount),
                          double(policy.keepAtMost) * double(finer->triangleCount));
                // Faces share their edges' points within one tessellation: no new open edge.
                EXPECT_LE(openEdges(s, level), fullOpen) << name << " level " << k + 1;
                finer = &level;
            }
        }
        EXPECT_GE(levels, 1u) << name;
        EXPECT_LE(double(levelBytes), double(policy.memory) * double(fullBytes)) << name;
    }
}

// Cancelling while the levels are made, between tessellations (the first half of the stage)
// or while their errors are measured on every thread (the second), stops the load in words.
TEST(CadLevels, ACancelStopsTheLevelsStage) {
    const fs::path path = kData / "occ/Motor-c.brep";
    REQUIRE_DATA(path);
    for (double at : {0.2, 0.7}) {
        std::atomic<bool> cancel{false};
        double last = 0.0;
        const auto progress = [&](const char* stage, double fraction) {
            if (std::string(stage) != "levels of detail") return;
            last = fraction;
            if (fraction >= at) cancel = true;
        };
        try {
            loadCad(path.string(), {}, progress, maxLevels, &cancel);
            ADD_FAILURE() << "a load cancelled at " << at << " of its levels finished";
        } catch (const ModelError& e) {
            EXPECT_EQ(std::string(e.what()), path.string() + ": cancelled");
        }
        EXPECT_TRUE(cancel);
        EXPECT_LT(last, 1.0) << "the stage ran to its end";
    }
}
