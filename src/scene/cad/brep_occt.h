// brep_occt.h - BrepShapes's decoded shapes (brep_shapes.h), their bytes, and the conversions
// every B-rep query needs: a part's face, an object's placement as a TopLoc_Location. Internal
// to src/scene; holds Open CASCADE types.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <TopLoc_Location.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <glm/glm.hpp>

#include "scene/cad/brep_shapes.h"
#include "scene/scene.h"

namespace scene {

struct BrepShapes::Shape {
    TopoDS_Shape shape;             // null: no shape for this geometry
    std::vector<TopoDS_Face> faces; // by B-rep face number (Geometry::partFaces)
};

// Open CASCADE's binary B-rep format (BinTools, without triangulations) of `shape.shape`, then
// each face's position in the shape's TopExp::MapShapes face order (sewing leaves the faces in
// another order than the map's).
std::string encodeShape(const BrepShapes::Shape& shape);
// Throws std::runtime_error when the bytes do not hold what encodeShape wrote.
BrepShapes::Shape decodeShape(std::string_view bytes);
// Every geometry's shape, decoded (a null shape where it has none).
std::vector<BrepShapes::Shape> decodedShapes(const BrepShapes& shapes);
// A store of shapes in hand, each encoded (by geometry index; null shapes stay absent).
std::shared_ptr<const BrepShapes> encodedShapes(const std::vector<BrepShapes::Shape>& shapes);

// The B-rep face behind a unique part ID, unplaced (geometry coordinates); nullopt for a scene
// without B-rep, a level-of-detail geometry, or an ID that names no part or no face.
std::optional<TopoDS_Face> partFace(const Scene& scene, uint32_t uniquePartId);

// An object's placement for Open CASCADE: rigid, or scaled alike on every axis (as CAD
// placements are). Applied to a shape with shape.Moved(location).
TopLoc_Location placement(const glm::dmat4& world);

} // namespace scene
