// lod_welded.cpp - a level of detail of a geometry simplified as one surface (lod_welded.h).
#include "scene/lod_welded.h"

#include "scene/lod_error.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cstring>
#include <optional>
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

std::vector<PartLevel> simplifyWelded(const Scene& scene, const Geometry& g, double share) {
    if (g.partCount < 2) return {};
    const Welded w = weld(scene, g);
    std::vector<uint32_t> reduced(w.indices.size());
    const size_t target = std::max<size_t>(3, 3 * size_t(double(g.triangleCount) * share + 0.5));
    const size_t kept = meshopt_simplify(reduced.data(), w.indices.data(), w.indices.size(),
                                         &w.positions[0].x, w.positions.size(), sizeof(glm::vec3),
                                         target, 1.0f, meshopt_SimplifyLockBorder, nullptr);
    if (kept == 0 || kept >= w.indices.size()) return {};
    reduced.resize(kept);
    // The open edges locked stay the only ones: where a welded geometry is not a clean
    // surface (edges of three triangles), the simplifier can open one elsewhere.
    if (openEdges(reduced) != openEdges(w.indices)) return {};

    // Which part each of the geometry's vertices belongs to (a vertex serves one part).
    std::vector<uint32_t> partOfVertex(g.vertexCount, 0);
    std::vector<std::vector<Triangle>> full(g.partCount);
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
    }

    for (uint32_t p = 0; p < g.partCount; ++p) {
        const Part& part = scene.parts[g.firstPart + p];
        if (!parts[p].indices.empty() || part.empty()) continue;
        // A triangle of zero area on one of its own vertices: the part stays, drawn nowhere,
        // and levelError counts what it lost.
        const uint32_t v = scene.indices[g.firstIndex + 3 * part.firstTriangle];
        parts[p].indices = {v, v, v};
    }
    return parts;
}

} // namespace scene
