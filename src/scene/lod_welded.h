// lod_welded.h - one of the two ways lod.cpp reduces a geometry (scene/lod.h): as one surface,
// its parts welded where their vertices share a position, each triangle of the result then
// given to a part; and the distance by which that moves any part, which the level's error
// covers. Where parts are small, simplifying each inside its locked outline keeps most of
// their triangles; welded, a geometry of many small parts shrinks like any other surface.
#pragma once

#include <cfloat>
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace scene {

// One part's triangles at one level, as indices into the full-detail geometry's vertices.
struct PartLevel {
    std::vector<uint32_t> indices;
    float error = 0.0f; // model units
};

// The geometry welded and simplified to about `share` of its triangles, with its open edges
// locked, so no crack opens inside it or along its border. Each triangle goes to the part
// that all its corners share, else to the part of the full-detail triangle nearest its
// centre, and takes that part's vertex at each corner where it has one. A part left
// without triangles keeps one of zero area, which draws nothing (every part of a geometry has
// triangles). The parts' error is meshoptimizer's; lod.cpp adds partsMoved. Empty where the
// geometry has a single part (lod.cpp's own way does the same there).
std::vector<PartLevel> simplifyWelded(const Scene& scene, const Geometry& g, double share);

// How far a level moves any part of `g`, in model units: over the parts, the farthest a
// corner or centre of a part's triangles at either level lies from the part's triangles at
// the other; for a part drawn nowhere (only triangles of zero area), its diagonal. Past
// `limit` it stops measuring and returns a distance beyond it.
float partsMoved(const Scene& scene, const Geometry& g, const std::vector<PartLevel>& parts,
                 float limit = FLT_MAX);

} // namespace scene
