// lod_policy.h - the one policy that makes levels of detail of candidates, whatever made them
// (meshoptimizer's simplifier for glTF and procedural meshes, lod.cpp; Open CASCADE's mesher at
// coarser deflections for CAD files, cad/cad_levels.cpp): every candidate measured by
// levelError (lod_error.h), the candidates worth weighing, the choice over the whole scene
// (lod_choice.h), and the levels appended as geometries of their own (lod.h).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "scene/lod.h"
#include "scene/lod_error.h"

namespace scene {

// One full-detail geometry's candidates, in chains that each go from the finest aim to the
// coarsest (a falling share of the triangles; a growing deflection).
struct GeometryCandidates {
    uint32_t geometry = 0; // full detail, with no levels yet
    std::vector<std::vector<LevelMesh>> chains;
};

// A level whose error passes this share of its geometry's size would show only where the
// geometry spans a pixel or two: its error need not be measured whole, and its chain ends.
constexpr float kUsefulErrorShare = 0.5f;

// The size errors are weighed against: the diagonal of the geometry's box.
float geometrySize(const Scene& scene, const Geometry& g);

// Counts a candidate's triangles and bytes and measures its error (levelError), up to
// kUsefulErrorShare of `size` (geometrySize). A part empty at full detail is emptied first:
// whatever made the candidate (a coarser mesher run may mesh a face the fine one could not),
// no level draws what full detail does not.
void measureCandidate(const Scene& scene, const Geometry& full, LevelMesh& level, float size);

// The candidates worth weighing, from every chain: up to the first that failed or whose error
// passes kUsefulErrorShare of the geometry's size, each with fewer triangles than every one
// before it in its chain (a locked border, seams or a face's outline may hold an aim back, and
// a coarser aim may then do better). Moved out of `candidates`.
std::vector<LevelMesh> usefulCandidates(const Scene& scene, GeometryCandidates& candidates);

// For every geometry of `candidates`, up to options.levels - 1 levels chosen among its useful
// candidates by chooseLevels (lod_choice.h): by growing error, each keeping at most
// options.keepAtMost of the triangles of the one before, those that draw the fewest triangles
// over every size on screen times the objects that draw the geometry, while all levels take at
// most options.memory of these geometries' full-detail bytes. Appended in the order of
// `candidates`, so the scene does not depend on the threads that made them.
void addChosenLevels(Scene& scene, std::vector<GeometryCandidates>& candidates,
                     const LodOptions& options);

// The candidates of every full-detail geometry without levels, made by meshoptimizer's
// simplifier (lod.cpp): two chains, with seams between the parts and welded (lod_welded.h),
// each at a falling share of the triangles. On every hardware thread; `progress` gets 0..1.
std::vector<GeometryCandidates> meshCandidates(const Scene& scene, const LodOptions& options,
                                               const LodProgress& progress = {});

// Runs task(i) for every i below `count` on every hardware thread, the calling thread too,
// which calls `progress` (the share of tasks finished) between its tasks. Tasks run in the
// order of i, each once, but may finish in any order. What a task or `progress` throws, on
// any thread (std::bad_alloc included), stops the tasks not begun and is rethrown here once
// the threads are done.
void forEachTask(size_t count, const std::function<void(size_t)>& task,
                 const std::function<void(double)>& progress = {});

} // namespace scene
