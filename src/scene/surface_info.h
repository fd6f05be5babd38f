// surface_info.h - what a CAD part's B-rep face is, kept from the load (Open CASCADE is gone
// by the time a user asks): its surface type and exact area, and the plane, axis and radius
// where the surface has them. Model units, the geometry's coordinates. Plain C++.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace scene {

enum class SurfaceKind : uint8_t {
    Mesh, // not a B-rep face: a glTF or procedural part
    Plane,
    Cylinder,
    Cone,
    Sphere,
    Torus,
    BSpline,
    Bezier,
    Revolution,
    Extrusion,
    Offset,
    Other,
};

// "plane", "cylinder", ... as --face-info prints them.
const char* surfaceName(SurfaceKind kind);

struct SurfaceInfo {
    SurfaceKind kind = SurfaceKind::Mesh;
    double area = 0.0; // of the face as trimmed, from the B-rep
    // Planes: the outward normal (the face's orientation) and d, with normal . p = d.
    glm::dvec3 normal{0.0};
    double d = 0.0;
    // Cylinders: radius and axis (a point on it and its direction); spheres: radius and
    // centre (axisOrigin).
    double radius = 0.0;
    glm::dvec3 axisOrigin{0.0}, axisDirection{0.0};
};

} // namespace scene
