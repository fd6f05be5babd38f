// cad_check.h - faces Open CASCADE's mesher should not be given. A damaged file can hold a face
// whose edges run far outside its surface (a trimming curve whose range was garbled from 7.85
// to 976.85 on a sphere, found by fuzz_cad): the mesher's Delaunay step then works on that
// polygon for minutes, on a thread nothing can stop, Cancel included.
#pragma once

#include <set>

#include <TopoDS_Shape.hxx>

namespace scene {

// The faces of `shape` (by TShape) with an edge whose curve on the face leaves the surface's
// parameter domain by more than its span along a direction that is not periodic: no valid
// face does that, since its edges bound it on the surface.
std::set<const void*> facesLeavingTheirSurface(const TopoDS_Shape& shape);

} // namespace scene
