// visibility_tint.h - the Visibility section's "tint by visibility": per part, the colour a
// finished census gives it (Renderer::setTint's), so the picture shows what the census found.
// Plain C++: unit-tested without a GPU.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/census.h"
#include "scene/part_set.h"

namespace app {

// How strongly a tinted part takes its tint (the packed colour's alpha): enough to read the
// ramp at a glance, little enough to keep the shading's light and dark.
constexpr uint8_t tintStrength = 190;
// Never seen: a colour the ramp never takes.
constexpr uint32_t neverSeenTint = 0xff00ffu | (uint32_t(tintStrength) << 24); // magenta

// Where a part of `pixels` sits on the ramp, 0 (barely seen) to 1 (as many as `largest`,
// the census's most seen part): log(1 + pixels) over log(1 + largest), since pixel counts
// span several orders of magnitude.
double tintRampPosition(uint64_t pixels, uint64_t largest);
// The heat ramp at `t` in 0..1, display-encoded RGBA8 (glm::packUnorm4x8's layout) with
// tintStrength as alpha: blue, cyan, green, yellow, red.
uint32_t tintRamp(double t);
// Per unique part: the ramp by its pixels for a part seen, neverSeenTint for one of
// `neverSeen`, 0 (untouched) for the rest (hidden parts and parts without triangles).
std::vector<uint32_t> visibilityTint(const scene::Census& census, const scene::PartSet& neverSeen);

} // namespace app
