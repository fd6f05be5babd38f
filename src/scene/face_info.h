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
    LengthUnit unit;              // the scene's: of the coordinates, radius and area
    Precision precision;          // the scene's, for describeSurface
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

// {"part","object","face","surface","area",...,"bbox","unit"}: "normal" and "d" for planes,
// "radius" and "axis" {origin, direction} for cylinders, "radius" and "center" for spheres;
// lengths and coordinates in "unit", the area in it squared; "bbox" null for an empty part.
std::string faceReportJson(const FaceReport& report);

// What the panel and the event lines say of a face, rounded to the scene's precision, the
// length unit once: "cylinder Ø 10 mm (r 5), axis (0, 0, 1), area 628.32 mm²", "plane n (0, 0,
// 1), area 200 mm²"; a mesh part (no B-rep face) gives "mesh, triangle area 0.5 m²".
std::string describeSurface(const FaceReport& report);

} // namespace scene
