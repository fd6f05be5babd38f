// test_face_info.cpp - what --face-info says of a part (scene/face_info.h): on a solid built
// here with known dimensions (a 40 x 30 x 20 box with a hole of radius 5 through it), the
// planes' normals, distances and areas and the hole's radius and axis, also for a copy moved
// away; on occt-misc's files, every face's surface type and area as Open CASCADE itself gives
// them, also in the panel's line for a face (area with its unit); on a mesh part, the area of
// its triangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <unistd.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include "cad_test_parts.h"
#include "scene/cad/cad_loader.h"
#include "scene/copies.h"
#include "scene/face_info.h"
#include "scene/inspect.h"
#include "scene/procedural/procedural.h"
#include "test_data.h"

namespace {

namespace fs = std::filesystem;
using namespace scene;

// The box with its hole, written as BREP and loaded as a user would.
Scene boxWithHole() {
    const fs::path path = cadtest::writeBoxWithHole("face_info", 40.0, 30.0, 20.0, 5.0);
    EXPECT_FALSE(path.empty());
    Scene s = loadCad(path.string(), {}).scene;
    fs::remove(path);
    return s;
}

} // namespace

TEST(FaceInfo, ABoxWithAHoleHasItsKnownPlanesAndCylinder) {
    const Scene s = boxWithHole();
    ASSERT_EQ(s.objects.size(), 1u);
    const double pi = std::numbers::pi;
    // Each plane by its outward normal: where it lies (d) and its area.
    struct Expected {
        glm::dvec3 normal;
        double d, area;
        bool seen = false;
    };
    std::vector<Expected> planes = {
        {{-1, 0, 0}, 0, 600},
        {{1, 0, 0}, 40, 600},
        {{0, -1, 0}, 0, 800},
        {{0, 1, 0}, 30, 800},
        {{0, 0, -1}, 0, 1200 - 25 * pi},
        {{0, 0, 1}, 20, 1200 - 25 * pi},
    };
    double cylinderArea = 0.0;
    for (uint32_t p = 0; p < s.geometries[0].partCount; ++p) {
        const auto r = faceReport(s, s.objects[0].uniquePartOffset + p);
        ASSERT_TRUE(r.has_value());
        ASSERT_TRUE(r->face.has_value());
        if (r->surface.kind == SurfaceKind::Cylinder) {
            EXPECT_NEAR(r->surface.radius, 5.0, 1e-9);
            EXPECT_NEAR(std::abs(r->surface.axisDirection.z), 1.0, 1e-9);
            EXPECT_NEAR(r->surface.axisOrigin.x, 20.0, 1e-9);
            EXPECT_NEAR(r->surface.axisOrigin.y, 15.0, 1e-9);
            // The hole's diameter, in the JSON and the panel's line with its axis.
            EXPECT_NE(faceReportJson(*r).find("\"diameter\":10,"), std::string::npos)
                << faceReportJson(*r);
            const std::string line = describeSurface(*r);
            EXPECT_EQ(line.rfind("cylinder \u00d8 10 (r 5), axis (0, 0, ", 0), 0u) << line;
            cylinderArea += r->surface.area;
            continue;
        }
        ASSERT_EQ(r->surface.kind, SurfaceKind::Plane) << "part " << p;
        auto found = std::find_if(planes.begin(), planes.end(), [&](const Expected& e) {
            return glm::length(e.normal - r->surface.normal) < 1e-9;
        });
        ASSERT_NE(found, planes.end()) << "an unexpected normal on part " << p;
        EXPECT_FALSE(found->seen);
        found->seen = true;
        EXPECT_NEAR(r->surface.d, found->d, 1e-9);
        EXPECT_NEAR(r->surface.area, found->area, 1e-6 * found->area);
        // The box of its triangles lies in its plane.
        EXPECT_NEAR(glm::dot(glm::dvec3(r->bbox.min), found->normal), found->d, 1e-4);
        EXPECT_NEAR(glm::dot(glm::dvec3(r->bbox.max), found->normal), found->d, 1e-4);
    }
    for (const Expected& e : planes) EXPECT_TRUE(e.seen) << e.normal.x << e.normal.y << e.normal.z;
    EXPECT_NEAR(cylinderArea, 2 * pi * 5 * 20, 1e-6 * 2 * pi * 5 * 20);
    const std::string json = faceReportJson(*faceReport(s, s.objects[0].uniquePartOffset));
    EXPECT_EQ(json.rfind("{\"part\":", 0), 0u) << json;
    EXPECT_NE(json.find("\"bbox\":{\"min\":["), std::string::npos) << json;
}

