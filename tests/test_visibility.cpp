// test_visibility.cpp - the visibility buffer (every registry row whose part is found by the
// shading pass, render/visibility.h) on lavapipe with validation on: vertex-fs's ID image byte
// for byte, and mesh-fs's colour within 1 per channel (the same meshlets: where triangles of
// one part tie in depth the same one wins, which vertex-fs's order of triangles need not
// give), on the procedural small scene with levels of detail, 2CylinderEngine, a glTF whose
// parts share vertices and an IGES file, culling off and occlusion, levels of detail off and
// at one pixel, 1x and 4x MSAA, along an orbit; then with a section plane, hidden parts, the
// exploded view and edges, and under X-ray; and its payloads numbered as shared_visibility.h
// says.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>

#include "app/headless.h"
#include "app/scene_source.h"
#include "image_compare.h"
#include "render/draw_list.h"
#include "render/technique.h"
#include "scene/lod.h"
#include "test_support.h"
#include "visibility_scenes.h"

namespace {

constexpr uint32_t W = 120, H = 80;
constexpr uint32_t NONE = gpu::BACKGROUND_ID;
using testing_support::colourDifference;
using testing_support::loadNamed;
using testing_support::sameIds;

// With `computeToo`, those with a compute rasterizer too: along the orbit its images may
// differ from the hardware's in pixels the rasterization rules explain, which
// test_compute_raster.cpp checks pixel by pixel.
std::vector<const render::Technique*> visibilityTechniques(bool computeToo = true) {
    std::vector<const render::Technique*> list;
    for (const render::Technique& t : render::techniques())
        if (t.isVisibilityBuffer() && (computeToo || !t.computeRaster)) list.push_back(&t);
    return list;
}

const render::Technique& named(const char* name) {
    const render::Technique* t = render::findTechnique(name);
    EXPECT_NE(t, nullptr) << name;
    return t ? *t : render::defaultTechnique();
}
const render::Technique& reference() {
    return named("vertex-fs");
}

// A mode whose lists the GPU culls and chooses levels in (the first mdi mode).
const render::DrawMode& gpuMode() {
    for (const render::DrawMode& m : render::drawModes())
        if (m.indirect) return m;
    return render::defaultDrawMode();
}

std::string nameOf(const render::RenderSettings& s) {
    return std::string(s.pipeline.technique->name) + " + " + s.pipeline.mode->name + ", culling " +
           render::cullModeName(s.culling.mode) + ", lod " + std::to_string(s.lod.errorPixels) +
           ", msaa " + std::to_string(s.pipeline.msaa);
}

std::vector<app::HeadlessResult::Images> framesOf(const app::HeadlessResult& r) {
    if (!r.frames.empty()) return r.frames;
    return {{r.ids, r.color}};
}

// Each visibility technique's frames against vertex-fs's IDs (two configs before it) and
// mesh-fs's colour (the config before it), within `tolerance` per channel. Returns the largest
// colour difference.
int expectAsVertexFs(const std::vector<render::RenderSettings>& configs,
                     const std::vector<app::HeadlessResult>& results, int tolerance = 1) {
    int most = 0;
    EXPECT_EQ(results.size(), configs.size());
    for (size_t c = 2; c < std::min(configs.size(), results.size()); ++c) {
        if (!configs[c].pipeline.technique->isVisibilityBuffer()) continue;
        const std::string name = nameOf(configs[c]);
        const auto frames = framesOf(results[c]), expected = framesOf(results[c - 2]);
        const auto mesh = framesOf(results[c - 1]);
        EXPECT_EQ(frames.size(), expected.size()) << name;
        EXPECT_EQ(frames.size(), mesh.size()) << name;
        for (size_t f = 0; f < std::min({frames.size(), expected.size(), mesh.size()}); ++f) {
            EXPECT_TRUE(sameIds(frames[f].ids, expected[f].ids, W)) << name << ", frame " << f;
            const auto colour = colourDifference(frames[f].color, mesh[f].color, W, tolerance);
            EXPECT_TRUE(colour.same()) << name << ", frame " << f << ": " << colour.message;
            most = std::max(most, colour.sizesDiffer ? 256 : colour.largest);
        }
    }
    return most;
}

// vertex-fs, mesh-fs and a visibility technique, each with `base`'s settings, for each
// visibility technique.
void addPair(std::vector<render::RenderSettings>& configs, const render::RenderSettings& base,
             bool computeToo = true) {
    for (const render::Technique* t : visibilityTechniques(computeToo))
        for (const render::Technique* drawn : {&reference(), &named("mesh-fs"), t}) {
            configs.push_back(base);
            configs.back().pipeline.technique = drawn;
        }
}

class VisibilityScenes : public ::testing::TestWithParam<std::string> {};

TEST_P(VisibilityScenes, DrawVertexFsImagesAlongAnOrbit) {
    ASSERT_FALSE(visibilityTechniques().empty());
    const app::LoadedScene loaded = loadNamed(GetParam());
    const scene::Camera camera = app::initialCamera(loaded, float(W) / float(H));
    std::vector<render::RenderSettings> configs;
    for (uint32_t msaa : {1u, 4u})
        for (render::CullMode cull : {render::CullMode::Off, render::CullMode::Occlusion})
            for (float lod : {0.0f, 1.0f}) {
                render::RenderSettings s = testing_support::settingsFor(reference(), gpuMode());
                s.pipeline.msaa = msaa;
                s.culling.mode = cull;
                s.lod.errorPixels = lod;
                addPair(configs, s, false);
            }
    app::Options o = testing_support::headlessOptions(W, H, 3);
    o.cameraPath = scene::CameraPath::Orbit;
    o.keepEveryFrame = true;
    const auto results = app::renderHeadlessSequence(o, loaded.scene, camera, configs);
    ASSERT_EQ(results.size(), configs.size());
    EXPECT_EQ(results.front().validationMessages, 0u);
    for (const auto& f : framesOf(results.front())) {
        const std::set<uint32_t> shown(f.ids.begin(), f.ids.end());
        EXPECT_GE(shown.size(), 5u) << "the reference shows too little to compare";
    }
    const int most = expectAsVertexFs(configs, results);
    std::printf("[ visbuf   ] %s: colour differs from mesh-fs by at most %d per channel\n",
                GetParam().c_str(), most);
}

INSTANTIATE_TEST_SUITE_P(Lavapipe, VisibilityScenes,
                         ::testing::Values("small", "engine", "shared-vertices", "cad-bearing"),
                         [](const auto& info) { return testing_support::testName(info.param); });

// A section plane through the middle (caps), hidden parts, the exploded view half open and
// edges on, at 1x and 4x with occlusion: vertex-fs's images; under X-ray (the parts outside a
// box selected in the middle drawn translucent over the shaded picture) too, and picks find
// what vertex-fs's find.
TEST(Visibility, SectionsHiddenPartsExplodeEdgesAndXrayDrawVertexFsImages) {
    const app::LoadedScene loaded = loadNamed("small");
    // Halfway to the target: the scene covers about a quarter of the image.
    scene::Camera camera = app::initialCamera(loaded, float(W) / float(H));
    camera.eye = camera.target + (camera.eye - camera.target) / 2.0;
    scene::fitPlanes(camera, loaded.scene.bounds());
    const glm::vec3 look = camera.target - camera.eye;
    const glm::vec3 size = glm::abs(look);
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
    for (bool xray : {false, true}) {
        std::vector<render::RenderSettings> configs;
        for (uint32_t msaa : {1u, 4u}) {
            render::RenderSettings s = testing_support::settingsFor(reference(), gpuMode());
            s.pipeline.msaa = msaa;
            s.edges.on = true;
            if (!xray)
                s.section.planes[0] =
                    scene::axisPlane(axis, camera.target[axis], look[axis] > 0.0f);
            addPair(configs, s);
        }
        app::Options o = testing_support::headlessOptions(W, H);
        o.hide = {0, 1, 2, 3, 40, 41};
        if (!xray) o.live.animation.explode = 0.5f;
        o.live.xray = xray;
        if (xray)
            o.selectRect = render::PartSetQuery{{W / 2 - 12, H / 2 - 8}, {W / 2 + 12, H / 2 + 8}};
        // Over the whole image; under X-ray over the selection's box, where parts can be picked.
        const uint32_t step = xray ? 4 : 8;
        for (uint32_t y = xray ? H / 2 - 8 : 4; y <= (xray ? H / 2 + 8 : H - 1); y += step)
            for (uint32_t x = xray ? W / 2 - 12 : 6; x <= (xray ? W / 2 + 12 : W - 1); x += step)
                o.picks.push_back({x, y});
        const auto results = app::renderHeadlessSequence(o, loaded.scene, camera, configs);
        ASSERT_EQ(results.size(), configs.size());
        // X-ray's layers add up over black in the 8-bit colour image, with what shows through
        // in 8-bit alpha, before the picture goes under them; over the picture, each layer
        // rounds onto it. The two orders of rounding part by up to 2 (render/visibility.h).
        const int most = expectAsVertexFs(configs, results, xray ? 2 : 1);
        for (size_t c = 2; c < configs.size(); ++c) {
            if (!configs[c].pipeline.technique->isVisibilityBuffer()) continue;
            const std::string name = nameOf(configs[c]) + (xray ? ", x-ray" : ", section");
            const app::HeadlessResult &r = results[c], &expected = results[c - 2];
            for (uint32_t hidden : o.hide)
                EXPECT_EQ(std::count(r.ids.begin(), r.ids.end(), hidden), 0) << name;
            ASSERT_EQ(r.picks.size(), expected.picks.size()) << name;
            size_t found = 0;
            for (size_t i = 0; i < r.picks.size(); ++i) {
                EXPECT_EQ(r.picks[i].part, expected.picks[i].part) << name << ", pick " << i;
                found += r.picks[i].part.has_value();
            }
            EXPECT_GE(found, 3u) << name << ": the picks found too little";
            if (xray) {
                ASSERT_TRUE(r.rectParts.has_value()) << name;
                EXPECT_TRUE(r.rectParts == expected.rectParts) << name;
            }
        }
        std::printf("[ visbuf   ] %s: colour differs from mesh-fs by at most %d per channel\n",
                    xray ? "x-ray" : "section, hidden, explode, edges", most);
    }
}

// The payloads (shared_visibility.h): every draw's meshlets numbered from a base on a meshlet
// slot, bases in draw order without overlap, and every slot of a draw's meshlets naming the
// draw; the draws' data as the mesh shader and the shading pass read it.
TEST(Visibility, PayloadsNumberEveryMeshletOfEveryDrawOnce) {
    const app::LoadedScene loaded = loadNamed("small");
    const uint32_t slot = gpu::VIS_MESHLET_PAYLOADS;
    for (const render::Technique* t : visibilityTechniques())
        for (bool levels : {false, true}) {
            render::PipelineKey key;
            key.technique = t;
            const render::DerivedGeometry derived = render::buildDerivedGeometry(loaded.scene, *t);
            const render::DrawList list =
                render::buildDrawList(loaded.scene, key, {}, derived.view(), levels);
            ASSERT_EQ(list.visibilityDraws.size(), list.ranges.size());
            ASSERT_EQ(list.meshletCounts.size(), list.ranges.size());
            ASSERT_GT(list.ranges.size(), 1u);
            uint64_t next = 0;
            for (uint32_t i = 0; i < list.ranges.size(); ++i) {
                const gpu::VisibilityDraw& d = list.visibilityDraws[i];
                EXPECT_EQ(d.triangleBase % slot, 0u);
                EXPECT_GE(d.triangleBase, next) << "draw " << i << " overlaps the one before";
                EXPECT_EQ(d.firstMeshlet, list.data[i].firstElement);
                EXPECT_EQ(d.idsOffset, list.data[i].idsOffset);
                EXPECT_EQ(d.idsWidth, list.data[i].idsWidth);
                EXPECT_EQ(d.objectIndex, list.ranges[i].object);
                EXPECT_EQ(d.lodLevel, list.ranges[i].level);
                EXPECT_EQ(d.drawIndex, i);
                for (uint32_t m = 0; m < list.meshletCounts[i]; ++m) {
                    const uint32_t s = d.triangleBase / slot + m;
                    ASSERT_LT(s, list.visibilityBlocks.size());
                    EXPECT_EQ(list.visibilityBlocks[s], i) << "meshlet " << m;
                }
                next = uint64_t(d.triangleBase) + uint64_t(list.meshletCounts[i]) * slot;
            }
        }
}

} // namespace
