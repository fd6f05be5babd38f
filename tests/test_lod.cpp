// test_lod.cpp - levels of detail (scene/lod.h) checked against the full-detail geometry they
// come from: every level triangle has its corners on full-detail vertices, each part keeps
// within the level's error of where it was (a part that goes is smaller than the error), no
// crack opens, levels shrink and their errors grow, and a forced level keeps every part ID.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <map>
#include <set>
#include <tuple>

#include "scene/lod.h"
#include "scene/procedural/procedural.h"

using namespace scene;

namespace {

using Point = std::tuple<float, float, float>;
using Edge = std::pair<Point, Point>;

Point pointOf(const Scene& s, const Geometry& g, uint32_t index) {
    const glm::vec3 p = s.vertices[g.firstVertex + index].position;
    return {p.x, p.y, p.z};
}

// The corners of part `p`'s triangles, by position (vertices split for normals count once).
std::vector<std::array<Point, 3>> trianglesOf(const Scene& s, const Geometry& g, uint32_t p) {
    const Part& part = s.parts[g.firstPart + p];
    std::vector<std::array<Point, 3>> out;
    for (uint32_t t = part.firstTriangle; t < part.firstTriangle + part.triangleCount; ++t) {
        const uint32_t* i = &s.indices[g.firstIndex + 3 * t];
        out.push_back({pointOf(s, g, i[0]), pointOf(s, g, i[1]), pointOf(s, g, i[2])});
    }
    return out;
}

// The part's outline: the edges only one of its triangles has.
std::set<Edge> outlineOf(const std::vector<std::array<Point, 3>>& triangles) {
    std::map<Edge, int> uses;
    for (const auto& t : triangles)
        for (int k = 0; k < 3; ++k) {
            Point a = t[k], b = t[(k + 1) % 3];
            if (b < a) std::swap(a, b);
            ++uses[{a, b}];
        }
    std::set<Edge> outline;
    for (const auto& [edge, count] : uses)
        if (count == 1) outline.insert(edge);
    return outline;
}

glm::vec3 vec(const Point& p) {
    return {std::get<0>(p), std::get<1>(p), std::get<2>(p)};
}

float diagonalOf(const std::set<Point>& points) {
    glm::vec3 low(FLT_MAX), high(-FLT_MAX);
    for (const Point& p : points) {
        low = glm::min(low, vec(p));
        high = glm::max(high, vec(p));
    }
    return glm::length(high - low);
}

// Distance from `p` to the nearest of `triangles`: to a triangle's plane where the foot of
// the perpendicular falls inside it (barycentric test), else to its nearest edge.
float distanceTo(glm::vec3 p, const std::vector<std::array<glm::vec3, 3>>& triangles) {
    auto toSegment = [](glm::vec3 q, glm::vec3 a, glm::vec3 b) {
        const glm::vec3 ab = b - a;
        const float len2 = glm::dot(ab, ab);
        const float t = len2 > 0 ? std::clamp(glm::dot(q - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
        return glm::length(q - (a + t * ab));
    };
    float best = FLT_MAX;
    for (const auto& [a, b, c] : triangles) {
        const glm::vec3 n = glm::cross(b - a, c - a);
        const float area2 = glm::dot(n, n);
        if (area2 > 0) {
            const glm::vec3 foot = p - n * (glm::dot(p - a, n) / area2);
            const float u = glm::dot(glm::cross(c - b, foot - b), n) / area2;
            const float v = glm::dot(glm::cross(a - c, foot - c), n) / area2;
            if (u >= 0 && v >= 0 && u + v <= 1) {
                best = std::min(best, glm::length(p - foot));
                continue;
            }
        }
        best = std::min({best, toSegment(p, a, b), toSegment(p, b, c), toSegment(p, c, a)});
    }
    return best;
}

// The triangles that may lie within `reach` of a point: a grid of cubes (the reach, or the
// triangles' mean size where larger), each listing every triangle whose box, grown by the
// reach, touches it; so a point's own cube lists all that can be that near.
class Nearby {
  public:
    Nearby(const std::vector<std::array<glm::vec3, 3>>& triangles, float reach)
        : triangles_(triangles) {
        float size = 0.0f;
        for (const auto& t : triangles)
            size += glm::length(glm::max(glm::max(t[0], t[1]), t[2]) -
                                glm::min(glm::min(t[0], t[1]), t[2]));
        cell_ = std::max({reach, size / float(triangles.size()), 1e-6f});
        for (uint32_t i = 0; i < triangles.size(); ++i) {
            const auto& t = triangles[i];
            const glm::ivec3 a = cellOf(glm::min(glm::min(t[0], t[1]), t[2]) - reach);
            const glm::ivec3 b = cellOf(glm::max(glm::max(t[0], t[1]), t[2]) + reach);
            for (int x = a.x; x <= b.x; ++x)
                for (int y = a.y; y <= b.y; ++y)
                    for (int z = a.z; z <= b.z; ++z) cells_[{x, y, z}].push_back(i);
        }
    }
    // The distance to the nearest of the triangles listed where `p` is (FLT_MAX: none).
    float distance(glm::vec3 p) const {
        const glm::ivec3 c = cellOf(p);
        const auto found = cells_.find({c.x, c.y, c.z});
        if (found == cells_.end()) return FLT_MAX;
        std::vector<std::array<glm::vec3, 3>> listed;
        for (uint32_t i : found->second) listed.push_back(triangles_[i]);
        return distanceTo(p, listed);
    }

  private:
    glm::ivec3 cellOf(glm::vec3 p) const { return glm::ivec3(glm::floor(p / cell_)); }
    const std::vector<std::array<glm::vec3, 3>>& triangles_;
    float cell_ = 1.0f;
    std::map<std::tuple<int, int, int>, std::vector<uint32_t>> cells_;
};

// The car-like preset: 20 geometries, 131 k distinct triangles, parts of a few dozen each.
Scene sceneWithLevels() {
    Scene s = makeProcedural({"car-like", 1});
    buildLevels(s);
    validate(s);
    return s;
}

} // namespace

TEST(Levels, EveryTriangleKeepsToItsPartWithinTheErrorAndNoCrackOpens) {
    const Scene s = sceneWithLevels();
    size_t levels = 0, welded = 0, emptied = 0;
    for (const Geometry& g : s.geometries) {
        if (g.level != 0) continue;
        std::vector<std::array<Point, 3>> whole;
        std::set<Point> positions;
        for (uint32_t p = 0; p < g.partCount; ++p)
            for (const auto& t : trianglesOf(s, g, p)) {
                whole.push_back(t);
                positions.insert(t.begin(), t.end());
            }
        const std::set<Edge> openEdges = outlineOf(whole);
        for (uint32_t l : g.levels) {
            const Geometry& coarse = s.geometries[l];
            ++levels;
            ASSERT_EQ(coarse.partCount, g.partCount);
            EXPECT_EQ(coarse.partFaces, g.partFaces);
            EXPECT_EQ(coarse.partMaterials, g.partMaterials);
            std::vector<std::array<Point, 3>> coarseWhole;
            for (uint32_t p = 0; p < g.partCount; ++p) {
                const auto full = trianglesOf(s, g, p);
                const auto reduced = trianglesOf(s, coarse, p);
                ASSERT_FALSE(reduced.empty()) << coarse.name << " lost part " << p;
                std::set<Point> own;
                for (const auto& t : full) own.insert(t.begin(), t.end());
                std::vector<std::array<glm::vec3, 3>> drawn; // the part's triangles of some area
                for (const auto& t : reduced) {
                    coarseWhole.push_back(t);
                    bool offOwn = false;
                    for (const Point& corner : t) {
                        ASSERT_TRUE(positions.count(corner))
                            << coarse.name << " part " << p << " has a corner off full detail";
                        offOwn = offOwn || !own.count(corner);
                    }
                    welded += offOwn;
                    if (t[0] != t[1] || t[1] != t[2])
                        drawn.push_back({vec(t[0]), vec(t[1]), vec(t[2])});
                }
                // Every corner of the part at full detail lies within the level's error of
                // the part's triangles there; a part drawn nowhere is smaller than the error.
                if (drawn.empty()) {
                    ++emptied;
                    EXPECT_LE(diagonalOf(own), coarse.lodError * 1.0001f)
                        << coarse.name << " part " << p;
                    continue;
                }
                const float reach = coarse.lodError * 1.0001f + 1e-6f;
                const Nearby nearby(drawn, reach);
                for (const Point& corner : own)
                    ASSERT_LE(nearby.distance(vec(corner)), reach)
                        << coarse.name << " part " << p << " moved further than its error";
            }
            // Inside the geometry no edge opens: the only edges with one triangle are the
            // geometry's open edges of full detail, all still there.
            ASSERT_EQ(outlineOf(coarseWhole), openEdges) << coarse.name << " opened a crack";
        }
    }
    EXPECT_GE(levels, 20u) << "too few levels to say anything";
    EXPECT_GT(welded, 100u) << "no level welded its parts";
    EXPECT_GT(emptied, 0u) << "no part smaller than its level's error went";
}

TEST(Levels, ShrinkAsTheirErrorsGrow) {
    const Scene s = sceneWithLevels();
    const LodOptions options;
    for (uint32_t gi = 0; gi < s.geometries.size(); ++gi) {
        const Geometry& g = s.geometries[gi];
        if (g.level != 0) continue;
        EXPECT_EQ(g.lodError, 0.0f);
        ASSERT_LT(g.levels.size(), maxLevels);
        const Geometry* finer = &g;
        for (size_t k = 0; k < g.levels.size(); ++k) {
            const Geometry& coarse = s.geometries[g.levels[k]];
            EXPECT_EQ(coarse.level, k + 1);
            EXPECT_TRUE(coarse.levels.empty());
            EXPECT_LE(double(coarse.triangleCount),
                      double(options.keepAtMost) * double(finer->triangleCount));
            EXPECT_GE(coarse.lodError, finer->lodError);
            EXPECT_GT(coarse.lodError, 0.0f);
            EXPECT_EQ(geometryAtLevel(s, gi, uint32_t(k + 1)), g.levels[k]);
            finer = &coarse;
        }
        // Past its coarsest level a geometry stays there.
        EXPECT_EQ(geometryAtLevel(s, gi, maxLevels - 1), g.levels.empty() ? gi : g.levels.back());
        EXPECT_EQ(geometryAtLevel(s, gi, 0), gi);
    }
}

TEST(Levels, SameScenesGiveTheSameLevels) {
    const Scene a = sceneWithLevels(), b = sceneWithLevels();
    EXPECT_EQ(a.indices, b.indices);
    ASSERT_EQ(a.geometries.size(), b.geometries.size());
    for (size_t g = 0; g < a.geometries.size(); ++g)
        EXPECT_EQ(a.geometries[g].lodError, b.geometries[g].lodError);
}

TEST(Levels, AForcedLevelKeepsEveryPartId) {
    const Scene s = sceneWithLevels();
    const std::vector<LevelStats> stats = levelStats(s);
    ASSERT_EQ(stats.size(), maxLevels);
    EXPECT_EQ(stats[0].drawnTriangles, s.drawnTriangleCount());
    for (uint32_t level = 1; level < maxLevels; ++level) {
        Scene forced = s;
        retargetToLevel(forced, level);
        validate(forced);
        EXPECT_EQ(forced.uniquePartCount(), s.uniquePartCount());
        for (size_t o = 0; o < s.objects.size(); ++o) {
            EXPECT_EQ(forced.objects[o].uniquePartOffset, s.objects[o].uniquePartOffset);
            EXPECT_EQ(forced.geometries[forced.objects[o].geometry].partCount,
                      s.geometries[s.objects[o].geometry].partCount);
        }
        EXPECT_EQ(forced.drawnTriangleCount(), stats[level].drawnTriangles);
        EXPECT_LT(stats[level].drawnTriangles, stats[level - 1].drawnTriangles);
        // The stats of a retargeted scene still count from full detail.
        EXPECT_EQ(levelStats(forced)[0].drawnTriangles, stats[0].drawnTriangles);
    }
}
