// test_edge_info.cpp - what --edge-info and the viewer's edge hover say of a B-rep edge
// (scene/edge_info.h): on a plate with a hole built here (40 x 30 x 10, hole of diameter 10
// through it at 20,15), the hole's circles and the plate's straight edges with their known
// sizes, and lengths as GCPnts_AbscissaPoint gives them on the file's own shape; on an
// occt-misc file, every face's edges against Open CASCADE's curves; the edge nearest a
// pixel under a camera looking down on the plate.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>
#include <unistd.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Geom_Circle.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include "cad_test_parts.h"
#include "scene/cad/brep_occt.h"
#include "scene/cad/cad_loader.h"
#include "scene/edge_info.h"
#include "test_data.h"

namespace {

namespace fs = std::filesystem;
using namespace scene;
constexpr double pi = std::numbers::pi;

struct Plate {
    Scene scene;
    TopoDS_Shape file; // the shape as the file holds it, read back here
};

Plate plateWithHole() {
    const fs::path path = cadtest::writeBoxWithHole("edge_info", 40.0, 30.0, 10.0, 5.0);
    EXPECT_FALSE(path.empty());
    Plate plate;
    plate.scene = loadCad(path.string(), {}).scene;
    BRep_Builder builder;
    EXPECT_TRUE(BRepTools::Read(plate.file, path.c_str(), builder));
    fs::remove(path);
    return plate;
}

// Every edge of every face of object 0, once each.
std::vector<EdgeReport> allEdges(const Scene& s) {
    std::set<uint32_t> seen;
    std::vector<EdgeReport> reports;
    for (uint32_t p = 0; p < s.geometries[s.objects[0].geometry].partCount; ++p)
        for (const EdgeRef& ref : faceEdges(s, s.objects[0].uniquePartOffset + p)) {
            EXPECT_EQ(ref.part, s.objects[0].uniquePartOffset + p);
            if (!seen.insert(ref.edge).second) continue;
            const auto report = edgeReport(s, ref);
            EXPECT_TRUE(report.has_value()) << "edge " << ref.edge;
            if (report) reports.push_back(*report);
        }
    return reports;
}

} // namespace

