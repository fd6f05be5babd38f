// cad_shared_points.cpp - boundary nodes of faces moved onto their edges' shared points
// (cad_shared_points.h).
#include "scene/cad/cad_shared_points.h"

#include <algorithm>

#include <BRep_Tool.hxx>
#include <Poly_PolygonOnTriangulation.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>

namespace scene {

namespace {

double squared(glm::vec3 a, glm::vec3 b) {
    const glm::dvec3 d = glm::dvec3(a) - glm::dvec3(b);
    return glm::dot(d, d);
}

// Whether `a` and `b` are one point: within the B-rep's `tolerance`, or a few floats apart
// (a float resolves 2^-24 of a coordinate, coarser than many tolerances far from 0).
bool samePoint(glm::vec3 a, glm::vec3 b, double tolerance) {
    const glm::vec3 size = glm::abs(a);
    const double within = tolerance + 1e-6 * double(std::max({size.x, size.y, size.z}));
    return squared(a, b) <= within * within;
}

glm::vec3 pointOf(const TopoDS_Vertex& v) {
    const gp_Pnt p = BRep_Tool::Pnt(v);
    return glm::vec3(float(p.X()), float(p.Y()), float(p.Z()));
}

} // namespace

std::vector<glm::vec3>* SharedPoints::find(const TopoDS_Shape& shape) {
    const Standard_Integer* i = index_.Seek(shape);
    return i ? &points_[size_t(*i)] : nullptr;
}

void SharedPoints::add(const TopoDS_Shape& shape, std::vector<glm::vec3> points) {
    index_.Bind(shape, Standard_Integer(points_.size()));
    points_.push_back(std::move(points));
}

void SharedPoints::share(const TopoDS_Face& face, const Handle(Poly_Triangulation) & triangulation,
                         const TopLoc_Location& location, Vertex* vertices) {
    const Standard_Integer nodes = triangulation->NbNodes();
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
        const Handle(Poly_PolygonOnTriangulation) polygon =
            BRep_Tool::PolygonOnTriangulation(edge, triangulation, location);
        if (polygon.IsNull() || polygon->NbNodes() < 2) continue;
        const Standard_Integer count = polygon->NbNodes();
        auto node = [&](Standard_Integer k) -> Vertex* { // k from 1, along the polygon
            const Standard_Integer n = polygon->Node(k);
            return n >= 1 && n <= nodes ? &vertices[n - 1] : nullptr;
        };
        // The polygon's ends are the edge's vertices, paired the way that puts them nearer
        // (an edge shorter than its tolerance has both ends within it of either vertex).
        TopoDS_Vertex first, last;
        TopExp::Vertices(edge, first, last);
        Vertex* ends[2] = {node(1), node(count)};
        if (!ends[0] || !ends[1] || first.IsNull() || last.IsNull()) continue;
        const glm::vec3 a = pointOf(first), b = pointOf(last);
        if (squared(ends[0]->position, b) + squared(ends[1]->position, a) <
            squared(ends[0]->position, a) + squared(ends[1]->position, b))
            std::swap(first, last);
        for (int k = 0; k < 2; ++k) {
            const TopoDS_Vertex& corner = k == 0 ? first : last;
            Vertex* v = ends[k];
            if (!samePoint(v->position, pointOf(corner), BRep_Tool::Tolerance(corner))) continue;
            if (std::vector<glm::vec3>* kept = find(corner))
                v->position = kept->front();
            else
                add(corner, {v->position});
        }
        // The nodes between, against the edge's points in either direction (a seam's two
        // polygons, or another face's, may run the other way).
        std::vector<glm::vec3> inner;
        for (Standard_Integer k = 2; k < count; ++k)
            if (const Vertex* v = node(k)) inner.push_back(v->position);
        if (inner.size() != size_t(count - 2) || inner.empty()) continue;
        std::vector<glm::vec3>* kept = find(edge);
        if (!kept) {
            add(edge, std::move(inner));
            continue;
        }
        if (kept->size() != inner.size()) continue;
        const bool reversed =
            squared(inner.front(), kept->back()) < squared(inner.front(), kept->front());
        const double tolerance = BRep_Tool::Tolerance(edge);
        for (size_t i = 0; i < inner.size(); ++i) {
            const glm::vec3 to = (*kept)[reversed ? inner.size() - 1 - i : i];
            if (samePoint(inner[i], to, tolerance)) node(Standard_Integer(i) + 2)->position = to;
        }
    }
}

} // namespace scene
