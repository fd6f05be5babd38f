// brep_inspect.cpp - exact distances and solid properties from the kept B-rep
// (brep_inspect.h): each side becomes its located faces (or edge) and Open CASCADE answers.
#include "scene/cad/brep_inspect.h"

#include <algorithm>
#include <cmath>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Iterator.hxx>

#include "scene/cad/brep_occt.h"

namespace scene {

namespace {

glm::dvec3 vec(const gp_XYZ& p) {
    return {p.X(), p.Y(), p.Z()};
}

// A side as Open CASCADE sees it, placed in the world: its faces in a compound, or its edge.
struct Located {
    TopoDS_Shape shape;
    bool single = false; // one face, or the edge: what may be a circle, cylinder or plane
};

std::optional<Located> locate(const Scene& scene, const Thing& thing) {
    if (thing.edge) {
        const auto ref = scene.locate(thing.edge->part);
        if (!ref) return std::nullopt;
        const Object& object = scene.objects[ref->object];
        if (!scene.brep->has(object.geometry)) return std::nullopt;
        TopTools_IndexedMapOfShape edges;
        TopExp::MapShapes(scene.brep->shape(object.geometry).shape, TopAbs_EDGE, edges);
        if (thing.edge->edge >= uint32_t(edges.Extent())) return std::nullopt;
        return Located{edges(int(thing.edge->edge) + 1).Moved(placement(object.world)), true};
    }
    if (thing.parts.empty()) return std::nullopt;
    TopoDS_Compound all;
    BRep_Builder builder;
    builder.MakeCompound(all);
    for (uint32_t id : thing.parts) {
        const auto face = partFace(scene, id);
        if (!face) return std::nullopt;
        builder.Add(all, face->Moved(placement(scene.objects[scene.locate(id)->object].world)));
    }
    if (thing.parts.size() == 1) {
        TopoDS_Iterator only(all);
        return Located{only.Value(), true};
    }
    return Located{all, false};
}

// What a single face or edge offers besides its points: a centre (circle, sphere, cylinder),
// an axis (circle, cylinder), an outward plane (planar face).
struct Feature {
    std::optional<glm::dvec3> centre, axis;
    std::optional<glm::dvec3> planePoint, planeNormal;
};

Feature featureOf(const Located& side) {
    Feature f;
    if (!side.single) return f;
    if (side.shape.ShapeType() == TopAbs_EDGE) {
        // The adaptor applies the edge's location: the circle is where the world has it.
        const BRepAdaptor_Curve curve(TopoDS::Edge(side.shape));
        if (curve.GetType() == GeomAbs_Circle) {
            const gp_Ax1 axis = curve.Circle().Axis();
            f.centre = vec(axis.Location().XYZ());
            f.axis = vec(axis.Direction().XYZ());
        }
        return f;
    }
    const TopoDS_Face& face = TopoDS::Face(side.shape);
    const BRepAdaptor_Surface surface(face);
    switch (surface.GetType()) {
    case GeomAbs_Cylinder: {
        // The centre: the face's own centre (of its area) brought onto the axis, midway along
        // a hole or a boss whatever the axis's origin.
        const gp_Ax1 axis = surface.Cylinder().Axis();
        GProp_GProps props;
        BRepGProp::SurfaceProperties(face, props);
        const glm::dvec3 origin = vec(axis.Location().XYZ()), d = vec(axis.Direction().XYZ());
        f.centre = origin + d * glm::dot(vec(props.CentreOfMass().XYZ()) - origin, d);
        f.axis = d;
        break;
    }
    case GeomAbs_Sphere:
        f.centre = vec(surface.Sphere().Location().XYZ());
        break;
    case GeomAbs_Plane: {
        const gp_Ax1 normal = surface.Plane().Axis();
        f.planePoint = vec(normal.Location().XYZ());
        // A reversed face looks the other way from its surface.
        const double sign = face.Orientation() == TopAbs_REVERSED ? -1.0 : 1.0;
        f.planeNormal = sign * vec(normal.Direction().XYZ());
        break;
    }
    default:
        break;
    }
    return f;
}

// Axes within this angle (radians) are parallel: their distance means something.
constexpr double kParallel = 1e-9;

void compareFeatures(const Feature& a, const Feature& b, DistanceReport& report) {
    if (a.centre && b.centre) report.centreDistance = glm::distance(*a.centre, *b.centre);
    if (a.axis && b.axis) {
        const double sine = glm::length(glm::cross(*a.axis, *b.axis));
        // Axes have no sense: the angle between lines, 0 to 90 degrees.
        report.axisAngleDegrees =
            glm::degrees(std::atan2(sine, std::abs(glm::dot(*a.axis, *b.axis))));
        if (sine < kParallel)
            report.axisDistance = glm::length(glm::cross(*b.centre - *a.centre, *a.axis));
    }
    auto toPlane = [&](const Feature& plane, const Feature& point) {
        if (plane.planeNormal && point.centre)
            report.pointToPlane = glm::dot(*point.centre - *plane.planePoint, *plane.planeNormal);
    };
    toPlane(a, b);
    toPlane(b, a);
}

std::optional<DistanceReport> exactDistance(const Scene& scene, const Thing& a, const Thing& b) {
    const auto la = locate(scene, a), lb = locate(scene, b);
    if (!la || !lb) return std::nullopt;
    BRepExtrema_DistShapeShape extrema(la->shape, lb->shape);
    if (!extrema.IsDone() || extrema.NbSolution() < 1) return std::nullopt;
    DistanceReport report;
    report.distance = extrema.Value();
    report.p0 = vec(extrema.PointOnShape1(1).XYZ());
    report.p1 = vec(extrema.PointOnShape2(1).XYZ());
    report.fromBrep = true;
    report.unit = scene.unit;
    compareFeatures(featureOf(*la), featureOf(*lb), report);
    return report;
}

SolidProperties exactProperties(const Scene& scene, uint32_t object) {
    const Object& o = scene.objects[object];
    const TopoDS_Shape shape = scene.brep->shape(o.geometry).shape.Moved(placement(o.world));
    SolidProperties p;
    p.object = object;
    p.unit = scene.unit;
    GProp_GProps surface;
    BRepGProp::SurfaceProperties(shape, surface);
    p.area = surface.Mass();
    // Closed: shells, each with every edge shared by two of its faces (seams aside).
    p.closed = false;
    for (TopExp_Explorer shell(shape, TopAbs_SHELL); shell.More(); shell.Next()) {
        p.closed = BRep_Tool::IsClosed(shell.Current());
        if (!p.closed) break;
    }
    if (p.closed) {
        GProp_GProps volume;
        BRepGProp::VolumeProperties(shape, volume);
        p.volume = std::abs(volume.Mass());
        p.center = vec(volume.CentreOfMass().XYZ());
    } else {
        p.center = vec(surface.CentreOfMass().XYZ());
    }
    // The exact box: from the surfaces, not the triangles nor the tolerances.
    Bnd_Box box;
    BRepBndLib::AddOptimal(shape, box, false, false);
    if (!box.IsVoid()) {
        double x0, y0, z0, x1, y1, z1;
        box.Get(x0, y0, z0, x1, y1, z1);
        p.bbox = {{x0, y0, z0}, {x1, y1, z1}};
    }
    return p;
}

} // namespace

// Open CASCADE throws Standard_Failure, no std::exception, where a shape defeats it (a
// degenerate surface, a curve it cannot evaluate): no answer then, and the caller goes on.
std::optional<DistanceReport> brepDistance(const Scene& scene, const Thing& a, const Thing& b) {
    if (!scene.brep) return std::nullopt;
    try {
        return exactDistance(scene, a, b);
    } catch (const Standard_Failure&) {
        return std::nullopt;
    }
}

std::optional<SolidProperties> brepProperties(const Scene& scene, uint32_t object) {
    if (!scene.brep || object >= scene.objects.size()) return std::nullopt;
    if (!scene.brep->has(scene.objects[object].geometry)) return std::nullopt;
    try {
        return exactProperties(scene, object);
    } catch (const Standard_Failure&) {
        return std::nullopt;
    }
}

double brepTolerance(const Scene& scene, uint32_t shapes) {
    double tolerance = 0.0;
    if (!scene.brep) return tolerance;
    for (uint32_t g = 0; g < scene.brep->geometryCount() && shapes > 0; ++g) {
        if (!scene.brep->has(g)) continue;
        --shapes;
        try {
            for (TopExp_Explorer v(scene.brep->shape(g).shape, TopAbs_VERTEX); v.More(); v.Next())
                tolerance = std::max(tolerance, BRep_Tool::Tolerance(TopoDS::Vertex(v.Current())));
        } catch (const std::exception&) { // bytes that cannot be read back: the others say it
        } catch (const Standard_Failure&) {
        }
    }
    return tolerance;
}

} // namespace scene