TEST(EdgeInfo, APlateWithAHoleHasItsKnownCirclesAndLines) {
    const Plate plate = plateWithHole();
    const Scene& s = plate.scene;
    ASSERT_EQ(s.objects.size(), 1u);
    TopTools_IndexedMapOfShape fileEdges;
    TopExp::MapShapes(plate.file, TopAbs_EDGE, fileEdges);
    const std::vector<EdgeReport> edges = allEdges(s);
    // 12 of the box, the hole's 2 circles and its cylinder's seam.
    ASSERT_EQ(edges.size(), 15u);
    ASSERT_EQ(fileEdges.Extent(), 15);
    int circles = 0, seams = 0;
    std::map<int, int> straight; // length: count
    for (const EdgeReport& e : edges) {
        SCOPED_TRACE("edge " + std::to_string(e.ref.edge));
        const BRepAdaptor_Curve own(TopoDS::Edge(fileEdges(int(e.ref.edge) + 1)));
        EXPECT_NEAR(e.length, GCPnts_AbscissaPoint::Length(own), 1e-9);
        EXPECT_GE(e.points.size(), 2u);
        if (e.kind == CurveKind::Circle) {
            ++circles;
            EXPECT_NEAR(e.radius, 5.0, 1e-9);
            EXPECT_NEAR(e.length, 2 * pi * 5, 1e-9);
            EXPECT_TRUE(e.closed);
            EXPECT_NEAR(e.center.x, 20.0, 1e-9);
            EXPECT_NEAR(e.center.y, 15.0, 1e-9);
            EXPECT_TRUE(std::abs(e.center.z) < 1e-9 || std::abs(e.center.z - 10) < 1e-9);
            EXPECT_NEAR(std::abs(e.axis.z), 1.0, 1e-12);
            // Enough points for a smooth circle, every one on it.
            EXPECT_GE(e.points.size(), 32u);
            for (const glm::dvec3& p : e.points)
                EXPECT_NEAR(glm::length(glm::dvec2(p) - glm::dvec2(20, 15)), 5.0, 1e-9);
            const std::string json = edgeReportJson(e);
            EXPECT_NE(json.find("\"curve\":\"circle\""), std::string::npos) << json;
            EXPECT_NE(json.find("\"radius\":5,\"diameter\":10,"), std::string::npos) << json;
            EXPECT_EQ(describeEdge(e).rfind("circle \u00d8 10 (r 5), length 31.4159", 0), 0u)
                << describeEdge(e);
            continue;
        }
        ASSERT_EQ(e.kind, CurveKind::Line);
        EXPECT_FALSE(e.closed);
        // Its direction runs from its start to its end, along an axis of the plate.
        EXPECT_NEAR(glm::length(e.end - e.start), e.length, 1e-9);
        EXPECT_NEAR(glm::length(e.direction - (e.end - e.start) / e.length), 0.0, 1e-12);
        const glm::dvec3 along = glm::abs(e.direction);
        const double expected = along.x > 0.5 ? 40.0 : along.y > 0.5 ? 30.0 : 10.0;
        EXPECT_NEAR(e.length, expected, 1e-9);
        // The seam of the hole runs up its side at radius 5.
        if (glm::length(glm::dvec2(e.start) - glm::dvec2(20, 15)) < 5.0 + 1e-9) ++seams;
        ++straight[int(std::lround(e.length))];
        EXPECT_NE(edgeReportJson(e).find("\"direction\":"), std::string::npos);
        EXPECT_NE(describeEdge(e).find(", direction ("), std::string::npos) << describeEdge(e);
    }
    EXPECT_EQ(circles, 2);
    EXPECT_EQ(seams, 1);
    EXPECT_EQ(straight[40], 4);
    EXPECT_EQ(straight[30], 4);
    EXPECT_EQ(straight[10], 5); // four corners and the seam
}

// An edge is named by its shape's edge index: the faces either side of it give the same one.
// (Edge reports name the part they were asked through; part 0 serves for any edge here.)
TEST(EdgeInfo, AnEdgeSharedByTwoFacesIsTheSameEdgeFromEitherSide) {
    const Plate plate = plateWithHole();
    const Scene& s = plate.scene;
    std::map<uint32_t, int> faces; // edge: faces it bounds
    for (uint32_t p = 0; p < s.uniquePartCount(); ++p)
        for (const EdgeRef& ref : faceEdges(s, p)) ++faces[ref.edge];
    ASSERT_EQ(faces.size(), 15u);
    // The hole's seam has the cylinder on both sides: one face.
    for (const auto& [edge, count] : faces) {
        const auto e = edgeReport(s, {0, edge});
        ASSERT_TRUE(e);
        const bool seam = glm::length(glm::dvec2(e->start) - glm::dvec2(20, 15)) < 5.0 + 1e-9 &&
                          e->kind == CurveKind::Line;
        EXPECT_EQ(count, seam ? 1 : 2) << "edge " << edge;
    }
    EXPECT_FALSE(edgeReport(s, {0, 15}).has_value()); // past the last edge
}

