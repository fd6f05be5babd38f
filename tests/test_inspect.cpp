// test_inspect.cpp - distances and properties (scene/inspect.h): on plates built here with
// known dimensions (a 100 x 60 x 10 plate with holes of diameter 10 and 16, 50 apart, and a
// second plate 7.5 above it) the gap, the holes' wall between them, their centre and axis
// distances and angle, point-to-plane distances, volumes, areas and centres of mass, also
// after the tessellation cache gave the scene back; on an occt-misc file, the answers Open
// CASCADE gives on the file's own shapes; on a mesh scene, the distance of two boxes.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <limits>
#include <numbers>
#include <regex>
#include <unistd.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <glm/gtc/matrix_transform.hpp>
#include <gp_Ax2.hxx>

#include "cad_test_parts.h"
#include "closed_cad_files.h"
#include "scene/cad/brep_occt.h"
#include "scene/cad/cad_cache.h"
#include "scene/copies.h"
#include "scene/face_info.h"
#include "scene/inspect.h"
#include "scene/mesh_builder.h"
#include "scene/mesh_inspect.h"
#include "test_data.h"

namespace {

namespace fs = std::filesystem;
using namespace scene;

constexpr double pi = std::numbers::pi;
constexpr double kR1 = 5.0, kR2 = 8.0, kSpacing = 50.0, kGap = 7.5;

// The plates as a BREP file in a folder of the test's own.
fs::path writePlates(const fs::path& folder) {
    const TopoDS_Shape plate = BRepPrimAPI_MakeBox(100.0, 60.0, 10.0).Shape();
    auto hole = [](double x, double r) {
        return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, 30, -1), gp_Dir(0, 0, 1)), r, 12.0)
            .Shape();
    };
    const TopoDS_Shape one = BRepAlgoAPI_Cut(plate, hole(25.0, kR1)).Shape();
    const TopoDS_Shape holed = BRepAlgoAPI_Cut(one, hole(25.0 + kSpacing, kR2)).Shape();
    const TopoDS_Shape above =
        BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 10.0 + kGap), 100.0, 60.0, 10.0).Shape();
    TopoDS_Compound both;
    BRep_Builder builder;
    builder.MakeCompound(both);
    builder.Add(both, holed);
    builder.Add(both, above);
    fs::create_directories(folder);
    const fs::path path = folder / "plates.brep";
    EXPECT_TRUE(BRepTools::Write(both, path.c_str()));
    return path;
}

// A private folder, also as XDG_CACHE_HOME for the cache test (the old value back after).
class Inspect : public ::testing::Test {
  protected:
    void SetUp() override {
        folder_ = fs::temp_directory_path() / ("idview_inspect_" + std::to_string(::getpid()));
        fs::remove_all(folder_);
        cacheHome_.emplace(folder_ / "cache");
        path_ = writePlates(folder_);
    }
    void TearDown() override {
        cacheHome_.reset();
        std::error_code ignored;
        fs::remove_all(folder_, ignored);
    }
    fs::path folder_, path_;
    std::optional<cadtest::CacheHome> cacheHome_;
};

// What the tests name in the plates' scene.
struct Plates {
    uint32_t holed = 0, above = 0;     // objects
    uint32_t hole1 = 0, hole2 = 0;     // their cylinders' unique parts
    uint32_t top = 0, underside = 0;   // the holed plate's top, the upper plate's bottom
    std::optional<EdgeRef> rim1, rim2; // the holes' circles on the top face
    Thing all(const Scene& s, uint32_t object) const {
        Thing t;
        const Object& o = s.objects[object];
        for (uint32_t p = 0; p < s.geometries[o.geometry].partCount; ++p)
            t.parts.push_back(o.uniquePartOffset + p);
        return t;
    }
};

