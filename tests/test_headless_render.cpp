// test_headless_render.cpp - renders on lavapipe with validation on and checks the ID image
// pixel by pixel against a CPU ray cast, and that the check itself catches one wrong part.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <unistd.h>

#include "app/headless.h"
#include "app/scene_source.h"
#include "image_compare.h"
#include "scene/procedural/generator.h"
#include "scene/raycast.h"
#include "test_data.h"
#include "test_support.h"

namespace fs = std::filesystem;
using app::HeadlessResult;

namespace {

app::Options testOptions(uint32_t width, uint32_t height) {
    // More frames than are in flight, so slots are reused.
    return testing_support::headlessOptions(width, height, 3);
}

// Every render of these tests goes through here: any validation message fails the test.
HeadlessResult renderChecked(const app::Options& o, const scene::Scene& s, const scene::Camera& c) {
    HeadlessResult r = app::renderHeadless(o, s, c);
    EXPECT_EQ(r.validationMessages, 0u) << "validation messages (printed above)";
    return r;
}

// The part the CPU sees at a pixel centre, or nothing when the pixel is near an edge: there
// the rasteriser's fixed-point snapping may decide either way, so no exact answer exists.
std::optional<uint32_t> stableReference(const scene::RayCaster& caster, const glm::mat4& viewProj,
                                        glm::vec2 size, uint32_t x, uint32_t y) {
    const glm::vec2 offsets[] = {
        {0.5f, 0.5f}, {0.2f, 0.2f}, {0.8f, 0.2f}, {0.2f, 0.8f}, {0.8f, 0.8f}};
    std::optional<uint32_t> first;
    for (size_t i = 0; i < std::size(offsets); ++i) {
        auto hit = caster.cast(scene::pixelRay(viewProj, size, glm::vec2(x, y) + offsets[i]));
        uint32_t id = hit ? hit->uniquePartId : gpu::BACKGROUND_ID;
        if (i == 0)
            first = id;
        else if (id != *first)
            return std::nullopt;
    }
    return first;
}

struct Comparison {
    size_t compared = 0, mismatches = 0;
    std::map<uint32_t, size_t> comparedPerId;
    std::set<uint32_t> wrongReferenceIds; // reference IDs of mismatching pixels
};

Comparison compareWithRaycast(const HeadlessResult& r, const scene::Scene& s,
                              const scene::Camera& camera, uint32_t step) {
    const glm::vec2 size(r.width, r.height);
    const glm::dmat4 viewProj = camera.viewProjection(size.x / size.y);
    const scene::RayCaster caster(s);
    Comparison c;
    for (uint32_t y = 0; y < r.height; y += step)
        for (uint32_t x = 0; x < r.width; x += step) {
            auto expected = stableReference(caster, viewProj, size, x, y);
            if (!expected) continue;
            c.compared++;
            c.comparedPerId[*expected]++;
            if (r.ids[size_t(y) * r.width + x] != *expected) {
                c.mismatches++;
                c.wrongReferenceIds.insert(*expected);
            }
        }
    return c;
}

class HeadlessRender : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        tiles = new scene::Scene(scene::makeTiles());
        tilesResult =
            new HeadlessResult(renderChecked(testOptions(320, 200), *tiles, scene::tilesCamera()));
    }
    static void TearDownTestSuite() {
        delete tiles;
        delete tilesResult;
    }
    static scene::Scene* tiles;
    static HeadlessResult* tilesResult;
};
scene::Scene* HeadlessRender::tiles = nullptr;
HeadlessResult* HeadlessRender::tilesResult = nullptr;

} // namespace

TEST_F(HeadlessRender, ValidationStaysSilent) {
    EXPECT_EQ(tilesResult->validationMessages, 0u);
    EXPECT_EQ(tilesResult->stats.draws, 25u); // per-draw: one draw per part
    EXPECT_EQ(tilesResult->gpuMs.size(), 3u);
}

TEST_F(HeadlessRender, TilesIdImageMatchesCpuRaycastAtEveryStablePixel) {
    Comparison c = compareWithRaycast(*tilesResult, *tiles, scene::tilesCamera(), 1);
    EXPECT_EQ(c.mismatches, 0u);
    EXPECT_GT(c.compared, 320u * 200u * 9 / 10); // edges are a small fraction of the image
    // Every part is visible by construction and was checked on many pixels, and so was the
    // background around the back plate.
    for (uint32_t id = 0; id < tiles->uniquePartCount(); ++id)
        EXPECT_GT(c.comparedPerId[id], 40u) << "part " << id;
    EXPECT_GT(c.comparedPerId[gpu::BACKGROUND_ID], 1000u);
}