// Under a camera looking straight down on the plate (x right, y down the image), a cursor two
// pixels inside the top face next to an edge finds that edge; the face's middle finds none.
TEST(EdgeInfo, TheNearestEdgeOnScreenIsTheOneNextToTheCursor) {
    const Plate plate = plateWithHole();
    const Scene& s = plate.scene;
    uint32_t top = ~0u;
    for (uint32_t p = 0; p < s.uniquePartCount(); ++p)
        for (const EdgeRef& ref : faceEdges(s, p)) {
            const auto e = edgeReport(s, ref);
            if (e && e->kind == CurveKind::Circle && e->center.z > 5.0 &&
                faceEdges(s, p).size() == 5)
                top = p;
        }
    ASSERT_NE(top, ~0u);
    // World x 0..40 to pixels 0..400, y 0..30 to 0..300: 10 pixels a unit.
    glm::dmat4 viewProj(1.0);
    viewProj[0][0] = 2.0 / 40.0;
    viewProj[1][1] = 2.0 / 30.0;
    viewProj[3] = glm::dvec4(-1.0, -1.0, 0.0, 1.0);
    const glm::dvec2 size(400, 300);
    auto nearest = [&](glm::dvec2 cursor) {
        const auto ref = nearestEdge(s, top, viewProj, size, cursor, 4.0);
        return ref ? edgeReport(s, *ref) : std::nullopt;
    };
    const auto left = nearest({2.0, 150.0}); // the edge x = 0 of the top face
    ASSERT_TRUE(left);
    EXPECT_EQ(left->kind, CurveKind::Line);
    EXPECT_NEAR(left->start.x, 0.0, 1e-9);
    EXPECT_NEAR(left->start.z, 10.0, 1e-9);
    EXPECT_NEAR(std::abs(left->direction.y), 1.0, 1e-12);
    const auto hole = nearest({200.0 + 53.0, 150.0}); // 0.3 units outside the hole's rim
    ASSERT_TRUE(hole);
    EXPECT_EQ(hole->kind, CurveKind::Circle);
    EXPECT_NEAR(hole->center.z, 10.0, 1e-9);
    EXPECT_FALSE(nearest({100.0, 150.0})); // 10 units from every edge
    EXPECT_FALSE(nearest({5.0, 150.0}));   // 5 pixels: beyond 4
}

// occt-misc's pump nut: every edge of every face as Open CASCADE gives it from the edge's own
// 3D curve (kind, length between its parameters, a circle's radius), placed.
TEST(EdgeInfo, AnOcctFilesEdgesAreOpenCascadesOwn) {
    const Scene s =
        loadCad(testing_support::requiredData("/usr/share/opencascade/data/occ/Pump_Nut.brep"), {})
            .scene;
    ASSERT_TRUE(s.brep);
    int circles = 0, checked = 0;
    for (uint32_t part = 0; part < s.uniquePartCount(); ++part) {
        const uint32_t object = s.locate(part)->object;
        const TopoDS_Shape& shape = s.brep->shape(s.objects[object].geometry).shape;
        TopTools_IndexedMapOfShape edges;
        TopExp::MapShapes(shape, TopAbs_EDGE, edges);
        const TopLoc_Location where = placement(glm::dmat4(s.objects[object].world));
        for (const EdgeRef& ref : faceEdges(s, part)) {
            const auto e = edgeReport(s, ref);
            ASSERT_TRUE(e);
            const TopoDS_Edge edge = TopoDS::Edge(edges(int(ref.edge) + 1).Moved(where));
            double first = 0, last = 0;
            const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
            ASSERT_FALSE(curve.IsNull());
            const double length =
                GCPnts_AbscissaPoint::Length(GeomAdaptor_Curve(curve), first, last);
            EXPECT_NEAR(e->length, length, 1e-9 * std::max(1.0, length)) << "edge " << ref.edge;
            Handle(Geom_Curve) basis = curve;
            if (auto trimmed = Handle(Geom_TrimmedCurve)::DownCast(basis))
                basis = trimmed->BasisCurve();
            if (auto circle = Handle(Geom_Circle)::DownCast(basis)) {
                ++circles;
                EXPECT_EQ(e->kind, CurveKind::Circle) << "edge " << ref.edge;
                EXPECT_NEAR(e->radius, circle->Radius(), 1e-9 * circle->Radius());
            }
            ++checked;
        }
    }
    EXPECT_GT(checked, 0);
    EXPECT_GT(circles, 0);
}