// Planes compared: square faces at 90 degrees, opposite ones at 180 and their distance
// apart, a face with itself at 0 and 0; the hole is no plane.
TEST(FaceInfo, PlanarFacesGiveTheirAngleAndParallelOnesTheirDistance) {
    const Scene s = boxWithHole();
    std::vector<FaceReport> faces;
    for (uint32_t p = 0; p < s.geometries[0].partCount; ++p)
        faces.push_back(*faceReport(s, s.objects[0].uniquePartOffset + p));
    auto withNormal = [&](glm::dvec3 n) {
        for (const FaceReport& f : faces)
            if (f.surface.kind == SurfaceKind::Plane && glm::length(f.surface.normal - n) < 1e-9)
                return f;
        ADD_FAILURE() << "no face with normal " << n.x << "," << n.y << "," << n.z;
        return FaceReport{};
    };
    const auto across = comparePlanes(withNormal({-1, 0, 0}), withNormal({1, 0, 0}));
    ASSERT_TRUE(across);
    EXPECT_NEAR(across->angleDegrees, 180.0, 1e-9);
    ASSERT_TRUE(across->distance);
    EXPECT_NEAR(*across->distance, 40.0, 1e-9);
    const auto height = comparePlanes(withNormal({0, 0, 1}), withNormal({0, 0, -1}));
    ASSERT_TRUE(height && height->distance);
    EXPECT_NEAR(*height->distance, 20.0, 1e-9);
    const auto square = comparePlanes(withNormal({0, -1, 0}), withNormal({1, 0, 0}));
    ASSERT_TRUE(square);
    EXPECT_NEAR(square->angleDegrees, 90.0, 1e-9);
    EXPECT_FALSE(square->distance);
    const auto itself = comparePlanes(withNormal({0, 1, 0}), withNormal({0, 1, 0}));
    ASSERT_TRUE(itself && itself->distance);
    EXPECT_NEAR(itself->angleDegrees, 0.0, 1e-9);
    EXPECT_NEAR(*itself->distance, 0.0, 1e-9);
    const auto hole = std::find_if(faces.begin(), faces.end(), [](const FaceReport& f) {
        return f.surface.kind == SurfaceKind::Cylinder;
    });
    ASSERT_NE(hole, faces.end());
    EXPECT_FALSE(comparePlanes(*hole, withNormal({1, 0, 0})));
}

// A copy moved along the grid: the same normals and areas, each plane's d moved by the
// normal's share of the shift, the hole's axis moved with it.
TEST(FaceInfo, AMovedCopySaysWhereItIs) {
    const Scene s = replicate(boxWithHole(), 2, COPY_X);
    ASSERT_EQ(s.objects.size(), 2u);
    const glm::dvec3 shift = glm::dvec3(s.objects[1].world[3]) - glm::dvec3(s.objects[0].world[3]);
    ASSERT_GT(glm::length(shift), 1.0);
    for (uint32_t p = 0; p < s.geometries[0].partCount; ++p) {
        const auto a = faceReport(s, s.objects[0].uniquePartOffset + p);
        const auto b = faceReport(s, s.objects[1].uniquePartOffset + p);
        ASSERT_TRUE(a && b);
        EXPECT_EQ(a->surface.kind, b->surface.kind);
        EXPECT_NEAR(a->surface.area, b->surface.area, 1e-9 * a->surface.area);
        if (a->surface.kind == SurfaceKind::Plane) {
            EXPECT_NEAR(glm::length(a->surface.normal - b->surface.normal), 0.0, 1e-9);
            EXPECT_NEAR(b->surface.d, a->surface.d + glm::dot(a->surface.normal, shift), 1e-4);
        } else {
            EXPECT_NEAR(glm::length(b->surface.axisOrigin - (a->surface.axisOrigin + shift)), 0.0,
                        1e-4);
        }
    }
}

