// brep_occt.h - BrepShapes's contents (brep_shapes.h) and the conversions every B-rep query
// needs: a part's face, an object's placement as a TopLoc_Location. Internal to src/scene;
// holds Open CASCADE types.
#pragma once

#include <optional>
#include <vector>

#include <TopLoc_Location.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <glm/glm.hpp>

#include "scene/cad/brep_shapes.h"
#include "scene/scene.h"

namespace scene {

struct BrepShapes::Impl {
    struct Shape {
        TopoDS_Shape shape;             // null: no shape for this geometry
        std::vector<TopoDS_Face> faces; // by B-rep face number (Geometry::partFaces)
    };
    std::vector<Shape> geometries; // by scene geometry index
};

// The B-rep face behind a unique part ID, unplaced (geometry coordinates); nullopt for a scene
// without B-rep, a level-of-detail geometry, or an ID that names no part.
std::optional<TopoDS_Face> partFace(const Scene& scene, uint32_t uniquePartId);

// An object's placement for Open CASCADE: rigid, or scaled alike on every axis (as CAD
// placements are). Applied to a shape with shape.Moved(location).
TopLoc_Location placement(const glm::dmat4& world);

} // namespace scene
