// section.h - section planes: cuts through the scene that show its inside. The renderer
// discards what a plane removes and draws caps where the cut opens a solid; the CPU ray cast
// honours the same planes, so tests can check the images against it.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "shared.h"

namespace scene {

// One plane. It keeps the points where dot(normal, p) <= offset; flip keeps the other side.
// An axis plane's normal is that axis, so offset is the coordinate where it cuts.
struct SectionPlane {
    bool on = false;
    glm::dvec3 normal{1.0, 0.0, 0.0}; // unit length, world space
    double offset = 0.0;              // world coordinates: double, like placements
    bool flip = false;

    // The plane as (a, b, c, d) for points relative to `origin` (the GPU's frame origin,
    // render::FrameParams): a point is cut away where dot(equation, (p - origin, 1)) > 0. The
    // origin is taken out in double, so a cut far from the world's origin stays exact. A plane
    // that is off cuts nothing: (0, 0, 0, -1).
    glm::dvec4 equation(const glm::dvec3& origin = glm::dvec3(0.0)) const;
    bool keeps(const glm::dvec3& p) const {
        return glm::dot(equation(), glm::dvec4(p, 1.0)) <= 0.0;
    }
    bool operator==(const SectionPlane&) const = default;
};

// Up to three planes. A point is drawn when every plane that is on keeps it: together they
// can cut a slab, or a corner out of the view.
constexpr uint32_t maxSectionPlanes = gpu::SECTION_PLANES_MAX; // FrameData's planes
struct Section {
    std::array<SectionPlane, maxSectionPlanes> planes{};
    bool any() const;
    bool keeps(const glm::dvec3& p) const;
    // Puts the plane in the first slot that is off; false when all are on.
    bool add(const SectionPlane& plane);
    bool operator==(const Section&) const = default;
};

// The plane of axis 0, 1 or 2 (x, y, z) at `value`.
SectionPlane axisPlane(int axis, double value, bool flip = false);

// "x,1.5" or "z,-20,flip": the flag's and the script's form. Throws std::invalid_argument
// with a message for people.
SectionPlane parseSectionPlane(const std::string& text);

} // namespace scene
