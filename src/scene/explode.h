// explode.h - the exploded view of an assembly, by assembly level: every node of the assembly
// tree (scene/assembly_tree.h) moves its members (child nodes, and its own object) apart
// from its centre, sub-assemblies as groups first and their parts within them less. The GPU
// animates it (render/animator.h); these are the CPU reference and the per-object offsets the
// GPU is given.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace scene {

// Per object: where it has moved at explode 1 (w is 0). A node's members each move by
// weight * (member's centre - node's centre), centres of world bounds, on top of what their
// node moved; the root's weight is 1, and below a node of two or more members the weight
// halves, so sub-assemblies part by more than their own parts do (a chain of single members
// changes nothing). The offset is a sum of fixed terms, so explode * offset stays linear in
// explode, and in a flat assembly it is the object's centre minus the scene's centre.
std::vector<glm::vec4> explodeOffsets(const Scene& scene);

// Writes into `moved` (a copy of `rest`) every object's placement moved by explode * offset,
// with exactly the float operations animate.comp performs, so both render the same pixels.
void placeExploded(Scene& moved, const Scene& rest, const std::vector<glm::vec4>& offsets,
                   float explode);
// A copy of `scene` with every object's translation moved by explode * its offset; it shares
// the scene's geometry (scene/shared_array.h) and holds objects of its own.
Scene explodedScene(const Scene& scene, float explode);

// The animation loop: 0 at t = 0, 1 at half the period, back to 0 after `periodSeconds`
// (0.5 - 0.5 cos(2 pi t / period)), smooth at both ends.
float explodeLoop(float seconds, float periodSeconds = 4.0f);

} // namespace scene
