// lod.cpp - candidate levels of detail of meshes by meshoptimizer's simplifier, with seams
// between the parts or welded (lod_welded.h), for the policy that chooses among them
// (lod_policy.h); and the scene's levels as a whole (lod.h).
#include "scene/lod.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <unordered_map>

#include "scene/lod_policy.h"
#include "scene/lod_welded.h"

namespace scene {
namespace {

// Simplifies one part on its own vertices, so that the simplifier's work and memory scale
// with the part, not with its geometry, and its border is the part's own outline.
PartLevel simplifyPart(const Scene& scene, const Geometry& g, const Part& part,
                       size_t targetTriangles) {
    if (part.empty()) return {}; // empty at every level
    const uint32_t* source = scene.indices.data() + g.firstIndex + 3 * part.firstTriangle;
    const size_t count = 3 * size_t(part.triangleCount);
    std::unordered_map<uint32_t, uint32_t> local;
    std::vector<uint32_t> globalOf, indices(count);
    std::vector<glm::vec3> positions;
    for (size_t i = 0; i < count; ++i) {
        auto [it, added] = local.try_emplace(source[i], uint32_t(globalOf.size()));
        if (added) {
            globalOf.push_back(source[i]);
            positions.push_back(scene.vertices[g.firstVertex + source[i]].position);
        }
        indices[i] = it->second;
    }
    PartLevel out;
    std::vector<uint32_t> reduced(count);
    // The error bound is left wide open: the level's size sets how far it goes, and the error
    // it reaches (levelError) decides where it may be drawn.
    const size_t kept = meshopt_simplify(
        reduced.data(), indices.data(), count, &positions[0].x, positions.size(), sizeof(glm::vec3),
        std::max<size_t>(3, 3 * targetTriangles), 1.0f, meshopt_SimplifyLockBorder, nullptr);
    if (kept == 0 || kept >= count) { // nothing to gain, or the part would vanish
        out.indices.assign(source, source + count);
        return out;
    }
    out.indices.resize(kept);
    for (size_t i = 0; i < kept; ++i) out.indices[i] = globalOf[reduced[i]];
    return out;
}

// Simplifies the geometry as a whole, every part on vertices of its own: where parts meet,
// meshoptimizer sees a seam, which it simplifies on both sides alike, so a part's outline may
// move (within the level's error) but never opens a crack; where three parts meet, the vertex
// stays. Every triangle keeps the part of its corners. Empty when a part would vanish (one
// empty at full detail stays empty).
std::vector<PartLevel> simplifyWhole(const Scene& scene, const Geometry& g, double share) {
    std::vector<uint32_t> indices, originOf, partOf;
    std::vector<glm::vec3> positions;
    indices.reserve(3 * size_t(g.triangleCount));
    for (uint32_t p = 0; p < g.partCount; ++p) {
        const Part& part = scene.parts[g.firstPart + p];
        std::unordered_map<uint32_t, uint32_t> local;
        for (uint32_t i = 3 * part.firstTriangle; i < 3 * (part.firstTriangle + part.triangleCount);
             ++i) {
            const uint32_t v = scene.indices[g.firstIndex + i];
            auto [it, added] = local.try_emplace(v, uint32_t(originOf.size()));
            if (added) {
                originOf.push_back(v);
                partOf.push_back(p);
                positions.push_back(scene.vertices[g.firstVertex + v].position);
            }
            indices.push_back(it->second);
        }
    }
    std::vector<uint32_t> reduced(indices.size());
    const size_t target = std::max<size_t>(3, 3 * size_t(double(g.triangleCount) * share + 0.5));
    // The error bound is left wide open, as for a part alone.
    const size_t kept = meshopt_simplify(reduced.data(), indices.data(), indices.size(),
                                         &positions[0].x, positions.size(), sizeof(glm::vec3),
                                         target, 1.0f, meshopt_SimplifyLockBorder, nullptr);
    std::vector<PartLevel> parts(g.partCount);
    for (size_t t = 0; t < kept; t += 3) {
        const uint32_t p = partOf[reduced[t]];
        if (partOf[reduced[t + 1]] != p || partOf[reduced[t + 2]] != p)
            throw std::logic_error("levels of detail: a triangle spans two parts");
        for (int k = 0; k < 3; ++k) parts[p].indices.push_back(originOf[reduced[t + k]]);
    }
    for (uint32_t p = 0; p < g.partCount; ++p)
        if (parts[p].indices.empty() && !scene.parts[g.firstPart + p].empty()) return {};
    return parts;
}

// With seams between the parts: as a whole where no part would vanish, at `share` or a
// milder aim up to keepAtMost of full detail, else each part alone inside its fixed outline.
std::vector<PartLevel> simplifySeamed(const Scene& scene, const Geometry& g, double share,
                                      const LodOptions& options) {
    std::vector<PartLevel> parts;
    for (double tried = share; parts.empty() && tried <= options.keepAtMost; tried *= 1.4)
        parts = simplifyWhole(scene, g, tried);
    if (!parts.empty()) return parts;
    for (uint32_t p = 0; p < g.partCount; ++p) {
        const Part& part = scene.parts[g.firstPart + p];
        const size_t target = size_t(double(part.triangleCount) * share + 0.5);
        parts.push_back(simplifyPart(scene, g, part, target));
    }
    return parts;
}

// One candidate level: at `share`, with seams between the parts (way 0) or welded (way 1,
// where the geometry has several parts; else none), with just the vertices it uses, in the
// order it first uses them.
LevelMesh candidateOf(const Scene& scene, const Geometry& g, double share, int way,
                      const LodOptions& options, float size) {
    std::vector<PartLevel> parts =
        way == 0 ? simplifySeamed(scene, g, share, options) : simplifyWelded(scene, g, share);
    LevelMesh level;
    if (parts.empty()) return level;
    std::vector<uint32_t> remap(g.vertexCount, UINT32_MAX);
    for (const PartLevel& part : parts) {
        std::vector<uint32_t>& out = level.parts.emplace_back();
        out.reserve(part.indices.size());
        for (uint32_t index : part.indices) {
            if (remap[index] == UINT32_MAX) {
                remap[index] = uint32_t(level.vertices.size());
                level.vertices.push_back(scene.vertices[g.firstVertex + index]);
            }
            out.push_back(remap[index]);
        }
    }
    measureCandidate(scene, g, level, size);
    return level;
}

// The shares of full detail's triangles candidates aim at: finely spaced near full detail,
// where a few hundredths of a unit of error separate a level that large parts may take at a
// few pixels from one they may not, then halving.
constexpr double candidateShares[] = {0.7, 0.5, 0.35, 0.25, 0.12, 0.06, 0.03, 0.015};

} // namespace

std::vector<GeometryCandidates> meshCandidates(const Scene& scene, const LodOptions& options,
                                               const LodProgress& progress) {
    std::vector<GeometryCandidates> out;
    // A geometry without triangles has nothing to simplify, and no level.
    for (uint32_t g = 0; g < scene.geometries.size(); ++g)
        if (scene.geometries[g].level == 0 && scene.geometries[g].levels.empty() &&
            scene.geometries[g].triangleCount > 0)
            out.push_back({g, {}});
    // Every candidate is a task of its own, the largest geometries' first, so that no thread
    // is left with a large one at the end.
    constexpr size_t shares = std::size(candidateShares);
    std::vector<float> sizes(out.size());
    std::vector<uint32_t> order(out.size());
    for (size_t i = 0; i < out.size(); ++i) {
        sizes[i] = geometrySize(scene, scene.geometries[out[i].geometry]);
        order[i] = uint32_t(i);
        out[i].chains.assign(2, std::vector<LevelMesh>(shares));
    }
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return scene.geometries[out[a].geometry].triangleCount >
               scene.geometries[out[b].geometry].triangleCount;
    });
    forEachTask(
        out.size() * 2 * shares,
        [&](size_t t) {
            const size_t i = order[t / (2 * shares)], way = t / shares % 2, share = t % shares;
            out[i].chains[way][share] =
                candidateOf(scene, scene.geometries[out[i].geometry], candidateShares[share],
                            int(way), options, sizes[i]);
        },
        progress);
    return out;
}

