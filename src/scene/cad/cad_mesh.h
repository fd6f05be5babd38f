// cad_mesh.h - from Open CASCADE triangulations to scene geometry, for the CAD loader only
// (this header, unlike cad_loader.h, speaks Open CASCADE): a face's triangles as one part, and
// levels of detail as coarser tessellations of the same faces.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <set>
#include <vector>

#include <IMeshTools_Parameters.hxx>
#include <Message_ProgressRange.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include "scene/cad/cad_shared_points.h"
#include "scene/lod.h"
#include "scene/scene.h"

namespace scene {

// Appends the triangles of `face` as the next part of scene.geometries.back(), whose vertices
// start at `geometryFirstVertex`; false when the face has none. With `shared` (one per
// geometry), its boundary vertices take the points earlier faces gave their edges, so that
// faces meeting at an edge meet at the same floats.
bool appendFace(Scene& scene, const TopoDS_Face& face, uint32_t geometryFirstVertex,
                SharedPoints* shared = nullptr);

// What one tessellation may take: its triangles, counted face by face as the mesher's
// threads finish them, and a flag another thread may set to stop it.
struct MeshBudget {
    uint64_t maxTriangles = 0;
    const std::atomic<bool>* cancel = nullptr;
    std::atomic<uint64_t> triangles{0};
    std::atomic<uint32_t> facesMeshed{0}; // faces counted, with triangles kept or new
    std::atomic<bool> over{false};
    // Faces (by TShape) the mesher is not given; they stay without triangles.
    std::set<const void*> skipped;
    bool stop() const { return over || (cancel && *cancel); }
};

// BRepMesh_IncrementalMesh(shape, parameters) with the faces' triangles counted into
// `budget`, those they already have first (dropped, and the faces meshed anew, where those
// alone pass the budget), each face's new ones as soon as it is meshed: once they
// pass budget.maxTriangles (or budget.cancel is set) no further face is begun, and `range`'s
// indicator should report a break (budget.stop()) so that Open CASCADE leaves the face it is in.
// The shape is then partly meshed; the caller throws it away.
void meshCounted(const TopoDS_Shape& shape, const IMeshTools_Parameters& parameters,
                 MeshBudget& budget, const Message_ProgressRange& range);

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
// triangulation. `progress` gets 0..1. The faces in `skipped` are not meshed.
void addCadLevels(Scene& scene, const TopoDS_Shape& all, const std::vector<CadShapeFaces>& shapes,
                  double deflection, double angularDeflection, uint32_t levels,
                  const LodOptions& lod, const std::set<const void*>& skipped,
                  const std::function<void(double)>& progress);

} // namespace scene
