// brep_inspect.h - inspect.h's answers for CAD scenes, from Scene::brep through Open CASCADE
// (BRepExtrema_DistShapeShape, BRepGProp, BRepBndLib). Free of Open CASCADE types.
#pragma once

#include <optional>

#include "scene/inspect.h"
#include "scene/scene.h"

namespace scene {

// nullopt where a side names a part without a B-rep face or an edge its shape lacks.
std::optional<DistanceReport> brepDistance(const Scene& scene, const Thing& a, const Thing& b);

// nullopt where the object's geometry has no shape (the caller answers from triangles).
std::optional<SolidProperties> brepProperties(const Scene& scene, uint32_t object);

// The largest vertex tolerance (BRep_Tool::Tolerance: how far Open CASCADE lets a vertex
// stray from its edges' ends) among the first `shapes` solids with a shape, decoding only
// those; 0 without a B-rep.
double brepTolerance(const Scene& scene, uint32_t shapes = 8);

} // namespace scene
