// edge_info.cpp - a CAD part's B-rep edges, measured by Open CASCADE on the placed edge, and
// the edge drawn nearest a pixel (edge_info.h).
#include "scene/edge_info.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>

#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GCPnts_TangentialDeflection.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>

#include "scene/cad/brep_occt.h"
#include "util/json_writer.h"

namespace scene {

const char* curveName(CurveKind kind) {
    static constexpr const char* names[] = {"line", "circle", "ellipse", "bspline", "other"};
    return names[size_t(kind)];
}

namespace {

// Drawing: a turn of at most this many radians between polyline points (about 63 points on a
// full circle, smooth at any size on screen), and a chord at most this share of the edge's
// length away from the curve (flat splines).
constexpr double polylineAngle = 0.1;
constexpr double polylineSag = 1e-3;

// The edges of one geometry's shape in TopExp::MapShapes order: EdgeRef::edge indexes it.
// Kept for the last geometry asked (hovering asks for the same part move after move); the
// weak pointer tells a reloaded scene's shapes from the ones mapped. The lock guards the
// rebuild, but the map handed out is the kept one: edge queries run on one thread at a time
// (the viewer's main thread, headless's), as they do now.
struct EdgeMap {
    std::weak_ptr<const BrepShapes> shapes;
    uint32_t geometry = 0;
    TopTools_IndexedMapOfShape edges;
};

const TopTools_IndexedMapOfShape* edgeMap(const Scene& scene, uint32_t geometry) {
    static std::mutex lock;
    static EdgeMap kept;
    if (!scene.brep || !scene.brep->has(geometry)) return nullptr;
    std::lock_guard guard(lock);
    if (kept.shapes.lock() != scene.brep || kept.geometry != geometry) {
        kept.edges.Clear();
        TopExp::MapShapes(scene.brep->shape(geometry).shape, TopAbs_EDGE, kept.edges);
        kept.shapes = scene.brep;
        kept.geometry = geometry;
    }
    return &kept.edges;
}

glm::dvec3 point(const gp_Pnt& p) {
    return {p.X(), p.Y(), p.Z()};
}

glm::dvec3 direction(const gp_Dir& d) {
    return {d.X(), d.Y(), d.Z()};
}

CurveKind kindOf(GeomAbs_CurveType type) {
    switch (type) {
    case GeomAbs_Line:
        return CurveKind::Line;
    case GeomAbs_Circle:
        return CurveKind::Circle;
    case GeomAbs_Ellipse:
        return CurveKind::Ellipse;
    case GeomAbs_BSplineCurve:
        return CurveKind::BSpline;
    default:
        return CurveKind::Other;
    }
}

std::vector<glm::dvec3> polyline(const BRepAdaptor_Curve& curve, CurveKind kind, double length) {
    const double first = curve.FirstParameter(), last = curve.LastParameter();
    if (kind == CurveKind::Line) return {point(curve.Value(first)), point(curve.Value(last))};
    // Open CASCADE refuses a sag of 0 (an edge of no length): a floor keeps it positive.
    GCPnts_TangentialDeflection sampler(curve, polylineAngle, std::max(polylineSag * length, 1e-12),
                                        2);
    std::vector<glm::dvec3> points;
    for (int i = 1; i <= sampler.NbPoints(); ++i) points.push_back(point(sampler.Value(i)));
    if (points.size() < 2) points = {point(curve.Value(first)), point(curve.Value(last))};
    return points;
}

// What edgeReport says of the placed edge; Open CASCADE may throw on a broken curve.
EdgeReport measured(const TopoDS_Edge& edge, EdgeRef ref, uint32_t object, const LengthUnit& unit) {
    const BRepAdaptor_Curve curve(edge);
    EdgeReport report;
    report.ref = ref;
    report.object = object;
    report.unit = unit;
    report.kind = kindOf(curve.GetType());
    report.length = GCPnts_AbscissaPoint::Length(curve);
    report.start = point(curve.Value(curve.FirstParameter()));
    report.end = point(curve.Value(curve.LastParameter()));
    TopoDS_Vertex first, last;
    TopExp::Vertices(edge, first, last);
    report.closed = !first.IsNull() && first.IsSame(last);
    if (report.kind == CurveKind::Line) report.direction = direction(curve.Line().Direction());
    if (report.kind == CurveKind::Circle) {
        const gp_Circ circle = curve.Circle();
        report.radius = circle.Radius();
        report.center = point(circle.Location());
        report.axis = direction(circle.Axis().Direction());
    }
    if (report.kind == CurveKind::Ellipse) {
        report.center = point(curve.Ellipse().Location());
        report.axis = direction(curve.Ellipse().Axis().Direction());
    }
    report.points = polyline(curve, report.kind, report.length);
    return report;
}

// Distance from `p` to the segment a-b, in pixels.
double segmentDistance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double span = glm::dot(ab, ab);
    const double t = span > 0.0 ? glm::clamp(glm::dot(p - a, ab) / span, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

} // namespace

std::vector<EdgeRef> faceEdges(const Scene& scene, uint32_t part) {
    const auto face = partFace(scene, part);
    if (!face) return {};
    const uint32_t geometry = scene.objects[scene.locate(part)->object].geometry;
    const TopTools_IndexedMapOfShape* edges = edgeMap(scene, geometry);
    if (!edges) return {};
    // A face's own map: a seam (a cylinder's) appears twice in the face, once here.
    TopTools_IndexedMapOfShape own;
    TopExp::MapShapes(*face, TopAbs_EDGE, own);
    std::vector<EdgeRef> refs;
    for (int i = 1; i <= own.Extent(); ++i) {
        const TopoDS_Edge& edge = TopoDS::Edge(own(i));
        // A degenerated edge (a cone's apex, a sphere's pole) is a point: nothing to measure.
        if (BRep_Tool::Degenerated(edge)) continue;
        const int index = edges->FindIndex(edge);
        if (index > 0) refs.push_back({part, uint32_t(index - 1)});
    }
    return refs;
}

std::optional<EdgeReport> edgeReport(const Scene& scene, EdgeRef ref) {
    const auto located = scene.locate(ref.part);
    if (!located) return std::nullopt;
    const Object& object = scene.objects[located->object];
    const TopTools_IndexedMapOfShape* edges = edgeMap(scene, object.geometry);
    if (!edges || ref.edge >= uint32_t(edges->Extent())) return std::nullopt;
    const TopoDS_Edge unplaced = TopoDS::Edge(edges->FindKey(int(ref.edge) + 1));
    if (BRep_Tool::Degenerated(unplaced) || !BRep_Tool::IsGeometric(unplaced)) return std::nullopt;
    const TopoDS_Edge edge = TopoDS::Edge(unplaced.Moved(placement(glm::dmat4(object.world))));

    // A broken curve makes Open CASCADE throw: that edge has no report, and the app goes on.
    try {
        EdgeReport report = measured(edge, ref, located->object, scene.unit);
        report.precision = scene.precision;
        return report;
    } catch (const Standard_Failure&) {
        return std::nullopt;
    }
}

std::optional<EdgeRef> nearestEdge(const Scene& scene, uint32_t part, const glm::dmat4& viewProj,
                                   glm::dvec2 size, glm::dvec2 cursor, double maxPixels) {
    // The polylines of the last part asked, placed: hovering asks again at every mouse move.
    static std::mutex lock;
    static std::weak_ptr<const BrepShapes> keptShapes;
    static uint32_t keptPart = 0;
    static std::vector<EdgeReport> kept;
    std::lock_guard guard(lock);
    if (!scene.brep) return std::nullopt;
    if (keptShapes.lock() != scene.brep || keptPart != part) {
        kept.clear();
        for (const EdgeRef& ref : faceEdges(scene, part))
            if (auto report = edgeReport(scene, ref)) kept.push_back(std::move(*report));
        keptShapes = scene.brep;
        keptPart = part;
    }
    auto toPixels = [&](glm::dvec3 p, glm::dvec2& out) {
        const glm::dvec4 clip = viewProj * glm::dvec4(p, 1.0);
        if (clip.w <= 0.0) return false; // behind the eye (perspective)
        out = (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * size;
        return true;
    };
    std::optional<EdgeRef> best;
    double bestDistance = maxPixels;
    for (const EdgeReport& edge : kept) {
        glm::dvec2 previous{0.0};
        bool havePrevious = false;
        for (const glm::dvec3& p : edge.points) {
            glm::dvec2 here;
            const bool visible = toPixels(p, here);
            if (visible && havePrevious) {
                const double d = segmentDistance(cursor, previous, here);
                if (d <= bestDistance) {
                    bestDistance = d;
                    best = edge.ref;
                }
            }
            previous = here;
            havePrevious = visible;
        }
    }
    return best;
}

void edgeReportMembers(util::JsonWriter& json, const EdgeReport& r) {
    json.member("part", r.ref.part)
        .member("object", r.object)
        .member("edge", r.ref.edge)
        .member("curve", curveName(r.kind))
        .member("length", r.length);
    if (r.kind == CurveKind::Circle)
        json.member("radius", r.radius)
            .member("diameter", 2.0 * r.radius)
            .member("center", r.center)
            .member("axis", r.axis);
    if (r.kind == CurveKind::Line) json.member("direction", r.direction);
    json.member("start", r.start).member("end", r.end).member("closed", r.closed);
    unitMember(json, r.unit);
}

std::string edgeReportJson(const EdgeReport& r) {
    util::JsonWriter json;
    json.beginObject();
    edgeReportMembers(json, r);
    return json.endObject().text();
}

std::string describeEdge(const EdgeReport& r) {
    // The unit once, on the line's first length (units.h).
    const LengthUnit none{};
    std::string line = curveName(r.kind);
    if (r.kind == CurveKind::Circle)
        line += " Ø " + formatLength(2.0 * r.radius, r.unit, r.precision) + " (r " +
                lengthText(r.radius, r.precision) + ")";
    line += ", length " +
            formatLength(r.length, r.kind == CurveKind::Circle ? none : r.unit, r.precision);
    if (r.kind == CurveKind::Line) line += ", direction " + directionText(r.direction);
    return line;
}

} // namespace scene
