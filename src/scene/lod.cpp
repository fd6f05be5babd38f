// lod.cpp - levels of detail by meshoptimizer's simplifier: with seams between the parts, or
// welded (lod_welded.h), whichever gives the fewer triangles for the error.
#include "scene/lod.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <iterator>
#include <limits>
#include <span>
#include <stdexcept>
#include <thread>
#include <tuple>
#include <unordered_map>

#include "scene/lod_choice.h"
#include "scene/lod_welded.h"

namespace scene {
namespace {

// Simplifies one part on its own vertices, so that the simplifier's work and memory scale
// with the part, not with its geometry, and its border is the part's own outline.
PartLevel simplifyPart(const Scene& scene, const Geometry& g, const Part& part,
                       size_t targetTriangles) {
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
    float relative = 0.0f;
    // The error bound is left wide open: the level's size sets how far it goes, and the error
    // it reaches decides where it may be drawn.
    const size_t kept = meshopt_simplify(
        reduced.data(), indices.data(), count, &positions[0].x, positions.size(), sizeof(glm::vec3),
        std::max<size_t>(3, 3 * targetTriangles), 1.0f, meshopt_SimplifyLockBorder, &relative);
    if (kept == 0 || kept >= count) { // nothing to gain, or the part would vanish
        out.indices.assign(source, source + count);
        return out;
    }
    out.indices.resize(kept);
    for (size_t i = 0; i < kept; ++i) out.indices[i] = globalOf[reduced[i]];
    out.error =
        relative * meshopt_simplifyScale(&positions[0].x, positions.size(), sizeof(glm::vec3));
    return out;
}

// Simplifies the geometry as a whole, every part on vertices of its own: where parts meet,
// meshoptimizer sees a seam, which it simplifies on both sides alike, so a part's outline may
// move (within the level's error) but never opens a crack; where three parts meet, the vertex
// stays. Every triangle keeps the part of its corners. Empty when a part would vanish.
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
    float relative = 0.0f;
    const size_t target = std::max<size_t>(3, 3 * size_t(double(g.triangleCount) * share + 0.5));
    // The error bound is left wide open: the level's size sets how far it goes, and the error
    // it reaches decides where it may be drawn.
    const size_t kept = meshopt_simplify(reduced.data(), indices.data(), indices.size(),
                                         &positions[0].x, positions.size(), sizeof(glm::vec3),
                                         target, 1.0f, meshopt_SimplifyLockBorder, &relative);
    const float error =
        relative * meshopt_simplifyScale(&positions[0].x, positions.size(), sizeof(glm::vec3));
    std::vector<PartLevel> parts(g.partCount);
    for (size_t t = 0; t < kept; t += 3) {
        const uint32_t p = partOf[reduced[t]];
        if (partOf[reduced[t + 1]] != p || partOf[reduced[t + 2]] != p)
            throw std::logic_error("levels of detail: a triangle spans two parts");
        for (int k = 0; k < 3; ++k) parts[p].indices.push_back(originOf[reduced[t + k]]);
    }
    for (PartLevel& part : parts) {
        if (part.indices.empty()) return {};
        part.error = error;
    }
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

struct Candidate {
    std::vector<PartLevel> parts;
    size_t triangles = 0;
    uint64_t bytes = 0; // as levelStats counts them
    float error = 0.0f;
};

// One candidate level: at `share`, with seams between the parts (way 0) or welded (way 1,
// where the geometry has several parts; else none). Where parts meet, meshoptimizer's error
// is the surface's, not how far a part's outline went along it: the error covers both.
// Errors past `limit` need not be measured whole.
Candidate candidateOf(const Scene& scene, const Geometry& g, double share, int way,
                      const LodOptions& options, float limit) {
    Candidate c;
    c.parts = way == 0 ? simplifySeamed(scene, g, share, options) : simplifyWelded(scene, g, share);
    if (c.parts.empty()) return c;
    c.error = partsMoved(scene, g, c.parts, limit);
    std::vector<bool> used(g.vertexCount, false);
    size_t vertices = 0;
    for (PartLevel& part : c.parts) {
        c.triangles += part.indices.size() / 3;
        c.error = std::max(c.error, part.error);
        for (uint32_t v : part.indices)
            if (!used[v]) used[v] = true, ++vertices;
    }
    c.bytes = geometryBytes(vertices, c.triangles, g.partCount);
    for (PartLevel& part : c.parts) part.error = c.error;
    return c;
}

// The shares of full detail's triangles candidates aim at: finely spaced near full detail,
// where a few hundredths of a unit of error separate a level that large parts may take at a
// few pixels from one they may not, then halving.
constexpr double candidateShares[] = {0.7, 0.5, 0.35, 0.25, 0.12, 0.06, 0.03, 0.015};

// One way's candidates (by falling share) worth weighing: up to the first whose error passes
// half the geometry's size (it would show only where the geometry spans a pixel or two),
// each with fewer triangles than every one before it (a part's locked border or seams may
// hold a share's aim back, and a smaller one may then do better).
void keepUseful(std::vector<Candidate>& out, std::span<Candidate> way, size_t triangles,
                float size) {
    for (Candidate& c : way) {
        if (c.parts.empty() || c.error > 0.5f * size) break;
        if (c.triangles >= triangles) continue;
        triangles = c.triangles;
        out.push_back(std::move(c));
    }
}

// The size errors are weighed against: the diagonal of the geometry's box.
float sizeOf(const Scene& scene, const Geometry& g) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (uint32_t v = 0; v < g.vertexCount; ++v) {
        lo = glm::min(lo, scene.vertices[g.firstVertex + v].position);
        hi = glm::max(hi, scene.vertices[g.firstVertex + v].position);
    }
    return g.vertexCount ? glm::length(hi - lo) : 0.0f;
}

// Appends one level as a geometry of its own, with just the vertices it uses.
uint32_t addLevel(Scene& scene, uint32_t base, uint32_t level, std::vector<PartLevel>& parts) {
    const Geometry& g = scene.geometries[base];
    Geometry out = levelShell(scene, g, level);
    std::vector<uint32_t> remap(g.vertexCount, UINT32_MAX);
    for (PartLevel& part : parts) {
        out.lodError = std::max(out.lodError, part.error);
        const uint32_t first = out.triangleCount;
        for (uint32_t index : part.indices) {
            if (remap[index] == UINT32_MAX) {
                remap[index] = out.vertexCount++;
                const Vertex vertex = scene.vertices[g.firstVertex + index];
                scene.vertices.push_back(vertex);
            }
            scene.indices.push_back(remap[index]);
        }
        out.triangleCount += uint32_t(part.indices.size() / 3);
        scene.parts.push_back({first, out.triangleCount - first});
        part.indices = {};
    }
    // A coarser level is never said to be closer than a finer one.
    const Geometry& finer = g.levels.empty() ? g : scene.geometries[g.levels.back()];
    out.lodError = std::max(out.lodError, finer.lodError);
    scene.geometries.push_back(std::move(out));
    const uint32_t index = uint32_t(scene.geometries.size() - 1);
    scene.geometries[base].levels.push_back(index);
    return index;
}

} // namespace