TEST_F(HeadlessRender, TilesIdImageHoldsExactlyTheVisibleParts) {
    std::set<uint32_t> seen(tilesResult->ids.begin(), tilesResult->ids.end());
    std::set<uint32_t> expected = {gpu::BACKGROUND_ID};
    for (uint32_t id = 0; id < 25; ++id) expected.insert(id);
    EXPECT_EQ(seen, expected);
    // Pixel centres of known places: the image centre falls between the two sheets, on the
    // back plate; the first sheet's lower left tile covers the pixel where (-3.6, 0, 0) lands.
    const glm::dmat4 viewProj = scene::tilesCamera().viewProjection(320.0f / 200.0f);
    auto idAt = [&](glm::vec3 p) {
        glm::vec4 clip = viewProj * glm::vec4(p, 1);
        glm::vec2 px = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(320, 200);
        return tilesResult->ids[size_t(px.y) * 320 + size_t(px.x)];
    };
    EXPECT_EQ(idAt({0, 1.0f, 0}), 24u);
    EXPECT_EQ(idAt({-3.6f, 0.0f, 0}), 0u);
    EXPECT_EQ(idAt({3.6f, 2.0f, 0}), 23u);
    EXPECT_EQ(tilesResult->ids[0], gpu::BACKGROUND_ID);
}

TEST_F(HeadlessRender, ColourImageIsNotBlank) {
    const auto& r = *tilesResult;
    auto rgba = [&](size_t i) {
        return uint32_t(r.color[4 * i]) | uint32_t(r.color[4 * i + 1]) << 8 |
               uint32_t(r.color[4 * i + 2]) << 16 | uint32_t(r.color[4 * i + 3]) << 24;
    };
    const uint32_t background = rgba(0);
    std::set<uint32_t> partColours;
    for (size_t i = 0; i < r.ids.size(); ++i) {
        if (r.ids[i] == gpu::BACKGROUND_ID) {
            ASSERT_EQ(rgba(i), background) << "pixel " << i;
        } else {
            ASSERT_NE(rgba(i), background) << "pixel " << i;
            partColours.insert(rgba(i));
        }
    }
    EXPECT_GE(partColours.size(), 20u); // parts get their own colours
}