void buildLevels(Scene& scene, const LodOptions& options, const LodProgress& progress) {
    if (options.levels < 1 || options.levels > maxLevels)
        throw std::invalid_argument("levels of detail: 1 to " + std::to_string(maxLevels));
    if (options.levels > 1) {
        std::vector<GeometryCandidates> candidates = meshCandidates(scene, options, progress);
        addChosenLevels(scene, candidates, options);
    }
    if (progress) progress(1.0);
}

Geometry levelShell(const Scene& scene, const Geometry& full, uint32_t level) {
    Geometry out;
    out.name = full.name + " (level " + std::to_string(level) + ")";
    out.partFaces = full.partFaces;
    out.partSurfaces = full.partSurfaces;
    out.partMaterials = full.partMaterials;
    out.level = level;
    out.firstVertex = uint32_t(scene.vertices.size());
    out.firstIndex = uint32_t(scene.indices.size());
    out.firstPart = uint32_t(scene.parts.size());
    out.partCount = full.partCount;
    return out;
}

uint32_t geometryAtLevel(const Scene& scene, uint32_t geometry, uint32_t level) {
    const Geometry& g = scene.geometries[geometry];
    if (level == 0 || g.levels.empty()) return geometry;
    return g.levels[std::min<size_t>(level, g.levels.size()) - 1];
}

std::vector<LevelStats> levelStats(const Scene& scene) {
    std::vector<uint32_t> fullDetail(scene.geometries.size());
    size_t levels = 1;
    for (uint32_t g = 0; g < scene.geometries.size(); ++g) {
        fullDetail[g] = g;
        levels = std::max(levels, scene.geometries[g].levels.size() + 1);
    }
    for (uint32_t g = 0; g < scene.geometries.size(); ++g)
        for (uint32_t l : scene.geometries[g].levels) fullDetail[l] = g;
    std::vector<LevelStats> stats(levels);
    for (const Geometry& g : scene.geometries) {
        LevelStats& s = stats[g.level];
        ++s.geometries;
        s.uniqueTriangles += g.triangleCount;
        s.vertices += g.vertexCount;
        s.bytes += geometryBytes(g);
        s.maxError = std::max(s.maxError, g.lodError);
    }
    for (const Object& o : scene.objects)
        for (uint32_t l = 0; l < levels; ++l)
            stats[l].drawnTriangles +=
                scene.geometries[geometryAtLevel(scene, fullDetail[o.geometry], l)].triangleCount;
    return stats;
}

void retargetToLevel(Scene& scene, uint32_t level) {
    for (Object& o : scene.objects) o.geometry = geometryAtLevel(scene, o.geometry, level);
}

} // namespace scene