Plates find(const Scene& s) {
    Plates f;
    EXPECT_EQ(s.objects.size(), 2u);
    // The holed plate has its two cylinders beyond a box's six faces.
    f.holed = s.geometries[s.objects[0].geometry].partCount > 6 ? 0 : 1;
    f.above = 1 - f.holed;
    for (uint32_t id = 0; id < s.uniquePartCount(); ++id) {
        const SurfaceInfo surface = faceReport(s, id)->surface;
        if (surface.kind == SurfaceKind::Cylinder)
            (std::abs(surface.radius - kR1) < 1e-9 ? f.hole1 : f.hole2) = id;
        if (surface.kind == SurfaceKind::Plane && surface.normal.z > 0.5 &&
            std::abs(surface.d - 10.0) < 1e-9)
            f.top = id;
        if (surface.kind == SurfaceKind::Plane && surface.normal.z < -0.5 &&
            std::abs(surface.d + 10.0 + kGap) < 1e-9)
            f.underside = id;
    }
    // The circles at z = 10, by their radius, numbered as inspect.h's EdgeRef numbers edges.
    const Object& holed = s.objects[f.holed];
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(s.brep->shape(holed.geometry).shape, TopAbs_EDGE, edges);
    for (int e = 1; e <= edges.Extent(); ++e) {
        const BRepAdaptor_Curve curve(TopoDS::Edge(edges(e)));
        if (curve.GetType() != GeomAbs_Circle ||
            std::abs(curve.Circle().Location().Z() - 10) > 1e-9)
            continue;
        const EdgeRef ref{holed.uniquePartOffset, uint32_t(e - 1)};
        (std::abs(curve.Circle().Radius() - kR1) < 1e-9 ? f.rim1 : f.rim2) = ref;
    }
    return f;
}

Thing part(uint32_t id) {
    return Thing{{id}, std::nullopt, ""};
}
Thing edge(EdgeRef ref) {
    return Thing{{}, ref, ""};
}

