// copy_grid.h - where model copies go: the axes their grid spans and each copy's shift. Plain
// C++ over glm, shared by scene::replicate and the STEP copies generator (src/tools/).
#pragma once

#include <cstdint>
#include <string>

#include <glm/glm.hpp>

namespace scene {

// The axes a grid of copies spans, as bits.
enum CopyAxis : uint32_t { COPY_X = 1, COPY_Y = 2, COPY_Z = 4 };
constexpr uint32_t COPY_XY = COPY_X | COPY_Y;

// "x", "xz", "zyx", ...: a non-empty set of x, y and z, each at most once. Throws
// std::invalid_argument with a message for people.
uint32_t parseCopyAxes(const std::string& text);
// The axes as parseCopyAxes reads them back: "xy", "z", ...
std::string copyAxesName(uint32_t axes);

// The distance between neighbouring copies along each axis for a model whose box has sides
// `extent`: the extent plus a 10% gap. A flat side takes the largest step (1 for a point), so
// that copies never lie on top of each other.
glm::dvec3 copyStep(const glm::dvec3& extent);

// Throws std::invalid_argument unless `axes` is a non-empty set of x, y and z and copies >= 1.
void checkCopyGrid(uint32_t copies, uint32_t axes);

// Copy `copy` (0 to copies - 1) on a grid over `axes` (a row, a square-ish grid or a cube-ish
// block, as compact as `copies` allows; x varies fastest): its shift from copy 0, whole
// `step`s along each chosen axis. Checks its arguments as checkCopyGrid does.
glm::dvec3 copyShift(uint32_t copy, uint32_t copies, uint32_t axes, const glm::dvec3& step);

} // namespace scene
