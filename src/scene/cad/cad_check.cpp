// cad_check.cpp - faces whose edges leave their surface (cad_check.h).
#include "scene/cad/cad_check.h"

#include <cmath>

#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Surface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

namespace scene {

namespace {

// Whether `value` lies within [low, high] widened by their span on each side; an infinite
// bound (planes, extrusions) never excludes.
bool near(double value, double low, double high) {
    if (!std::isfinite(value)) return false;
    if (!std::isfinite(low) || !std::isfinite(high)) return true;
    const double span = high - low;
    return value >= low - span && value <= high + span;
}

bool edgesStayOn(const TopoDS_Face& face) {
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
    if (surface.IsNull()) return true;
    double u1, u2, v1, v2;
    surface->Bounds(u1, u2, v1, v2);
    const bool uPeriodic = surface->IsUPeriodic(), vPeriodic = surface->IsVPeriodic();
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
        double first = 0.0, last = 0.0;
        const Handle(Geom2d_Curve) curve =
            BRep_Tool::CurveOnSurface(TopoDS::Edge(e.Current()), face, first, last);
        if (curve.IsNull()) continue;
        for (const double t : {first, 0.5 * (first + last), last}) {
            if (!std::isfinite(t)) return false;
            const gp_Pnt2d p = curve->Value(t);
            if ((!uPeriodic && !near(p.X(), u1, u2)) || (!vPeriodic && !near(p.Y(), v1, v2)))
                return false;
        }
    }
    return true;
}

} // namespace

std::set<const void*> facesLeavingTheirSurface(const TopoDS_Shape& shape) {
    std::set<const void*> faces;
    for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next())
        if (!edgesStayOn(TopoDS::Face(e.Current()))) faces.insert(e.Current().TShape().get());
    return faces;
}

} // namespace scene