void expectPlates(const Scene& s) {
    ASSERT_TRUE(s.brep);
    const Plates f = find(s);
    ASSERT_TRUE(f.rim1 && f.rim2);
    // The plates' gap, between their facing sides.
    const auto gap = measureDistance(s, f.all(s, f.holed), f.all(s, f.above));
    ASSERT_TRUE(gap);
    EXPECT_TRUE(gap->fromBrep);
    EXPECT_NEAR(gap->distance, kGap, 1e-6 * kGap);
    EXPECT_NEAR(gap->p0.z, 10.0, 1e-9);
    EXPECT_NEAR(gap->p1.z, 10.0 + kGap, 1e-9);
    // The wall between the holes, and their centres and axes.
    const auto holes = measureDistance(s, part(f.hole1), part(f.hole2));
    ASSERT_TRUE(holes);
    EXPECT_NEAR(holes->distance, kSpacing - kR1 - kR2, 1e-6);
    ASSERT_TRUE(holes->centreDistance && holes->axisAngleDegrees && holes->axisDistance);
    EXPECT_NEAR(*holes->centreDistance, kSpacing, 1e-9);
    EXPECT_NEAR(*holes->axisAngleDegrees, 0.0, 1e-9);
    EXPECT_NEAR(*holes->axisDistance, kSpacing, 1e-9);
    EXPECT_FALSE(holes->pointToPlane);
    // The same from the holes' rims.
    const auto rims = measureDistance(s, edge(*f.rim1), edge(*f.rim2));
    ASSERT_TRUE(rims && rims->centreDistance && rims->axisAngleDegrees && rims->axisDistance);
    EXPECT_NEAR(rims->distance, kSpacing - kR1 - kR2, 1e-6);
    EXPECT_NEAR(*rims->centreDistance, kSpacing, 1e-9);
    EXPECT_NEAR(*rims->axisAngleDegrees, 0.0, 1e-9);
    EXPECT_NEAR(*rims->axisDistance, kSpacing, 1e-9);
    // A hole's centre lies mid-plate: 5 below the top (its outward normal up), 12.5 off the
    // upper plate's underside (outward normal down); the rim lies in the top.
    const auto inPlate = measureDistance(s, part(f.top), part(f.hole1));
    ASSERT_TRUE(inPlate && inPlate->pointToPlane);
    EXPECT_NEAR(*inPlate->pointToPlane, -5.0, 1e-9);
    EXPECT_NEAR(inPlate->distance, 0.0, 1e-9); // the top touches the hole's wall
    const auto toUpper = measureDistance(s, part(f.hole2), part(f.underside));
    ASSERT_TRUE(toUpper && toUpper->pointToPlane);
    EXPECT_NEAR(*toUpper->pointToPlane, 5.0 + kGap, 1e-9);
    const auto rimUp = measureDistance(s, edge(*f.rim1), part(f.underside));
    ASSERT_TRUE(rimUp && rimUp->pointToPlane);
    EXPECT_NEAR(*rimUp->pointToPlane, kGap, 1e-9);
    EXPECT_NEAR(rimUp->distance, kGap, 1e-6);

    // Volumes, areas and centres of mass from the dimensions.
    const auto holed = objectProperties(s, f.holed);
    ASSERT_TRUE(holed);
    EXPECT_TRUE(holed->closed);
    const double v1 = pi * kR1 * kR1 * 10, v2 = pi * kR2 * kR2 * 10;
    const double volume = 100 * 60 * 10 - v1 - v2;
    EXPECT_NEAR(holed->volume, volume, 1e-9 * volume);
    const double area =
        2 * (6000 - pi * (kR1 * kR1 + kR2 * kR2)) + 2 * 1000 + 2 * 600 + 2 * pi * (kR1 + kR2) * 10;
    EXPECT_NEAR(holed->area, area, 1e-9 * area);
    const double x = (6e4 * 50 - v1 * 25 - v2 * (25 + kSpacing)) / volume;
    EXPECT_NEAR(holed->center.x, x, 1e-9 * 100);
    EXPECT_NEAR(holed->center.y, 30.0, 1e-9 * 100);
    EXPECT_NEAR(holed->center.z, 5.0, 1e-9 * 100);
    EXPECT_NEAR(glm::length(holed->bbox.min - glm::dvec3(0.0)), 0.0, 1e-6);
    EXPECT_NEAR(glm::length(holed->bbox.max - glm::dvec3(100, 60, 10)), 0.0, 1e-6);
    const auto above = objectProperties(s, f.above);
    ASSERT_TRUE(above);
    EXPECT_NEAR(above->volume, 6e4, 1e-9 * 6e4);
    EXPECT_NEAR(glm::length(above->center - glm::dvec3(50, 30, 15 + kGap)), 0.0, 1e-9 * 100);
    const SolidProperties sum = sumProperties({*holed, *above});
    EXPECT_NEAR(sum.volume, volume + 6e4, 1e-9 * 1e5);
    EXPECT_NEAR(sum.bbox.max.z, 20 + kGap, 1e-6);
    EXPECT_FALSE(objectProperties(s, 2));
}

} // namespace

TEST_F(Inspect, PlatesWithHolesMeasureAsBuilt) {
    expectPlates(loadCad(path_.string(), {}).scene);
}

// The B-rep and its face order come back from the cache: the very same answers.
TEST_F(Inspect, TheCacheGivesTheSameAnswers) {
    const CadLoadResult miss = loadCadCached(path_.string(), {});
    ASSERT_EQ(miss.cache, "miss") << miss.cacheNote;
    const CadLoadResult hit = loadCadCached(path_.string(), {});
    ASSERT_EQ(hit.cache, "hit") << hit.cacheNote;
    expectPlates(hit.scene);
    const Plates f = find(hit.scene);
    const auto a = measureDistance(miss.scene, part(f.hole1), part(f.top));
    const auto b = measureDistance(hit.scene, part(f.hole1), part(f.top));
    ASSERT_TRUE(a && b);
    EXPECT_EQ(distanceJson(*a), distanceJson(*b));
    EXPECT_EQ(propertiesJson(*objectProperties(miss.scene, 0)),
              propertiesJson(*objectProperties(hit.scene, 0)));
}

