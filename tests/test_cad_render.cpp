// test_cad_render.cpp - real CAD files (Debian's occt-misc samples: STEP, IGES, BREP)
// through the renderer on lavapipe with validation on: every part-ID technique draws the same
// ID image, and a pick names the B-rep face a CPU ray cast hits, with its product and path.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "app/headless.h"
#include "app/scene_source.h"
#include "image_compare.h"
#include "render/technique.h"
#include "scene/face_info.h"
#include "scene/raycast.h"
#include "test_data.h"
#include "test_support.h"

namespace {

constexpr uint32_t W = 240, H = 150;

// The pixel nearest the image centre inside a 5x5 block of one part.
app::Options::Pixel interiorNearCentre(const std::vector<uint32_t>& ids) {
    app::Options::Pixel best{0, 0};
    long bestDistance = -1;
    for (uint32_t y = 2; y + 2 < H; ++y)
        for (uint32_t x = 2; x + 2 < W; ++x) {
            const uint32_t id = ids[size_t(y) * W + x];
            bool inside = id != gpu::BACKGROUND_ID;
            for (uint32_t dy = y - 2; dy <= y + 2 && inside; ++dy)
                for (uint32_t dx = x - 2; dx <= x + 2 && inside; ++dx)
                    inside = ids[size_t(dy) * W + dx] == id;
            const long dx = long(x) - long(W / 2), dy = long(y) - long(H / 2);
            const long d = dx * dx + dy * dy;
            if (inside && (bestDistance < 0 || d < bestDistance)) {
                best = {x, y};
                bestDistance = d;
            }
        }
    return best;
}

class CadRender : public ::testing::TestWithParam<const char*> {};

TEST_P(CadRender, EveryTechniqueDrawsTheSameFacesAndAPickNamesTheFace) {
    const std::string path = GetParam();
    REQUIRE_DATA(path);
    app::SceneSettings source;
    source.model = path;
    const app::LoadedScene loaded = app::loadScene(source);
    const scene::Scene& scene = loaded.scene;
    const scene::Camera camera = app::initialCamera(loaded, float(W) / float(H));

    app::Options o = testing_support::headlessOptions(W, H);
    const auto first = app::renderHeadless(o, scene, camera);
    const app::Options::Pixel pixel = interiorNearCentre(first.ids);
    ASSERT_NE(first.ids[size_t(pixel.y) * W + pixel.x], gpu::BACKGROUND_ID) << path;

    std::vector<render::RenderSettings> configs;
    for (const render::Technique* t : render::partIdTechniques())
        configs.push_back(testing_support::settingsFor(*t, render::defaultDrawMode()));
    o.picks = {pixel};
    const auto results = app::renderHeadlessSequence(o, scene, camera, configs);
    EXPECT_EQ(results.front().validationMessages, 0u) << path;

    const glm::dmat4 viewProj = camera.viewProjection(float(W) / float(H));
    const auto hit = scene::RayCaster(scene).cast(
        scene::pixelRay(viewProj, glm::vec2(W, H), glm::vec2(pixel.x, pixel.y) + 0.5f));
    ASSERT_TRUE(hit.has_value()) << path;
    for (size_t c = 0; c < configs.size(); ++c) {
        const std::string name = path + " " + configs[c].pipeline.technique->name;
        const app::HeadlessResult& r = results[c];
        EXPECT_TRUE(testing_support::sameIds(r.ids, first.ids, W)) << name;
        ASSERT_EQ(r.picks.size(), 1u);
        ASSERT_TRUE(r.picks.front().part.has_value()) << name;
        EXPECT_EQ(*r.picks.front().part, hit->uniquePartId) << name;
    }
    // The pick names the face: its B-rep face number, and the product and path it belongs to.
    const auto info = scene::describePart(scene, hit->uniquePartId);
    ASSERT_TRUE(info && info->face.has_value()) << path;
    EXPECT_EQ(*info->face, scene.geometries[info->geometry].partFaces.at(info->localPart));
    EXPECT_FALSE(info->name.empty());
    EXPECT_FALSE(info->path.empty());
    const std::string json = app::pickJson(scene, results.front().picks.front());
    EXPECT_NE(json.find("\"face\":" + std::to_string(*info->face) + ","), std::string::npos)
        << json;
    EXPECT_NE(json.find("\"name\":\""), std::string::npos) << json;
}

INSTANTIATE_TEST_SUITE_P(Lavapipe, CadRender,
                         ::testing::Values("/usr/share/opencascade/data/step/screw.step",
                                           "/usr/share/opencascade/data/iges/hammer.iges",
                                           "/usr/share/opencascade/data/occ/bottle.brep"),
                         [](const auto& info) {
                             return testing_support::testName(
                                 std::filesystem::path(info.param).filename().string());
                         });

} // namespace

