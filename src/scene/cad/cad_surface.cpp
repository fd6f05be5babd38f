// cad_surface.cpp - surface type, exact area, plane, axis and radius of a B-rep face.
#include "scene/cad/cad_surface.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Pln.hxx>
#include <gp_Sphere.hxx>

#include <utility>

namespace scene {
namespace {

glm::dvec3 toGlm(const gp_XYZ& v) {
    return {v.X(), v.Y(), v.Z()};
}

SurfaceKind kindOf(GeomAbs_SurfaceType type) {
    static constexpr std::pair<GeomAbs_SurfaceType, SurfaceKind> kinds[] = {
        {GeomAbs_Plane, SurfaceKind::Plane},
        {GeomAbs_Cylinder, SurfaceKind::Cylinder},
        {GeomAbs_Cone, SurfaceKind::Cone},
        {GeomAbs_Sphere, SurfaceKind::Sphere},
        {GeomAbs_Torus, SurfaceKind::Torus},
        {GeomAbs_BSplineSurface, SurfaceKind::BSpline},
        {GeomAbs_BezierSurface, SurfaceKind::Bezier},
        {GeomAbs_SurfaceOfRevolution, SurfaceKind::Revolution},
        {GeomAbs_SurfaceOfExtrusion, SurfaceKind::Extrusion},
        {GeomAbs_OffsetSurface, SurfaceKind::Offset},
    };
    for (const auto& [occt, kind] : kinds)
        if (occt == type) return kind;
    return SurfaceKind::Other;
}

} // namespace

SurfaceInfo surfaceOf(const TopoDS_Face& face) {
    SurfaceInfo info;
    GProp_GProps props;
    BRepGProp::SurfaceProperties(face, props);
    info.area = props.Mass();
    const BRepAdaptor_Surface surface(face); // with the face's location
    info.kind = kindOf(surface.GetType());
    if (info.kind == SurfaceKind::Plane) {
        const gp_Pln plane = surface.Plane();
        glm::dvec3 normal = toGlm(plane.Axis().Direction().XYZ());
        // A reversed face looks the other way: its outward normal is the surface's negated.
        if (face.Orientation() == TopAbs_REVERSED) normal = -normal;
        info.normal = normal;
        info.d = glm::dot(normal, toGlm(plane.Location().XYZ()));
    } else if (info.kind == SurfaceKind::Cylinder) {
        const gp_Cylinder cylinder = surface.Cylinder();
        info.radius = cylinder.Radius();
        info.axisOrigin = toGlm(cylinder.Axis().Location().XYZ());
        info.axisDirection = toGlm(cylinder.Axis().Direction().XYZ());
    } else if (info.kind == SurfaceKind::Sphere) {
        const gp_Sphere sphere = surface.Sphere();
        info.radius = sphere.Radius();
        info.axisOrigin = toGlm(sphere.Location().XYZ());
    }
    return info;
}

} // namespace scene
