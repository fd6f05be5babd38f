// inspect.h - exact answers about what the user selected: the minimum distance between two
// things (faces, edges, solids, assembly nodes) with the two closest points, centre-to-centre
// and axis-to-axis distances and angles where circles and cylinders are involved, a point's
// distance to a plane; and a solid's volume, surface area and centre of mass. CAD scenes are
// answered from the B-rep (Scene::brep, Open CASCADE: BRepExtrema_DistShapeShape, BRepGProp),
// mesh scenes (glTF, generated) from their triangles. World coordinates, the scene's unit.
// This header stays free of Open CASCADE types.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace scene {

// A B-rep edge as the viewer and the JSON name it: the part (so the object, whose placement
// applies) and the edge's 0-based index in TopExp::MapShapes(shape, TopAbs_EDGE) of the part's
// geometry shape (BrepShapes), "edge E of its shape".
struct EdgeRef {
    uint32_t part = 0;
    uint32_t edge = 0;
    bool operator==(const EdgeRef&) const = default;
};

// One side of a measurement: a set of unique part IDs (a face, a solid's faces, an assembly
// node's), or a single edge. `label` names it for the panel: the assembly node, then the face
// or edge ("board/U3/ESP32 · face 12", "... · edge 4").
struct Thing {
    std::vector<uint32_t> parts; // sorted; empty when `edge` is set
    std::optional<EdgeRef> edge;
    std::string label;
};

struct DistanceReport {
    double distance = 0.0;       // minimum distance between the two things
    glm::dvec3 p0{0.0}, p1{0.0}; // its closest points, on a and on b
    bool fromBrep = false;       // exact B-rep answer (CAD) or triangles (mesh scenes)
    // Where both sides are circles (edges) or cylinders (faces): their centres' distance,
    // and their axes' angle (degrees, 0..90) and, where parallel, the axes' distance.
    std::optional<double> centreDistance, axisAngleDegrees, axisDistance;
    // Where one side is a planar face: the other side's centre (circle, sphere or cylinder
    // axis point nearest the plane, or a point thing's location) to that plane, signed along
    // its outward normal.
    std::optional<double> pointToPlane;
    LengthUnit unit;
};

// nullopt when a side is empty or names parts the scene does not have.
std::optional<DistanceReport> measureDistance(const Scene& scene, const Thing& a, const Thing& b);

struct SolidProperties {
    uint32_t object = 0;
    double volume = 0.0;    // unit cubed; 0 for an open shell
    double area = 0.0;      // unit squared, of every face
    glm::dvec3 center{0.0}; // centre of mass (volume's; the surface's for an open shell)
    Bounds bbox;            // world, exact (the B-rep's), mesh: the triangles'
    bool closed = false;    // a closed solid (its volume means something)
    LengthUnit unit;
};

// How finely the scene's lengths are known (precision.h): its B-rep's tolerance
// (brepTolerance) against a float's resolution at its largest coordinate.
Precision scenePrecision(const Scene& scene);

// An object's properties (a CAD solid, placed); mesh objects give area, bbox and, when their
// triangles close, the enclosed volume and its centre. nullopt for an object out of range.
std::optional<SolidProperties> objectProperties(const Scene& scene, uint32_t object);

// Several objects together (a selection, a whole CAD file): volumes and areas summed, the
// boxes united, the centre of mass weighted by volume (by area where one is open), closed
// where all are; `object` holds the count.
SolidProperties sumProperties(const std::vector<SolidProperties>& each);

// {"distance":D,"p0":[x,y,z],"p1":[x,y,z],"source":"brep"|"mesh",...,"unit":"mm"}, then the
// optional members where set: "center_distance", "axis_angle" (degrees), "axis_distance",
// "point_to_plane".
std::string distanceJson(const DistanceReport& report);
// {"object":O,"volume":V,"area":A,"center":[..],"bbox":{"min":[..],"max":[..],"size":[..]},
// "closed":true,"unit":"mm"}; "bbox" is null for an object without triangles.
std::string propertiesJson(const SolidProperties& properties);
// A sum's line: {"object":"all","objects":N,"volume":...} as propertiesJson.
std::string totalPropertiesJson(const SolidProperties& sum);

} // namespace scene