namespace {

// A part with a material of its own (CAD face colours, Geometry::partMaterials) shows it with
// every technique: exactly that part's pixels change, to the pure red given (green and blue
// stay 0 under the headlight); every other pixel is the image without part materials.
TEST(PartMaterials, APartsOwnMaterialShowsWithEveryTechnique) {
    app::SceneSettings source;
    source.builtin = "tiles";
    const app::LoadedScene loaded = app::loadScene(source);
    scene::Scene own = loaded.scene;
    const uint32_t red = scene::addMaterial(own, "own red", glm::vec4(1, 0, 0, 1));
    const uint32_t geometry = own.objects.front().geometry;
    scene::Geometry& g = own.geometries[geometry];
    g.partMaterials.assign(g.partCount, gpu::OBJECT_MATERIAL);
    g.partMaterials[3] = red;
    scene::validate(own);
    std::set<uint32_t> redIds; // part 3 of every object placing that geometry
    for (const scene::Object& o : own.objects)
        if (o.geometry == geometry) redIds.insert(o.uniquePartOffset + 3);

    const scene::Camera camera = app::initialCamera(loaded, float(W) / float(H));
    std::vector<render::RenderSettings> configs;
    for (const render::Technique* t : render::partIdTechniques()) {
        configs.push_back(testing_support::settingsFor(*t, render::defaultDrawMode()));
        configs.back().shading.partWeight = 0.0f; // the material colour alone
    }
    const app::Options o = testing_support::headlessOptions(W, H);
    const auto plain = app::renderHeadlessSequence(o, loaded.scene, camera, configs);
    const auto colored = app::renderHeadlessSequence(o, own, camera, configs);
    EXPECT_EQ(colored.front().validationMessages, 0u);
    for (size_t c = 0; c < configs.size(); ++c) {
        const std::string name = configs[c].pipeline.technique->name;
        ASSERT_TRUE(testing_support::sameIds(colored[c].ids, plain[c].ids, W)) << name;
        size_t redPixels = 0, wrong = 0;
        for (size_t i = 0; i < colored[c].ids.size(); ++i) {
            const uint8_t* p = &colored[c].color[4 * i];
            if (redIds.count(colored[c].ids[i])) {
                ++redPixels;
                wrong += !(p[0] > 40 && p[1] == 0 && p[2] == 0);
            } else {
                wrong += !std::equal(p, p + 4, &plain[c].color[4 * i]);
            }
        }
        EXPECT_GT(redPixels, 50u) << name;
        EXPECT_EQ(wrong, 0u) << name;
    }
}

} // namespace

namespace {

// Closed models show no background between their faces at 1280x720. bearing.iges's faces do
// not share their edges in the file: unsewn, 46 pinholes open along its seams here.
TEST(CadSeams, ClosedModelsShowNoBackgroundBetweenTheirFaces) {
    constexpr uint32_t w = 1280, h = 720;
    for (const char* path : {"/usr/share/opencascade/data/iges/bearing.iges",
                             "/usr/share/opencascade/data/occ/Motor-c.brep",
                             "/usr/share/opencascade/data/step/linkrods.step"}) {
        REQUIRE_DATA(path);
        app::SceneSettings source;
        source.model = path;
        const app::LoadedScene loaded = app::loadScene(source);
        const app::Options o = testing_support::headlessOptions(w, h);
        const auto result =
            app::renderHeadless(o, loaded.scene, app::initialCamera(loaded, float(w) / float(h)));
        EXPECT_EQ(result.validationMessages, 0u) << path;
        size_t shown = 0;
        for (uint32_t id : result.ids) shown += id != gpu::BACKGROUND_ID;
        EXPECT_GT(shown, size_t(w) * h / 20) << path;
        EXPECT_EQ(testing_support::enclosedBackground(result.ids, w, h).size(), 0u) << path;
    }
}

} // namespace

namespace {

// --face-info picks the face the ID image shows at the pixel and reports that face: on
// linkrods.step, at a pixel inside a face near the centre, the part of the ID image, the
// B-rep face the pick names, a surface the B-rep knows and an area that is positive.
TEST(FaceInfoPick, NamesTheFaceTheIdImageShows) {
    const std::string path = "/usr/share/opencascade/data/step/linkrods.step";
    REQUIRE_DATA(path);
    app::SceneSettings source;
    source.model = path;
    const app::LoadedScene loaded = app::loadScene(source);
    const scene::Camera camera = app::initialCamera(loaded, float(W) / float(H));
    app::Options o = testing_support::headlessOptions(W, H);
    const auto plain = app::renderHeadless(o, loaded.scene, camera);
    const app::Options::Pixel pixel = interiorNearCentre(plain.ids);
    o.faceInfos = {pixel, {0, 0}};
    const auto r = app::renderHeadless(o, loaded.scene, camera);
    EXPECT_EQ(r.validationMessages, 0u);
    ASSERT_EQ(r.faceInfoPicks.size(), 2u);
    const uint32_t shown = plain.ids[size_t(pixel.y) * W + pixel.x];
    ASSERT_TRUE(r.faceInfoPicks[0].part.has_value());
    EXPECT_EQ(*r.faceInfoPicks[0].part, shown);
    EXPECT_FALSE(r.faceInfoPicks[1].part.has_value()); // the corner shows no part
    const auto report = scene::faceReport(loaded.scene, shown);
    ASSERT_TRUE(report.has_value());
    EXPECT_EQ(report->face, scene::describePart(loaded.scene, shown)->face);
    EXPECT_NE(report->surface.kind, scene::SurfaceKind::Mesh);
    EXPECT_GT(report->surface.area, 0.0);
}

} // namespace