// A copy moved along x: its faces, edges and solid are measured where the copy is (each
// object's placement applied), against the original.
TEST_F(Inspect, AMovedCopyIsMeasuredWhereItIs) {
    const Scene original = loadCad(path_.string(), {}).scene;
    const Scene s = replicate(original, 2, COPY_X);
    ASSERT_EQ(s.objects.size(), 4u);
    const glm::dvec3 shift = glm::dvec3(s.objects[2].world[3]) - glm::dvec3(s.objects[0].world[3]);
    ASSERT_GT(shift.x, 100.0);
    const Plates f = find(original);
    const uint32_t moved = original.uniquePartCount(); // copy 1's IDs: copy 0's plus this
    const auto plates = measureDistance(s, f.all(s, f.holed), f.all(s, f.holed + 2));
    ASSERT_TRUE(plates);
    EXPECT_NEAR(plates->distance, shift.x - 100.0, 1e-6);
    const auto holes = measureDistance(s, part(f.hole1), part(f.hole1 + moved));
    ASSERT_TRUE(holes && holes->centreDistance && holes->axisDistance);
    EXPECT_NEAR(*holes->centreDistance, glm::length(shift), 1e-9);
    EXPECT_NEAR(*holes->axisDistance, glm::length(shift), 1e-9);
    const EdgeRef rim{f.rim2->part + moved, f.rim2->edge};
    const auto rims = measureDistance(s, edge(*f.rim2), edge(rim));
    ASSERT_TRUE(rims && rims->centreDistance);
    EXPECT_NEAR(*rims->centreDistance, glm::length(shift), 1e-9);
    EXPECT_NEAR(rims->distance, glm::length(shift) - 2 * kR2, 1e-6);
    const auto a = objectProperties(s, f.holed), b = objectProperties(s, f.holed + 2);
    ASSERT_TRUE(a && b);
    EXPECT_NEAR(b->volume, a->volume, 1e-9 * a->volume);
    EXPECT_NEAR(glm::length(b->center - (a->center + shift)), 0.0, 1e-9);
    EXPECT_NEAR(glm::length(b->bbox.min - (a->bbox.min + shift)), 0.0, 1e-6);
}

TEST_F(Inspect, JsonLinesCarryTheMembersAndUnit) {
    const Scene s = loadCad(path_.string(), {}).scene;
    const Plates f = find(s);
    const std::string d = distanceJson(*measureDistance(s, part(f.hole1), part(f.hole2)));
    const std::string n = "-?[0-9][-+.e0-9]*", v = "\\[" + n + "," + n + "," + n + "\\]";
    EXPECT_TRUE(std::regex_match(
        d, std::regex("\\{\"distance\":" + n + ",\"p0\":" + v + ",\"p1\":" + v +
                      ",\"source\":\"brep\",\"center_distance\":" + n + ",\"axis_angle\":" + n +
                      ",\"axis_distance\":" + n + ",\"unit\":\"none\"\\}")))
        << d;
    const std::string p = propertiesJson(*objectProperties(s, f.above));
    EXPECT_TRUE(std::regex_match(p, std::regex("\\{\"object\":" + std::to_string(f.above) +
                                               ",\"volume\":" + n + ",\"area\":" + n +
                                               ",\"center\":" + v + ",\"bbox\":\\{\"min\":" + v +
                                               ",\"max\":" + v + ",\"size\":" + v +
                                               "\\},\"closed\":true,\"unit\":\"none\"\\}")))
        << p;
    const std::string total = totalPropertiesJson(sumProperties({*objectProperties(s, 0)}));
    EXPECT_EQ(total.rfind("{\"object\":\"all\",\"objects\":1,\"volume\":", 0), 0u) << total;
}

