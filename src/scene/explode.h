// explode.h - the exploded view of an assembly: every object moves away from the scene centre
// along the line through its own centre. The GPU animates it (render/animator.h); these are
// the CPU reference and the per-object offsets the GPU is given.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace scene {

// Per object: the centre of its world bounds minus the centre of the scene's bounds (w is 0).
// At explode 1 an object's translation has moved by its offset, so its centre is twice as far
// from the scene centre as at rest.
std::vector<glm::vec4> explodeOffsets(const Scene& scene);

// A copy of `scene` with every object's translation moved by explode * offset, with exactly
// the float operations animate.comp performs, so both render the same pixels.
Scene explodedScene(const Scene& scene, float explode);

// The animation loop: 0 at t = 0, 1 at half the period, back to 0 after `periodSeconds`
// (0.5 - 0.5 cos(2 pi t / period)), smooth at both ends.
float explodeLoop(float seconds, float periodSeconds = 4.0f);

} // namespace scene
