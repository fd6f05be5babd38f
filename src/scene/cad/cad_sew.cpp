// cad_sew.cpp - sewing a shape's faces, keeping their order (cad_sew.h).
#include "scene/cad/cad_sew.h"

#include <BRepBuilderAPI_Sewing.hxx>
#include <TopExp.hxx>

namespace scene {

namespace {

// One sewing of `shape` at `tolerance`: true, with `shape`, `faces` and `freeEdges` replaced,
// when every face comes out as one face of its own.
bool sewOnce(TopoDS_Shape& shape, TopTools_IndexedMapOfShape& faces, double tolerance,
             int& freeEdges) {
    BRepBuilderAPI_Sewing sewing(tolerance);
    sewing.Add(shape);
    sewing.Perform();
    const TopoDS_Shape sewn = sewing.SewedShape();
    if (sewn.IsNull()) return false;
    TopTools_IndexedMapOfShape replaced;
    for (int f = 1; f <= faces.Extent(); ++f) {
        const TopoDS_Shape face = sewing.ModifiedSubShape(faces(f));
        if (face.IsNull() || face.ShapeType() != TopAbs_FACE || replaced.Add(face) != f)
            return false;
    }
    TopTools_IndexedMapOfShape all;
    TopExp::MapShapes(sewn, TopAbs_FACE, all);
    if (all.Extent() != replaced.Extent()) return false;
    for (int f = 1; f <= all.Extent(); ++f)
        if (!replaced.Contains(all(f))) return false;
    shape = sewn;
    faces = replaced;
    freeEdges = sewing.NbFreeEdges();
    return true;
}

} // namespace

bool sewFaces(TopoDS_Shape& shape, TopTools_IndexedMapOfShape& faces, double tolerance,
              double gapTolerance) {
    if (faces.Extent() < 2 || !(tolerance > 0.0)) return false;
    int freeEdges = 0;
    if (!sewOnce(shape, faces, tolerance, freeEdges)) return false;
    // The edges paired at the file's resolution stay paired; only those left free are
    // candidates now, so a wider tolerance cannot pull apart what matched exactly.
    if (freeEdges > 0 && gapTolerance > tolerance) sewOnce(shape, faces, gapTolerance, freeEdges);
    return true;
}

} // namespace scene