// Open CASCADE's own answers on the file as it reads it plainly: each solid's volume, area
// and centre, and the distance between two solids' faces.
TEST(InspectOcct, AFileAnswersAsOpenCascadeDoes) {
    const fs::path file = testing_support::kOcctData / "occ" / "Motor-c.brep";
    REQUIRE_DATA(file);
    const Scene s = loadCad(file.string(), {}).scene;
    const TopoDS_Shape plain = testing_support::readPlain(file);
    std::vector<TopoDS_Shape> solids;
    for (TopExp_Explorer e(plain, TopAbs_SOLID); e.More(); e.Next()) solids.push_back(e.Current());
    ASSERT_EQ(solids.size(), s.objects.size());
    ASSERT_GE(solids.size(), 2u);
    for (uint32_t o = 0; o < s.objects.size(); ++o) {
        ASSERT_EQ(s.objects[o].name, "solid " + std::to_string(o + 1));
        GProp_GProps volume, surface;
        BRepGProp::VolumeProperties(solids[o], volume);
        BRepGProp::SurfaceProperties(solids[o], surface);
        const auto p = objectProperties(s, o);
        ASSERT_TRUE(p && p->closed);
        EXPECT_NEAR(p->volume, std::abs(volume.Mass()), 1e-9 * std::abs(volume.Mass()));
        EXPECT_NEAR(p->area, surface.Mass(), 1e-9 * surface.Mass());
        const gp_Pnt c = volume.CentreOfMass();
        EXPECT_NEAR(glm::distance(p->center, glm::dvec3(c.X(), c.Y(), c.Z())), 0.0, 1e-6);
    }
    auto faces = [](const TopoDS_Shape& solid) {
        TopoDS_Compound all;
        BRep_Builder builder;
        builder.MakeCompound(all);
        for (TopExp_Explorer e(solid, TopAbs_FACE); e.More(); e.Next())
            builder.Add(all, e.Current());
        return all;
    };
    // Two small solids apart (a few faces each: quick), and one of them against a large one.
    for (const auto& [a, b] : {std::pair(5u, 7u), std::pair(7u, 2u)}) {
        BRepExtrema_DistShapeShape occt(faces(solids[a]), faces(solids[b]));
        ASSERT_TRUE(occt.IsDone());
        Plates f;
        const auto ours = measureDistance(s, f.all(s, a), f.all(s, b));
        ASSERT_TRUE(ours);
        EXPECT_GT(ours->distance, 1.0);
        EXPECT_NEAR(ours->distance, occt.Value(), 1e-9 * (1 + occt.Value()));
        const gp_Pnt p0 = occt.PointOnShape1(1), p1 = occt.PointOnShape2(1);
        EXPECT_NEAR(glm::distance(ours->p0, glm::dvec3(p0.X(), p0.Y(), p0.Z())), 0.0, 1e-6);
        EXPECT_NEAR(glm::distance(ours->p1, glm::dvec3(p1.X(), p1.Y(), p1.Z())), 0.0, 1e-6);
    }
}

