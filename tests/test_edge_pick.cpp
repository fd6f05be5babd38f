// test_edge_pick.cpp - --edge-info against the ID image and the CPU ray cast, on lavapipe with
// validation on: on a plate with a hole built here (40 x 30 x 10, hole of diameter 10 at
// 20,15), a pixel a couple of pixels inside the top face next to one of its edges (placed from
// the camera) names the part the ID image and the ray cast give there, and the edge of that
// face nearest the ray's hit point (BRepExtrema); the face's middle names no edge.
#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

// Before Open CASCADE's headers: its Handle macro would rewrite vk::Handle.
#include "app/headless.h"
#include "app/scene_source.h"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepTools.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <gp_Ax2.hxx>

#include "cad_test_parts.h"
#include "scene/cad/brep_occt.h"
#include "scene/edge_info.h"
#include "scene/raycast.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;
constexpr uint32_t W = 240, H = 150;

app::LoadedScene plateWithHole() {
    const fs::path path = cadtest::writeBoxWithHole("edge_pick", 40.0, 30.0, 10.0, 5.0);
    EXPECT_FALSE(path.empty());
    app::SceneSettings source;
    source.model = path.string();
    source.cadCache = false;
    app::LoadedScene loaded = app::loadScene(source);
    fs::remove(path);
    return loaded;
}

} // namespace

TEST(EdgeInfoPick, NamesTheEdgeNearestTheRayCastsHit) {
    const app::LoadedScene loaded = plateWithHole();
    const scene::Scene& s = loaded.scene;
    ASSERT_TRUE(s.brep);
    const scene::Camera camera = app::initialCamera(loaded, float(W) / float(H));
    const glm::dvec2 size(W, H);
    const glm::dmat4 viewProj = camera.viewProjection(size.x / size.y);
    auto project = [&](glm::dvec3 p) {
        const glm::dvec4 clip = viewProj * glm::dvec4(p, 1.0);
        return (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * size;
    };
    // 2.5 pixels from the edge point `on` towards `inward` on the top face (z = 10), which the
    // starting view shows from above; and the middle of the face between the plate's edge and
    // the hole.
    auto inside = [&](glm::dvec3 on, glm::dvec3 inward) {
        const glm::dvec2 a = project(on), b = project(inward);
        const glm::dvec2 at = a + 2.5 * glm::normalize(b - a);
        return app::Options::Pixel{uint32_t(at.x), uint32_t(at.y)};
    };
    const glm::dvec2 middle = project({8, 15, 10});
    app::Options o = testing_support::headlessOptions(W, H);
    o.edgeInfos = {inside({20, 0, 10}, {20, 5, 10}),   // the front edge, y = 0
                   inside({40, 20, 10}, {35, 20, 10}), // the right edge, x = 40
                   inside({25, 15, 10}, {27, 15, 10}), // the hole's rim
                   {uint32_t(middle.x), uint32_t(middle.y)}};
    const auto r = app::renderHeadless(o, s, camera);
    EXPECT_EQ(r.validationMessages, 0u);
    ASSERT_EQ(r.edgeInfoEdges.size(), o.edgeInfos.size());

    const scene::RayCaster caster(s);
    const TopoDS_Shape& shape = s.brep->shape(s.objects[0].geometry).shape;
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(shape, TopAbs_EDGE, edges);
    const TopLoc_Location where = scene::placement(glm::dmat4(s.objects[0].world));
    for (size_t i = 0; i < o.edgeInfos.size(); ++i) {
        const app::Options::Pixel pixel = o.edgeInfos[i];
        SCOPED_TRACE("pixel " + std::to_string(pixel.x) + "," + std::to_string(pixel.y));
        const uint32_t shown = r.ids[size_t(pixel.y) * W + pixel.x];
        const scene::Ray ray = scene::pixelRay(viewProj, size, glm::dvec2(pixel.x, pixel.y) + 0.5);
        const auto hit = caster.cast(ray);
        ASSERT_TRUE(hit.has_value());
        ASSERT_TRUE(r.edgeInfoPicks[i].part.has_value());
        EXPECT_EQ(*r.edgeInfoPicks[i].part, shown);
        EXPECT_EQ(hit->uniquePartId, shown);
        const std::string json = app::edgeInfoJson(s, r.edgeInfoPicks[i], r.edgeInfoEdges[i]);
        const std::string head =
            "{\"x\":" + std::to_string(pixel.x) + ",\"y\":" + std::to_string(pixel.y) + ",";
        EXPECT_EQ(json.rfind(head + "\"part\":" + std::to_string(shown) + ",", 0), 0u) << json;
        if (i + 1 == o.edgeInfos.size()) { // the face's middle
            EXPECT_FALSE(r.edgeInfoEdges[i].has_value());
            EXPECT_NE(json.find("\"edge\":null"), std::string::npos) << json;
            continue;
        }
        ASSERT_TRUE(r.edgeInfoEdges[i].has_value());
        EXPECT_EQ(r.edgeInfoEdges[i]->part, shown);
        // The face's edge nearest the point the ray meets, by Open CASCADE.
        const glm::dvec3 p = ray.origin + hit->t * ray.direction;
        const TopoDS_Shape vertex = BRepBuilderAPI_MakeVertex(gp_Pnt(p.x, p.y, p.z)).Shape();
        std::optional<uint32_t> nearest;
        double least = 1e300;
        for (const scene::EdgeRef& ref : scene::faceEdges(s, shown)) {
            BRepExtrema_DistShapeShape distance(vertex, edges(int(ref.edge) + 1).Moved(where));
            ASSERT_TRUE(distance.IsDone());
            if (distance.Value() < least) {
                least = distance.Value();
                nearest = ref.edge;
            }
        }
        EXPECT_EQ(r.edgeInfoEdges[i]->edge, nearest);
        EXPECT_LT(least, 2.0); // a couple of pixels on a 40-unit plate about 150 pixels wide
        const auto report = scene::edgeReport(s, *r.edgeInfoEdges[i]);
        ASSERT_TRUE(report);
        EXPECT_EQ(report->kind, i == 2 ? scene::CurveKind::Circle : scene::CurveKind::Line);
        EXPECT_NE(json.find("\"edge\":" + std::to_string(*nearest) + ",\"curve\":"),
                  std::string::npos)
            << json;
    }
}
