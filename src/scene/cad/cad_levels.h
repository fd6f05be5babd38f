// cad_levels.h - candidate levels of detail of CAD shapes: each shape's faces tessellated again
// by Open CASCADE at coarser deflections, one part per face as at full detail, for the policy
// every kind of geometry shares (scene/lod_policy.h). For the CAD loader only: this header,
// unlike cad_loader.h, speaks Open CASCADE.
#pragma once

#include <functional>
#include <set>
#include <vector>

#include "scene/cad/brep_occt.h"
#include "scene/lod_policy.h"

namespace scene {

// The deflections candidates are tessellated at, as multiples of full detail's: doubling, so
// that a curved face's triangles fall by about half from one to the next (the mesh path's
// shares of the triangles fall alike), as far as a level's error may still be worth weighing
// for a shape a quarter of the model's size (full detail's deflection being a thousandth of
// the model's diagonal unless --deflection says otherwise).
constexpr double kCandidateDeflections[] = {2, 4, 8, 16, 32, 64, 128, 256};

// The candidates of every full-detail geometry of `scene` without levels that `shapes` (by
// geometry index, as BrepShapes keeps them) has a shape for: one chain each, its faces
// tessellated at each of kCandidateDeflections times `deflection`, the angular bound grown by
// the square root of that multiple (a chord's sag grows as the square of the angle it spans)
// up to 90 degrees, and measured by levelError as a mesh's candidates are. Faces of one
// tessellation share the points of their edges, so no crack opens between them. A shape's
// chain ends at a tessellation where a face of its has no triangles, or before one whose
// deflection passes kUsefulErrorShare of its size (what the mesher may stray by). Faces in
// `skipped` are not meshed; the shapes keep no triangulation afterwards. `progress` gets 0..1
// and may throw to stop.
std::vector<GeometryCandidates> cadCandidates(const Scene& scene,
                                              const std::vector<BrepShapes::Shape>& shapes,
                                              double deflection, double angularDeflection,
                                              const std::set<const void*>& skipped,
                                              const std::function<void(double)>& progress = {});

} // namespace scene