// Mesh scenes: two boxes of side 2, the second 3 beyond the first along x (and offset on the
// other axes, where they overlap), measured from their triangles; their volume and centre.
TEST(InspectMesh, TwoBoxesAtAKnownDistance) {
    Scene s;
    MeshBuilder builder;
    builder.addBox(glm::vec3(0.0f), glm::vec3(2.0f));
    const uint32_t box = builder.finish(s, "box");
    const uint32_t material = addMaterial(s, "grey", glm::vec4(0.5f));
    addObject(s, box, material, glm::dmat4(1.0));
    const glm::dvec3 offset(5.0, 0.5, 0.25);
    addObject(s, box, material, glm::translate(glm::dmat4(1.0), offset));
    Plates f;
    const auto d = measureDistance(s, f.all(s, 0), f.all(s, 1));
    ASSERT_TRUE(d);
    EXPECT_FALSE(d->fromBrep);
    EXPECT_NEAR(d->distance, 3.0, 1e-12);
    EXPECT_NEAR(d->p0.x, 1.0, 1e-12);
    EXPECT_NEAR(d->p1.x, 4.0, 1e-12);
    EXPECT_FALSE(measureDistance(s, edge({0, 0}), f.all(s, 1)));
    const auto p = objectProperties(s, 1);
    ASSERT_TRUE(p && p->closed);
    EXPECT_NEAR(p->volume, 8.0, 1e-12);
    EXPECT_NEAR(p->area, 24.0, 1e-12);
    EXPECT_NEAR(glm::distance(p->center, offset), 0.0, 1e-12);
    EXPECT_NEAR(glm::distance(p->bbox.max, offset + 1.0), 0.0, 1e-12);
}

// Many triangles each side (a 48-sided prism, a tilted box): the pruned search finds what
// every pair of triangles tried gives.
TEST(InspectMesh, ThePrunedSearchFindsWhatEveryPairGives) {
    Scene s;
    MeshBuilder builder;
    builder.addPrism(glm::vec2(0.0f), 1.0f, 0.0f, 2.0f, 48, true);
    const uint32_t prism = builder.finish(s, "prism");
    builder.addBox(glm::vec3(0.0f), glm::vec3(1.0f, 3.0f, 0.5f));
    const uint32_t box = builder.finish(s, "box");
    const uint32_t material = addMaterial(s, "grey", glm::vec4(0.5f));
    addObject(s, prism, material, glm::dmat4(1.0));
    glm::dmat4 tilted = glm::translate(glm::dmat4(1.0), glm::dvec3(2.1, 0.3, 1.2));
    tilted = glm::rotate(tilted, 0.7, glm::dvec3(0.3, 1.0, 0.2));
    addObject(s, box, material, tilted);
    auto triangles = [&](uint32_t object) {
        std::vector<Triangle> all;
        const Object& o = s.objects[object];
        const Geometry& g = s.geometries[o.geometry];
        for (uint32_t t = 0; t < g.triangleCount; ++t) {
            Triangle c;
            for (size_t k = 0; k < 3; ++k)
                c[k] = placed(
                    o.world,
                    s.vertices[g.firstVertex + s.indices[g.firstIndex + 3 * t + k]].position);
            all.push_back(c);
        }
        return all;
    };
    double every = std::numeric_limits<double>::infinity();
    const auto a = triangles(0), b = triangles(1);
    ASSERT_GT(a.size() * b.size(), 1000u);
    for (const Triangle& x : a)
        for (const Triangle& y : b) every = std::min(every, triangleDistance(x, y).distance);
    Plates f;
    const auto d = measureDistance(s, f.all(s, 0), f.all(s, 1));
    ASSERT_TRUE(d);
    EXPECT_GT(every, 0.01);
    EXPECT_EQ(d->distance, every);
    EXPECT_NEAR(glm::distance(d->p0, d->p1), every, 1e-12);
}

TEST(InspectMesh, CrossingTrianglesTouch) {
    const Triangle a{glm::dvec3(-1, -1, 0), glm::dvec3(1, -1, 0), glm::dvec3(0, 1, 0)};
    const Triangle b{glm::dvec3(0, 0, -1), glm::dvec3(0.2, 0, 1), glm::dvec3(0.1, 5, 1)};
    EXPECT_EQ(triangleDistance(a, b).distance, 0.0);
    const Triangle c{glm::dvec3(0, 0, 2), glm::dvec3(1, 0, 3), glm::dvec3(0, 1, 3)};
    EXPECT_NEAR(triangleDistance(a, c).distance, 2.0, 1e-15);
}
