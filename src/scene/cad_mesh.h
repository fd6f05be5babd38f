// cad_mesh.h - from Open CASCADE triangulations to scene geometry, for the CAD loader only
// (this header, unlike cad_loader.h, speaks Open CASCADE): a face's triangles as one part, and
// levels of detail as coarser tessellations of the same faces.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include "scene/lod.h"
#include "scene/scene.h"

namespace scene {

// Appends the triangles of `face` as the next part of scene.geometries.back(), whose vertices
// start at `geometryFirstVertex`; false when the face has none.
bool appendFace(Scene& scene, const TopoDS_Face& face, uint32_t geometryFirstVertex);

// A distinct shape's faces, and the full-detail geometry built from them.
struct CadShapeFaces {
    const TopTools_IndexedMapOfShape* faces = nullptr;
    uint32_t geometry = 0;
};

// Tessellates `all` again at 4^level times `deflection` (the angular bound relaxed with it,
// since the linear one bounds the distance from the surface) for levels 1 to levels - 1, and
// adds each shape's level as a geometry of its own (Geometry::levels) with the same parts. Its
// lodError is that deflection, or more where full detail's vertices lie further from the
// level's triangles of their face (measured) plus full detail's deflection. Faces share their
// edges' discretisation in one tessellation, so no crack opens between faces. A shape stops at a
// level where a face of its would have no triangles, where the level keeps more than
// `lod.keepAtMost` of the triangles of the one before, or where its levels together would
// take more than `lod.memory` of its full detail's bytes. `all` keeps the coarsest
// triangulation. `progress` gets 0..1.
void addCadLevels(Scene& scene, const TopoDS_Shape& all, const std::vector<CadShapeFaces>& shapes,
                  double deflection, double angularDeflection, uint32_t levels,
                  const LodOptions& lod, const std::function<void(double)>& progress);

} // namespace scene
