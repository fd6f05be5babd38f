// face_info.h - what --face-info (and the viewer's face properties) says of a part: its
// surface in world coordinates, with the exact area where a B-rep face stands behind it
// (SurfaceInfo, kept from the load) and the area of its triangles otherwise, and its box.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "scene/scene.h"
#include "scene/surface_info.h"

namespace scene {

struct FaceReport {
    uint32_t part = 0, object = 0;
    std::optional<uint32_t> face; // CAD files: the B-rep face
    SurfaceInfo surface;          // world coordinates
    Bounds bbox;                  // world, of the part's triangles
};

// Objects place geometry rigidly, or scaled alike on every axis: areas and radii scale by the
// cube root of the placement's determinant.
std::optional<FaceReport> faceReport(const Scene& scene, uint32_t uniquePartId);

// Two planar faces compared: the angle between their outward normals (0: facing the same
// way, 90: square, 180: facing each other or apart), and where they are parallel the distance
// between their planes (a wall's thickness, a slot's width).
struct PlanePair {
    double angleDegrees = 0.0;
    std::optional<double> distance;
};
// nullopt unless both are planes.
std::optional<PlanePair> comparePlanes(const FaceReport& a, const FaceReport& b);

// {"part","object","face","surface","area",...,"bbox"}: "normal" and "d" for planes,
// "radius" and "axis" {origin, direction} for cylinders, "radius" and "center" for spheres.
std::string faceReportJson(const FaceReport& report);

} // namespace scene
