// copies.h - model copies: every object replicated on a grid, each copy with unique part IDs
// of its own, geometry shared (copies add objects, not vertices).
#pragma once

#include "scene/copy_grid.h"
#include "scene/scene.h"

namespace scene {

// copies >= 1. Copy 0 is the scene itself; copy k is shifted along a grid over the chosen
// axes (copyShift, scene/copy_grid.h) by the scene's extent plus a 10% gap (copyStep).
// Objects of copy k follow all of copy k-1, so unique part IDs of copy k are
// those of copy 0 plus k * scene.uniquePartCount(). Names stay as they are; copy 0 keeps the
// paths too, copy k > 0 prefixes them with "copy k/" ("copy 1/car/chassis/floor pan" is the
// floor pan of the second copy), so that paths stay unique.
Scene replicate(const Scene& scene, uint32_t copies, uint32_t axes = COPY_XY);

} // namespace scene
