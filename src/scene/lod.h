// lod.h - coarser levels of detail of a scene's geometries, part by part, so that every
// triangle of a level belongs to one part of the full-detail geometry and part IDs do not
// depend on the level. Plain C++, built once per scene.
//
// A level is a geometry of its own in Scene::geometries, with the same parts in the same
// order (the same partFaces and partMaterials), so every technique's ID data is built for it
// as for any geometry. The full-detail geometry lists its levels (Geometry::levels) and each
// level its error in model units (Geometry::lodError). A part empty at full detail is empty at
// every level, and a geometry without triangles has no levels.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "scene/scene.h"

namespace scene {

// Levels 0 (full detail) to maxLevels - 1.
constexpr uint32_t maxLevels = gpu::LOD_MAX_LEVELS; // CullStats counts each

struct LodOptions {
    uint32_t levels = maxLevels; // including full detail: 1 builds none
    // A level that keeps more than this share of the level before's triangles is not worth
    // its memory, nor are levels that together would take more than `memory` of full
    // detail's bytes (vertices, indices and part ranges), so every level together stays
    // under 1 + memory of full detail alone.
    float keepAtMost = 0.8f;
    float memory = 0.55f;
};

// Called with the share of geometries done, 0..1, from the calling thread.
using LodProgress = std::function<void(double fraction)>;

// Adds the levels of every full-detail geometry that has none yet: meshoptimizer's simplifier
// makes candidates at a falling share of the triangles, with seams between the parts or
// welded (lod.cpp, lod_welded.h), and the policy every kind of geometry shares (lod_policy.h)
// measures their error against full detail and keeps those that would draw the fewest
// triangles over every distance the geometry may be seen at. Runs on every hardware thread;
// the result does not depend on their number. (CAD files make their candidates from Open
// CASCADE instead, scene/cad/cad_levels.h.)
void buildLevels(Scene& scene, const LodOptions& options = {}, const LodProgress& progress = {});

// What a geometry of this size takes in memory: its vertices, indices and part ranges. The
// memory rules of levels and the statistics all count this.
inline uint64_t geometryBytes(uint64_t vertices, uint64_t triangles, uint64_t parts) {
    return vertices * sizeof(Vertex) + 12 * triangles + parts * sizeof(Part);
}
inline uint64_t geometryBytes(const Geometry& g) {
    return geometryBytes(g.vertexCount, g.triangleCount, g.partCount);
}

// A new coarser level of `full` before its vertices and triangles: named after it, with its
// parts (same count, faces, surfaces and materials), starting at the scene's array ends.
Geometry levelShell(const Scene& scene, const Geometry& full, uint32_t level);

// The geometry `object` draws at `level`: its own at 0, else its coarsest level up to
// `level` (geometries with fewer levels stop at their last).
uint32_t geometryAtLevel(const Scene& scene, uint32_t geometry, uint32_t level);

// What one level holds over the whole scene, for --stats and the benchmark.
struct LevelStats {
    uint32_t geometries = 0;      // full-detail geometries that have this level
    uint64_t uniqueTriangles = 0; // in those geometries
    uint64_t vertices = 0;
    uint64_t bytes = 0;          // vertices, indices and part ranges
    uint64_t drawnTriangles = 0; // every object drawn at this level (geometryAtLevel)
    float maxError = 0.0f;       // model units
};
// Levels 0 to the most any geometry has; objects retargeted by retargetToLevel count from
// their full-detail geometry.
std::vector<LevelStats> levelStats(const Scene& scene);

// Every object drawn at `level` (geometryAtLevel): what forcing one level for the whole scene
// draws. Part IDs, names and placements are those of `scene`.
void retargetToLevel(Scene& scene, uint32_t level);

} // namespace scene