void buildLevels(Scene& scene, const LodOptions& options, const LodProgress& progress) {
    if (options.levels < 1 || options.levels > maxLevels)
        throw std::invalid_argument("levels of detail: 1 to " + std::to_string(maxLevels));
    std::vector<uint32_t> todo;
    for (uint32_t g = 0; g < scene.geometries.size(); ++g)
        if (scene.geometries[g].level == 0 && scene.geometries[g].levels.empty()) todo.push_back(g);
    // Every candidate is a task of its own, the largest geometries' first, so that no
    // thread is left with a large one at the end. The calling thread works too and reports
    // between its tasks.
    constexpr size_t shares = std::size(candidateShares);
    std::vector<float> sizes(todo.size());
    std::vector<uint32_t> order(todo.size());
    for (size_t i = 0; i < todo.size(); ++i) {
        sizes[i] = sizeOf(scene, scene.geometries[todo[i]]);
        order[i] = uint32_t(i);
    }
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return scene.geometries[todo[a]].triangleCount > scene.geometries[todo[b]].triangleCount;
    });
    const size_t tasks = options.levels > 1 ? todo.size() * 2 * shares : 0;
    std::vector<Candidate> candidates(todo.size() * 2 * shares);
    std::atomic<size_t> next{0}, done{0};
    auto work = [&](bool report) {
        for (size_t t; (t = next.fetch_add(1)) < tasks;) {
            const size_t i = order[t / (2 * shares)], way = t / shares % 2, share = t % shares;
            candidates[(2 * i + way) * shares + share] =
                candidateOf(scene, scene.geometries[todo[i]], candidateShares[share], int(way),
                            options, 0.5f * sizes[i]);
            const size_t finished = ++done;
            if (report && progress) progress(double(finished) / double(tasks));
        }
    };
    const unsigned threads =
        std::max(1u, std::min<unsigned>(std::thread::hardware_concurrency(), unsigned(tasks)));
    std::vector<std::jthread> workers;
    for (unsigned t = 1; t < threads; ++t) workers.emplace_back(work, false);
    work(true);
    workers.clear(); // joins
    // Which candidates become levels weighs every geometry against the others, by the
    // objects that draw it, for the memory the scene may spend on levels.
    std::vector<uint32_t> instances(scene.geometries.size(), 0);
    for (const Object& o : scene.objects) ++instances[o.geometry];
    std::vector<CandidateSet> sets(todo.size());
    std::vector<std::vector<Candidate>> useful(todo.size());
    double bytes = 0.0;
    for (size_t i = 0; i < todo.size(); ++i) {
        const Geometry& g = scene.geometries[todo[i]];
        for (size_t way = 0; way < 2; ++way)
            keepUseful(useful[i], {candidates.data() + (2 * i + way) * shares, shares},
                       g.triangleCount, sizes[i]);
        sets[i].triangles = g.triangleCount;
        sets[i].size = sizes[i];
        sets[i].instances = std::max(instances[todo[i]], 1u);
        for (const Candidate& c : useful[i])
            sets[i].candidates.push_back({c.triangles, c.bytes, c.error});
        bytes += double(geometryBytes(g));
    }
    const auto chosen =
        chooseLevels(sets, options.levels - 1, options.keepAtMost, double(options.memory) * bytes);
    // Appended in geometry order, so the scene does not depend on the threads' timing.
    for (size_t i = 0; i < todo.size(); ++i)
        for (size_t l = 0; l < chosen[i].size(); ++l)
            addLevel(scene, todo[i], uint32_t(l + 1), useful[i][chosen[i][l]].parts);
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
