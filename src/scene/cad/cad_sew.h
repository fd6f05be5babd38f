// cad_sew.h - faces sewn along their common edges before meshing. An IGES file often holds
// faces that touch without sharing their edges; each face then samples its own copy of an
// edge, and where the copies' points differ, background shows through a closed model in
// pinholes along the seams (38 pixels of bearing.iges at 1280x720). Sewn faces share their
// edges, so the mesher samples each edge once for both faces. Some files leave gaps wider
// than their own resolution between faces that meet: hammer.iges (resolution 0.001) has one
// of 0.15 between two faces, which stayed two free edges and showed 2 pixels of background
// at 1280x720; those are closed by a second sewing within the gap tolerance.
#pragma once

#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Shape.hxx>

namespace scene {

// Sews the faces of `shape` that lie within `tolerance` of each other. On success `shape`
// is the sewn shape and `faces` its faces in the order of the faces they replace, so a part
// keeps its face number; where sewing would drop, split or merge a face both stay as they
// were and it returns false. Where free edges remain and `gapTolerance` is larger, the sewn
// shape is sewn again within it (kept only where that too keeps every face).
bool sewFaces(TopoDS_Shape& shape, TopTools_IndexedMapOfShape& faces, double tolerance,
              double gapTolerance = 0.0);

} // namespace scene
