// section.h - section planes: cuts through the scene that show its inside. The renderer
// discards what a plane removes and draws caps where the cut opens a solid; the CPU ray cast
// honours the same planes, so tests can check the images against it.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "scene/surface_info.h"
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
    // The same for a point of a surface whose outward normal there is `normal` (any length),
    // by the in-plane rule: a surface parallel to the plane (gpu::SECTION_PARALLEL_COS) and
    // within `tolerance` of it lies in it, and is kept where its outward normal faces the
    // side cut away (it bounds what the plane keeps), cut otherwise, whatever its rounding.
    // A face the plane was put in (planeAtFace) is thus whole, and cut whole with flip. The
    // renderer's rule too (shaders/scene.frag, cutAway).
    bool keeps(const glm::dvec3& p, const glm::dvec3& normal, double tolerance) const;
    bool operator==(const SectionPlane&) const = default;
};

// Up to three planes. A point is drawn when every plane that is on keeps it: together they
// can cut a slab, or a corner out of the view.
constexpr uint32_t maxSectionPlanes = gpu::SECTION_PLANES_MAX; // FrameData's planes
struct Section {
    std::array<SectionPlane, maxSectionPlanes> planes{};
    bool any() const;
    bool keeps(const glm::dvec3& p) const;
    bool keeps(const glm::dvec3& p, const glm::dvec3& normal, double tolerance) const;
    // Puts the plane in the first slot that is off; false when all are on.
    bool add(const SectionPlane& plane);
    bool operator==(const Section&) const = default;
};

// The plane of axis 0, 1 or 2 (x, y, z) at `value`.
SectionPlane axisPlane(int axis, double value, bool flip = false);

// The in-plane rule's tolerance where the largest magnitude float arithmetic meets (the
// coordinates, the placements' translations, the planes' offsets) is `reach`: far above the
// rounding of a point in a plane, far below anything a user sees apart from it.
double inPlaneTolerance(double reach);

// The plane of a planar face (SurfaceKind::Plane), flush with it, keeping the side its
// outward normal leaves: the solid it bounds. The viewer's "section at the selected face".
SectionPlane planeAtFace(const SurfaceInfo& face, bool flip = false);

// "x,1.5" or "z,-20,flip": the flag's and the script's form. Throws std::invalid_argument
// with a message for people.
SectionPlane parseSectionPlane(const std::string& text);

} // namespace scene