// The comparison above must catch a part drawn with a wrong ID: a shader that reports part 5
// of each object as part 6 has to produce mismatches on exactly the pixels of those parts.
TEST(HeadlessRenderCheck, OneWrongPartIdIsCaught) {
    fs::path dir = fs::temp_directory_path() / ("idview-wrong-id-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::copy(IDVIEW_SOURCE_SHADER_DIR, dir, fs::copy_options::recursive);
    std::ofstream(dir / "techniques/per_draw.glsl")
        << "uint lookupLocalPart(FrameData f, DrawData d, uint primitive) {\n"
           "    return d.firstPart == 5u ? 6u : d.firstPart;\n}\n";
    app::Options o = testOptions(320, 200);
    o.shaderDir = dir.string();
    scene::Scene s = scene::makeTiles();
    HeadlessResult r = renderChecked(o, s, scene::tilesCamera());
    fs::remove_all(dir);
    Comparison c = compareWithRaycast(r, s, scene::tilesCamera(), 1);
    EXPECT_EQ(c.wrongReferenceIds, (std::set<uint32_t>{5u, 12u + 5u}));
    EXPECT_EQ(c.mismatches, c.comparedPerId[5] + c.comparedPerId[17]);
    EXPECT_EQ(r.validationMessages, 0u);
}

TEST(HeadlessRenderAssembly, IdsNamePartsAndAgreeWithRaycast) {
    scene::Scene s = scene::makeAssembly();
    app::Options o = testOptions(256, 160);
    app::LoadedScene loaded;
    loaded.scene = s;
    loaded.source = "assembly";
    scene::Camera camera = app::initialCamera(loaded, 256.0f / 160.0f);
    HeadlessResult r = renderChecked(o, s, camera);
    EXPECT_EQ(r.validationMessages, 0u);
    EXPECT_EQ(r.stats.draws, s.uniquePartCount());
    std::set<uint32_t> seen;
    for (uint32_t id : r.ids) {
        if (id == gpu::BACKGROUND_ID) continue;
        ASSERT_TRUE(s.locate(id)) << "ID " << id << " names no part";
        seen.insert(id);
    }
    EXPECT_GT(seen.size(), 60u); // bolt heads, plates, columns, brackets
    Comparison c = compareWithRaycast(r, s, camera, 2);
    EXPECT_EQ(c.mismatches, 0u);
    EXPECT_GT(c.compared, 256u * 160u / 4 * 8 / 10);
}

TEST(HeadlessRenderAssembly, ShadingOptionsChangeColoursButNotIds) {
    scene::Scene s = scene::makeTiles();
    app::Options plain = testOptions(160, 100);
    plain.live.render.shading.partWeight = 0.0f;
    app::Options colorized = plain;
    colorized.live.render.shading.colorizeDraws = true;
    HeadlessResult a = renderChecked(plain, s, scene::tilesCamera());
    HeadlessResult b = renderChecked(colorized, s, scene::tilesCamera());
    EXPECT_TRUE(testing_support::sameIds(a.ids, b.ids, plain.width));
    EXPECT_FALSE(testing_support::sameColours(a.color, b.color, plain.width));
    // Part weight 0 with one grey material: every part pixel is grey (R = G = B), while the
    // colorized draws and the default weight give coloured parts.
    auto greyParts = [](const HeadlessResult& r) {
        size_t grey = 0, parts = 0;
        for (size_t i = 0; i < r.ids.size(); ++i) {
            if (r.ids[i] == gpu::BACKGROUND_ID) continue;
            parts++;
            const uint8_t* c = &r.color[4 * i];
            grey += c[0] == c[1] && c[1] == c[2];
        }
        return std::pair(grey, parts);
    };
    auto [grey, parts] = greyParts(a);
    EXPECT_GT(parts, 0u);
    EXPECT_EQ(grey, parts);
    EXPECT_LT(greyParts(b).first, greyParts(b).second / 10);
}

// Scenes from the generator and from a real glTF file go through the same check.
namespace {

void expectIdsMatchRaycast(const app::LoadedScene& loaded, uint32_t width, uint32_t height,
                           size_t minimumParts, const app::CameraSettings& view = {}) {
    const scene::Camera camera = app::initialCamera(loaded, float(width) / float(height), view);
    HeadlessResult r = renderChecked(testOptions(width, height), loaded.scene, camera);
    std::set<uint32_t> seen;
    for (uint32_t id : r.ids)
        if (id != gpu::BACKGROUND_ID) {
            ASSERT_TRUE(loaded.scene.locate(id)) << "ID " << id << " names no part";
            seen.insert(id);
        }
    EXPECT_GE(seen.size(), minimumParts);
    Comparison c = compareWithRaycast(r, loaded.scene, camera, 3);
    EXPECT_EQ(c.mismatches, 0u);
    EXPECT_GT(c.compared, size_t(width / 3) * (height / 3) / 2);
}

} // namespace

TEST(HeadlessRenderScenes, ProceduralSmallAgreesWithRaycast) {
    app::SceneSettings source;
    source.builtin = "procedural:preset=small,seed=3";
    expectIdsMatchRaycast(app::loadScene(source), 192, 120, 100);
}

TEST(HeadlessRenderScenes, EngineFromGltfInComponentsModeAgreesWithRaycast) {
    app::SceneSettings source;
    source.model = testing_support::requiredData(
        "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
    // 1,410 parts instead of 115: many more borders to get right.
    source.parts = scene::PartMode::Components;
    expectIdsMatchRaycast(app::loadScene(source), 192, 120, 100);
}

// Orthographic views and the standard views: the ID image against the ray cast through the
// same camera (parallel rays in ortho), pixel by pixel, from three sides.
TEST(HeadlessRenderScenes, StandardViewsInBothProjectionsAgreeWithRaycast) {
    app::SceneSettings source;
    source.builtin = "procedural:preset=small,seed=3";
    const app::LoadedScene loaded = app::loadScene(source);
    for (const auto& [name, ortho] : {std::pair("isometric", true), std::pair("top", true),
                                      std::pair("front", false), std::pair("left", true)}) {
        SCOPED_TRACE(std::string(name) + (ortho ? " ortho" : ""));
        expectIdsMatchRaycast(loaded, 192, 120, 30, {scene::findStandardView(name), ortho});
    }
}

// The headlight follows the projection (prelude.glsl's toViewer): in ortho every point is lit
// from the view's one direction, so the flat tiles and plate, all facing the camera in one
// grey material, come out one colour; in perspective the light's angle changes across them.
TEST(HeadlessRenderScenes, OrthoLightsEveryPointFromTheViewsDirection) {
    const scene::Scene s = scene::makeTiles();
    app::Options o = testOptions(160, 100);
    o.live.render.shading.partWeight = 0.0f;
    scene::Camera camera = scene::tilesCamera();
    auto colours = [&](bool ortho) {
        camera.ortho = ortho;
        scene::fitPlanes(camera, s.bounds());
        const HeadlessResult r = renderChecked(o, s, camera);
        std::set<std::array<uint8_t, 3>> seen;
        for (size_t i = 0; i < r.ids.size(); ++i)
            if (r.ids[i] != gpu::BACKGROUND_ID)
                seen.insert({r.color[4 * i], r.color[4 * i + 1], r.color[4 * i + 2]});
        return seen.size();
    };
    EXPECT_EQ(colours(true), 1u);
    EXPECT_GT(colours(false), 5u);
}

// An STL file's solids are objects of one part each: the ID image holds exactly both
// triangles' IDs (and the background), and a real model agrees with the ray cast.
TEST(HeadlessRenderScenes, StlSolidsDrawTheirPartsAndAgreeWithRaycast) {
    app::SceneSettings source;
    source.model =
        testing_support::requiredData("/usr/share/assimp/models/STL/triangle_with_two_solids.stl");
    const app::LoadedScene two = app::loadScene(source);
    const scene::Camera camera = app::initialCamera(two, 160.0f / 100.0f);
    const HeadlessResult r = renderChecked(testOptions(160, 100), two.scene, camera);
    const std::set<uint32_t> seen(r.ids.begin(), r.ids.end());
    EXPECT_EQ(seen, (std::set<uint32_t>{0, 1, gpu::BACKGROUND_ID}));
    source.model = "/usr/share/opencascade/data/stl/bearing.stl";
    expectIdsMatchRaycast(app::loadScene(source), 160, 100, 1);
}
