// copies.h - model copies: every object replicated on a grid, each copy with unique part IDs
// of its own, geometry shared (copies add objects, not vertices).
#pragma once

#include "scene/scene.h"

namespace scene {

// copies >= 1. Copy 0 is the scene itself; copy k is shifted along a square-ish grid in the
// x/y plane by the scene's extent plus a 10% gap. Objects of copy k follow all of copy k-1,
// so unique part IDs of copy k are those of copy 0 plus k * scene.uniquePartCount().
Scene replicate(const Scene& scene, uint32_t copies);

} // namespace scene