namespace {

// Open CASCADE's own answer for every face of the file: surface type and area, sorted.
std::vector<std::pair<int, double>> occtFaces(const fs::path& path) {
    TopoDS_Shape shape;
    const std::string ext = path.extension().string();
    if (ext == ".brep") {
        BRep_Builder builder;
        EXPECT_TRUE(BRepTools::Read(shape, path.c_str(), builder));
    } else if (ext == ".step") {
        STEPControl_Reader reader;
        EXPECT_EQ(reader.ReadFile(path.c_str()), IFSelect_RetDone);
        reader.TransferRoots();
        shape = reader.OneShape();
    } else {
        IGESControl_Reader reader;
        EXPECT_EQ(reader.ReadFile(path.c_str()), IFSelect_RetDone);
        reader.TransferRoots();
        shape = reader.OneShape();
    }
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    std::vector<std::pair<int, double>> out;
    for (int f = 1; f <= faces.Extent(); ++f) {
        GProp_GProps props;
        BRepGProp::SurfaceProperties(faces(f), props);
        out.emplace_back(int(BRepAdaptor_Surface(TopoDS::Face(faces(f))).GetType()), props.Mass());
    }
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

TEST(FaceInfo, EveryFaceOfTheSampleFilesIsWhatOpenCascadeSays) {
    const fs::path data = "/usr/share/opencascade/data";
    for (const char* name : {"occ/Motor-c.brep", "step/linkrods.step", "iges/bearing.iges"}) {
        REQUIRE_DATA(data / name);
        std::optional<OcctLeaksIgnored> ignored(std::in_place); // the first reader's setup
        const auto expected = occtFaces(data / name);
        ignored.reset();
        const Scene s = loadCad((data / name).string(), {}).scene;
        // GeomAbs_SurfaceType's order, as SurfaceKind names them (GeomAbs_OtherSurface last).
        const SurfaceKind kinds[] = {
            SurfaceKind::Plane,   SurfaceKind::Cylinder,   SurfaceKind::Cone,
            SurfaceKind::Sphere,  SurfaceKind::Torus,      SurfaceKind::Bezier,
            SurfaceKind::BSpline, SurfaceKind::Revolution, SurfaceKind::Extrusion,
            SurfaceKind::Offset,  SurfaceKind::Other};
        std::vector<std::pair<int, double>> ours;
        for (const Object& o : s.objects)
            for (uint32_t p = 0; p < s.geometries[o.geometry].partCount; ++p) {
                const auto r = faceReport(s, o.uniquePartOffset + p);
                ASSERT_TRUE(r.has_value());
                const int type =
                    int(std::find(std::begin(kinds), std::end(kinds), r->surface.kind) -
                        std::begin(kinds));
                ours.emplace_back(type, r->surface.area);
            }
        std::sort(ours.begin(), ours.end());
        ASSERT_EQ(ours.size(), expected.size()) << name;
        for (size_t i = 0; i < ours.size(); ++i) {
            EXPECT_EQ(ours[i].first, expected[i].first) << name << " face " << i;
            // Open CASCADE's own arithmetic gives the same areas, but sewing bearing.iges moves
            // its faces' trims within the file's resolution (1e-4 mm): by up to that times a
            // face's perimeter, at most about 4 sqrt(area) for these faces.
            const double slack =
                fs::path(name).extension() == ".iges"
                    ? 1e-4 * expected[i].second + 4e-4 * std::sqrt(expected[i].second)
                    : 1e-9 * expected[i].second;
            EXPECT_NEAR(ours[i].second, expected[i].second, slack) << name << " face " << i;
        }
    }
}

// A part that is no B-rep face: surface mesh, the area of its triangles where its object
// places them, no face.
TEST(FaceInfo, AMeshPartHasTheAreaOfItsTriangles) {
    const Scene s = makeProcedural({});
    const Object& o = s.objects.back();
    const Geometry& g = s.geometries[o.geometry];
    const auto r = faceReport(s, o.uniquePartOffset);
    ASSERT_TRUE(r.has_value());
    EXPECT_EQ(r->surface.kind, SurfaceKind::Mesh);
    EXPECT_FALSE(r->face.has_value());
    const Part& part = s.parts[g.firstPart];
    double area = 0.0;
    for (uint32_t t = part.firstTriangle; t < part.firstTriangle + part.triangleCount; ++t) {
        glm::vec3 c[3];
        for (uint32_t k = 0; k < 3; ++k)
            c[k] = glm::vec3(
                o.world *
                glm::vec4(s.vertices[g.firstVertex + s.indices[g.firstIndex + 3 * t + k]].position,
                          1.0f));
        area += 0.5 * double(glm::length(glm::cross(c[1] - c[0], c[2] - c[0])));
    }
    EXPECT_GT(area, 0.0);
    EXPECT_NEAR(r->surface.area, area, 1e-5 * area);
    EXPECT_NE(faceReportJson(*r).find("\"surface\":\"mesh\""), std::string::npos);
}

// What the panel and the selection's event line say of each face of screw.step (one shape,
// so its faces are numbered as TopExp::MapShapes orders them): the area, read back from the
// text, is Open CASCADE's own for that face rounded to the model's precision, in mm².
TEST(FaceInfo, EachFaceLineGivesOpenCascadesAreaInMillimetres) {
    const char* path = "/usr/share/opencascade/data/step/screw.step";
    REQUIRE_DATA(path);
    Scene s = loadCad(path, {}).scene;
    s.unit = cadUnit(path);          // as app::loadScene sets it (test_units.cpp checks that)
    s.precision = scenePrecision(s); // and this (test_precision.cpp)
    ASSERT_GT(s.precision.length, 0.0);
    TopTools_IndexedMapOfShape faces;
    {
        // This process's first STEP reader (the load read in a worker): its setup is never
        // freed by Open CASCADE.
        const OcctLeaksIgnored ignored;
        STEPControl_Reader reader;
        ASSERT_EQ(reader.ReadFile(path), IFSelect_RetDone);
        reader.TransferRoots();
        TopExp::MapShapes(reader.OneShape(), TopAbs_FACE, faces);
    }
    ASSERT_GT(s.uniquePartCount(), 0u);
    for (uint32_t part = 0; part < s.uniquePartCount(); ++part) {
        const auto report = faceReport(s, part);
        ASSERT_TRUE(report && report->face);
        const std::string line = describeSurface(*report);
        const size_t at = line.find(", area ");
        ASSERT_NE(at, std::string::npos) << line;
        GProp_GProps props;
        BRepGProp::SurfaceProperties(faces(int(*report->face) + 1), props);
        EXPECT_EQ(line.substr(at + 7), areaText(props.Mass(), s.precision) + " mm\u00b2") << line;
        EXPECT_EQ(line.rfind(surfaceName(report->surface.kind), 0), 0u) << line;
    }
}
