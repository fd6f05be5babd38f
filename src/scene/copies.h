// copies.h - model copies: every object replicated on a grid, each copy with unique part IDs
// of its own, geometry shared (copies add objects, not vertices).
#pragma once

#include <string>

#include "scene/scene.h"

namespace scene {

// The axes a grid of copies spans, as bits.
enum CopyAxis : uint32_t { COPY_X = 1, COPY_Y = 2, COPY_Z = 4 };
constexpr uint32_t COPY_XY = COPY_X | COPY_Y;

// "x", "xz", "zyx", ...: a non-empty set of x, y and z, each at most once. Throws
// std::invalid_argument with a message for people.
uint32_t parseCopyAxes(const std::string& text);
// The axes as parseCopyAxes reads them back: "xy", "z", ...
std::string copyAxesName(uint32_t axes);

// copies >= 1. Copy 0 is the scene itself; copy k is shifted along a grid over the chosen
// axes (a row, a square-ish grid or a cube-ish block; x varies fastest) by the scene's extent
// plus a 10% gap. Objects of copy k follow all of copy k-1, so unique part IDs of copy k are
// those of copy 0 plus k * scene.uniquePartCount(). Names stay as they are; copy 0 keeps the
// paths too, copy k > 0 prefixes them with "copy k/" ("copy 1/car/chassis/floor pan" is the
// floor pan of the second copy), so that paths stay unique.
Scene replicate(const Scene& scene, uint32_t copies, uint32_t axes = COPY_XY);

} // namespace scene
