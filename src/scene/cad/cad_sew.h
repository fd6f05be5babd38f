// cad_sew.h - faces sewn along their common edges before meshing. An IGES file often holds
// faces that touch without sharing their edges; each face then samples its own copy of an
// edge, and where the copies' points differ, background shows through a closed model in
// pinholes along the seams (38 pixels of bearing.iges at 1280x720). Sewn faces share their
// edges, so the mesher samples each edge once for both faces.
#pragma once

#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Shape.hxx>

namespace scene {

// Sews the faces of `shape` that lie within `tolerance` of each other. On success `shape`
// is the sewn shape and `faces` its faces in the order of the faces they replace, so a part
// keeps its face number; where sewing would drop, split or merge a face both stay as they
// were and it returns false.
bool sewFaces(TopoDS_Shape& shape, TopTools_IndexedMapOfShape& faces, double tolerance);

} // namespace scene
