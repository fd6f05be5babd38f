// lod_welded.h - one of the two ways lod.cpp reduces a geometry (scene/lod.h): as one surface,
// its parts welded where their vertices share a position, each triangle of the result then
// given to a part. Where parts are small, simplifying each inside its locked outline keeps
// most of their triangles; welded, a geometry of many small parts shrinks like any other
// surface.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace scene {

// One part's triangles at one level, as indices into the full-detail geometry's vertices.
struct PartLevel {
    std::vector<uint32_t> indices;
};

// The geometry welded and simplified to about `share` of its triangles, with its open edges
// locked, so no crack opens inside it or along its border. Each triangle goes to the part
// that all its corners share, else to the part of the full-detail triangle nearest its
// centre, and takes that part's vertex at each corner where it has one. A part left
// without triangles keeps one of zero area, which draws nothing (its error counts its
// diagonal, lod_error.h); a part empty at full detail stays empty. Empty where the geometry
// has a single part (lod.cpp's own way does the same there).
std::vector<PartLevel> simplifyWelded(const Scene& scene, const Geometry& g, double share);

} // namespace scene
