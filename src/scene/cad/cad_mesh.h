// cad_mesh.h - from Open CASCADE triangulations to scene geometry, for the CAD loader only
// (this header, unlike cad_loader.h, speaks Open CASCADE): a face's triangles as one part, and
// a tessellation counted against a budget.
#pragma once

#include <atomic>
#include <cstdint>
#include <set>
#include <vector>

#include <IMeshTools_Parameters.hxx>
#include <Message_ProgressRange.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include "scene/cad/cad_shared_points.h"
#include "scene/scene.h"

namespace scene {

// Appends the triangles of `face` as the next part of scene.geometries.back(), whose vertices
// start at `geometryFirstVertex`; false when the face has none. With `shared` (one per
// geometry), its boundary vertices take the points earlier faces gave their edges, so that
// faces meeting at an edge meet at the same floats.
bool appendFace(Scene& scene, const TopoDS_Face& face, uint32_t geometryFirstVertex,
                SharedPoints* shared = nullptr);

// Appends a part with no triangles to scene.geometries.back(): a face that did not triangulate
// keeps its part and unique ID.
void appendEmptyPart(Scene& scene);

// What one tessellation may take: its triangles, counted face by face as the mesher's
// threads finish them, and a flag another thread may set to stop it.
struct MeshBudget {
    uint64_t maxTriangles = 0;
    const std::atomic<bool>* cancel = nullptr;
    std::atomic<uint64_t> triangles{0};
    std::atomic<uint32_t> facesMeshed{0}; // faces counted, with triangles kept or new
    std::atomic<bool> over{false};
    // A face's meshing ran out of memory (Open CASCADE would only mark the face failed).
    std::atomic<bool> outOfMemory{false};
    // Faces (by TShape) the mesher is not given; they stay without triangles.
    std::set<const void*> skipped;
    bool stop() const { return over || outOfMemory || (cancel && *cancel); }
};

// BRepMesh_IncrementalMesh(shape, parameters) with the faces' triangles counted into
// `budget`, those they already have first (dropped, and the faces meshed anew, where those
// alone pass the budget), each face's new ones as soon as it is meshed: once they
// pass budget.maxTriangles (or budget.cancel is set) no further face is begun, and `range`'s
// indicator should report a break (budget.stop()) so that Open CASCADE leaves the face it is in.
// The shape is then partly meshed; the caller throws it away. A face that ran out of memory
// on any of the mesher's threads stops it too, and std::bad_alloc is thrown here.
void meshCounted(const TopoDS_Shape& shape, const IMeshTools_Parameters& parameters,
                 MeshBudget& budget, const Message_ProgressRange& range);

} // namespace scene
