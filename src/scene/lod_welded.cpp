// lod_welded.cpp - a level of detail of a geometry simplified as one surface (lod_welded.h).
#include "scene/lod_welded.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <optional>
#include <tuple>
#include <unordered_map>

namespace scene {
namespace {

struct PositionHash {
    size_t operator()(const glm::vec3& p) const {
        const auto bits = [](float f) {
            uint32_t u;
            std::memcpy(&u, &f, sizeof u);
            return size_t(u);
        };
        return (bits(p.x) * 73856093u) ^ (bits(p.y) * 19349663u) ^ (bits(p.z) * 83492791u);
    }
};

// The geometry with one vertex per position: its triangles over those, and per welded vertex
// the geometry's vertices at that position.
struct Welded {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> indices;
    std::vector<std::vector<uint32_t>> originals;
    std::vector<uint32_t> partOfTriangle; // full detail's
};

Welded weld(const Scene& scene, const Geometry& g) {
    Welded w;
    std::unordered_map<glm::vec3, uint32_t, PositionHash> ids;
    w.indices.reserve(3 * size_t(g.triangleCount));
    for (uint32_t p = 0; p < g.partCount; ++p) {
        const Part& part = scene.parts[g.firstPart + p];
        for (uint32_t i = 3 * part.firstTriangle; i < 3 * (part.firstTriangle + part.triangleCount);
             ++i) {
            const uint32_t v = scene.indices[g.firstIndex + i];
            const glm::vec3 position = scene.vertices[g.firstVertex + v].position;
            auto [it, added] = ids.try_emplace(position, uint32_t(w.positions.size()));
            if (added) {
                w.positions.push_back(position);
                w.originals.emplace_back();
            }
            std::vector<uint32_t>& at = w.originals[it->second];
            if (std::find(at.begin(), at.end(), v) == at.end()) at.push_back(v);
            w.indices.push_back(it->second);
        }
        w.partOfTriangle.insert(w.partOfTriangle.end(), part.triangleCount, p);
    }
    return w;
}

// The edges only one of `indices`' triangles has, as (low, high) vertex pairs, sorted.
std::vector<std::pair<uint32_t, uint32_t>> openEdges(const std::vector<uint32_t>& indices) {
    std::vector<std::pair<uint32_t, uint32_t>> edges;
    for (size_t t = 0; t + 2 < indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = indices[t + k], b = indices[t + (k + 1) % 3];
            edges.emplace_back(std::min(a, b), std::max(a, b));
        }
    std::sort(edges.begin(), edges.end());
    std::vector<std::pair<uint32_t, uint32_t>> open;
    for (size_t i = 0; i < edges.size();) {
        size_t j = i;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        if (j - i == 1) open.push_back(edges[i]);
        i = j;
    }
    return open;
}

// Distance from `p` to triangle (a, b, c): the closest point by the triangle's regions.
float distanceToTriangle(glm::vec3 p, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return glm::length(ap);
    const glm::vec3 bp = p - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return glm::length(bp);
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return glm::length(p - (a + ab * (d1 / (d1 - d3))));
    const glm::vec3 cp = p - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return glm::length(cp);
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return glm::length(p - (a + ac * (d2 / (d2 - d6))));
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return glm::length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
    const float denom = 1.0f / (va + vb + vc);
    return glm::length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

using Triangle = std::array<glm::vec3, 3>;

// Triangles sorted into a grid of cubes, each listed in every cube its box touches, for the
// nearest of them to a point.
class TriangleGrid {
  public:
    explicit TriangleGrid(const std::vector<Triangle>& triangles) : triangles_(triangles) {
        glm::vec3 low(FLT_MAX), high(-FLT_MAX);
        for (const Triangle& t : triangles)
            for (const glm::vec3& p : t) {
                low = glm::min(low, p);
                high = glm::max(high, p);
            }
        low_ = low;
        // About a triangle per cube where they spread over a surface.
        const float extent = std::max(glm::length(high - low), 1e-12f);
        cell_ = std::max(extent / std::sqrt(float(triangles.size())), extent * 1e-3f);
        for (uint32_t i = 0; i < triangles.size(); ++i) {
            const Triangle& t = triangles[i];
            const glm::ivec3 a = cellOf(glm::min(glm::min(t[0], t[1]), t[2]));
            const glm::ivec3 b = cellOf(glm::max(glm::max(t[0], t[1]), t[2]));
            for (int x = a.x; x <= b.x; ++x)
                for (int y = a.y; y <= b.y; ++y)
                    for (int z = a.z; z <= b.z; ++z) cells_[key({x, y, z})].push_back(i);
        }
    }

    // The nearest triangle to `p`: its distance and index; or, once one within `enough` is
    // found (the caller wants no nearer), that one; or, where none lies within `farEnough`
    // (the caller needs no more), a distance above it that no triangle is nearer than.
    struct Hit {
        float distance = FLT_MAX;
        uint32_t index = 0;
    };
    Hit nearest(glm::vec3 p, float enough = 0.0f, float farEnough = FLT_MAX) const {
        const glm::ivec3 at = cellOf(p);
        Hit best;
        for (int ring = 0; float(ring - 1) * cell_ < best.distance; ++ring) {
            if (float(ring - 1) * cell_ > farEnough) {
                best.distance = std::min(best.distance, float(ring - 1) * cell_);
                return best;
            }
            for (int x = -ring; x <= ring; ++x)
                for (int y = -ring; y <= ring; ++y)
                    for (int z = -ring; z <= ring; ++z) {
                        if (std::max({std::abs(x), std::abs(y), std::abs(z)}) != ring) continue;
                        const auto found = cells_.find(key(at + glm::ivec3(x, y, z)));
                        if (found == cells_.end()) continue;
                        for (uint32_t i : found->second) {
                            const Triangle& t = triangles_[i];
                            const float d = distanceToTriangle(p, t[0], t[1], t[2]);
                            if (d < best.distance) best = {d, i};
                        }
                    }
            if (best.distance <= enough) return best;
        }
        return best;
    }

  private:
    glm::ivec3 cellOf(glm::vec3 p) const { return glm::ivec3(glm::floor((p - low_) / cell_)); }
    static uint64_t key(glm::ivec3 c) {
        return (uint64_t(uint32_t(c.x) & 0x1FFFFF) << 42) |
               (uint64_t(uint32_t(c.y) & 0x1FFFFF) << 21) | uint64_t(uint32_t(c.z) & 0x1FFFFF);
    }

    const std::vector<Triangle>& triangles_;
    glm::vec3 low_{0.0f};
    float cell_ = 1.0f;
    std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
};

// The farthest a corner or centre of `from` lies from the nearest of `to`; or, once that is
// beyond `limit`, a distance beyond it.
float farthest(const std::vector<Triangle>& from, const std::vector<Triangle>& to, float limit) {
    const TriangleGrid grid(to);
    std::vector<glm::vec3> points;
    points.reserve(2 * from.size());
    for (const Triangle& t : from) {
        points.insert(points.end(), t.begin(), t.end());
        points.push_back((t[0] + t[1] + t[2]) / 3.0f);
    }
    // Corners shared by several triangles are measured once.
    std::sort(points.begin(), points.end(), [](const glm::vec3& a, const glm::vec3& b) {
        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    float worst = 0.0f;
    for (const glm::vec3& p : points) {
        worst = std::max(worst, grid.nearest(p, worst, limit).distance); // no nearer can count
        if (worst > limit) break;
    }
    return worst;
}

float diagonal(const std::vector<Triangle>& triangles) {
    glm::vec3 low(FLT_MAX), high(-FLT_MAX);
    for (const Triangle& t : triangles)
        for (const glm::vec3& p : t) {
            low = glm::min(low, p);
            high = glm::max(high, p);
        }
    return glm::length(high - low);
}

// The part all three corners have a vertex in, if exactly one.
std::optional<uint32_t> sharedPart(const Welded& w, const std::vector<uint32_t>& partOfVertex,
                                   const uint32_t* c) {
    std::optional<uint32_t> found;
    for (uint32_t a : w.originals[c[0]]) {
        const uint32_t p = partOfVertex[a];
        const auto has = [&](uint32_t corner) {
            for (uint32_t v : w.originals[corner])
                if (partOfVertex[v] == p) return true;
            return false;
        };
        if (!has(c[1]) || !has(c[2]) || found == p) continue;
        if (found) return std::nullopt; // two parts share all three: let the centre decide
        found = p;
    }
    return found;
}

} // namespace

float partsMoved(const Scene& scene, const Geometry& g, const std::vector<PartLevel>& parts,
                 float limit) {
    float moved = 0.0f;
    for (uint32_t p = 0; p < g.partCount && moved <= limit; ++p) {
        const Part& part = scene.parts[g.firstPart + p];
        std::vector<Triangle> full, coarse;
        for (uint32_t t = part.firstTriangle; t < part.firstTriangle + part.triangleCount; ++t) {
            const uint32_t* i = &scene.indices[g.firstIndex + 3 * size_t(t)];
            full.push_back({scene.vertices[g.firstVertex + i[0]].position,
                            scene.vertices[g.firstVertex + i[1]].position,
                            scene.vertices[g.firstVertex + i[2]].position});
        }
        const std::vector<uint32_t>& indices = parts[p].indices;
        for (size_t k = 0; k + 2 < indices.size(); k += 3) {
            const Triangle t{scene.vertices[g.firstVertex + indices[k]].position,
                             scene.vertices[g.firstVertex + indices[k + 1]].position,
                             scene.vertices[g.firstVertex + indices[k + 2]].position};
            if (t[0] != t[1] || t[1] != t[2]) coarse.push_back(t);
        }
        moved = std::max(moved, coarse.empty() ? diagonal(full)
                                               : std::max(farthest(full, coarse, limit),
                                                          farthest(coarse, full, limit)));
    }
    return moved;
}

std::vector<PartLevel> simplifyWelded(const Scene& scene, const Geometry& g, double share) {
    if (g.partCount < 2) return {};
    const Welded w = weld(scene, g);
    std::vector<uint32_t> reduced(w.indices.size());
    float relative = 0.0f;
    const size_t target = std::max<size_t>(3, 3 * size_t(double(g.triangleCount) * share + 0.5));
    const size_t kept = meshopt_simplify(reduced.data(), w.indices.data(), w.indices.size(),
                                         &w.positions[0].x, w.positions.size(), sizeof(glm::vec3),
                                         target, 1.0f, meshopt_SimplifyLockBorder, &relative);
    if (kept == 0 || kept >= w.indices.size()) return {};
    reduced.resize(kept);
    // The open edges locked stay the only ones: where a welded geometry is not a clean
    // surface (edges of three triangles), the simplifier can open one elsewhere.
    if (openEdges(reduced) != openEdges(w.indices)) return {};

    // Which part each of the geometry's vertices belongs to (a vertex serves one part).
    std::vector<uint32_t> partOfVertex(g.vertexCount, 0);
    std::vector<std::vector<Triangle>> full(g.partCount), coarse(g.partCount);
    for (uint32_t t = 0; t < g.triangleCount; ++t) {
        const uint32_t* i = &scene.indices[g.firstIndex + 3 * size_t(t)];
        Triangle tri;
        for (int k = 0; k < 3; ++k) {
            partOfVertex[i[k]] = w.partOfTriangle[t];
            tri[k] = scene.vertices[g.firstVertex + i[k]].position;
        }
        full[w.partOfTriangle[t]].push_back(tri);
    }

    std::vector<PartLevel> parts(g.partCount);
    std::vector<Triangle> fullTriangles;
    std::vector<uint32_t> fullPart;
    for (uint32_t p = 0; p < g.partCount; ++p) {
        fullTriangles.insert(fullTriangles.end(), full[p].begin(), full[p].end());
        fullPart.insert(fullPart.end(), full[p].size(), p);
    }
    const TriangleGrid grid(fullTriangles);
    for (size_t t = 0; t < kept; t += 3) {
        const uint32_t* c = &reduced[t];
        const Triangle tri{w.positions[c[0]], w.positions[c[1]], w.positions[c[2]]};
        const uint32_t p =
            sharedPart(w, partOfVertex, c)
                .value_or(fullPart[grid.nearest((tri[0] + tri[1] + tri[2]) / 3.0f).index]);
        for (int k = 0; k < 3; ++k) {
            const std::vector<uint32_t>& at = w.originals[c[k]];
            const auto own = std::find_if(at.begin(), at.end(),
                                          [&](uint32_t v) { return partOfVertex[v] == p; });
            parts[p].indices.push_back(own != at.end() ? *own : at.front());
        }
        coarse[p].push_back(tri);
    }

    const float error =
        relative * meshopt_simplifyScale(&w.positions[0].x, w.positions.size(), sizeof(glm::vec3));
    for (uint32_t p = 0; p < g.partCount; ++p) {
        if (!coarse[p].empty()) continue;
        // A triangle of zero area on one of its own vertices: the part stays, drawn nowhere.
        const uint32_t v =
            scene.indices[g.firstIndex + 3 * scene.parts[g.firstPart + p].firstTriangle];
        parts[p].indices = {v, v, v};
    }
    for (PartLevel& part : parts) part.error = error;
    return parts;
}

} // namespace scene
