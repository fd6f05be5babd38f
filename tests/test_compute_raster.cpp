// test_compute_raster.cpp - the compute rasterizer (visbuffer-compute, with --raster-all: every
// meshlet it can draw goes to raster.comp) on lavapipe with validation on, against vertex-fs's
// ID images over the visibility buffer's test scenes, culling off and occlusion, levels of
// detail 0 and 1 px, 1x and 4x, along an orbit. Every pixel where the two differ must be
// explained by a CPU rasterizer with the same rules (tests/cpu_raster.h) over the triangles of
// the two parts it shows: its sample lies within one subpixel step of an edge of one of them,
// but not on it (there the top-left rule decides, which both follow), so a vertex placed a
// rounding apart could move the edge across it; or the two parts' surfaces there lie within 2
// ulps of depth. The counts are printed; an unexplained pixel fails, and so does the top-left
// rule turned around in a copy of raster.glsl.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>

#include "app/headless.h"
#include "raster_explainer.h"
#include "render/renderer.h"
#include "render/technique.h"
#include "scene/camera_path.h"
#include "shader_copy.h"
#include "test_support.h"
#include "visibility_scenes.h"

namespace {

constexpr uint32_t W = 160, H = 120, FRAMES = 3;
using testing_support::Explainer;

const render::Technique& named(const char* name) {
    const render::Technique* t = render::findTechnique(name);
    EXPECT_NE(t, nullptr) << name;
    return t ? *t : render::defaultTechnique();
}

const render::DrawMode& gpuMode() {
    for (const render::DrawMode& m : render::drawModes())
        if (m.indirect) return m;
    return render::defaultDrawMode();
}

struct Tally {
    testing_support::Explained pixels;    // those that differ from vertex-fs's, and why
    uint64_t triangles = 0, computed = 0; // drawn, and drawn by the compute rasterizer
    // The largest difference from visbuffer's colour where the part agrees (1x), but where
    // another triangle of the part may have won by a rounding.
    int colour = 0;
};

// vertex-fs, visbuffer and visbuffer-compute (every meshlet it can draw on the compute path)
// with each of the settings, drawn with the shaders in `shaderDir` (empty: the source's).
Tally compareScene(const std::string& sceneName, const std::string& shaderDir) {
    const app::LoadedScene loaded = testing_support::loadNamed(sceneName);
    const scene::Camera start = app::initialCamera(loaded, float(W) / float(H));
    std::vector<render::RenderSettings> configs;
    for (uint32_t msaa : {1u, 4u})
        for (render::CullMode cull : {render::CullMode::Off, render::CullMode::Occlusion})
            for (float lod : {0.0f, 1.0f})
                for (const char* technique : {"vertex-fs", "visbuffer", "visbuffer-compute"}) {
                    render::RenderSettings s =
                        testing_support::settingsFor(named(technique), gpuMode());
                    s.pipeline.msaa = msaa;
                    s.culling.mode = cull;
                    s.lod.errorPixels = lod;
                    s.raster.all = true;
                    configs.push_back(s);
                }
    app::Options o = testing_support::headlessOptions(W, H, FRAMES);
    o.cameraPath = scene::CameraPath::Orbit;
    o.keepEveryFrame = true;
    if (!shaderDir.empty()) o.shaderDir = shaderDir;
    const auto results = app::renderHeadlessSequence(o, loaded.scene, start, configs);
    EXPECT_EQ(results.size(), configs.size());
    Tally tally;
    for (size_t c = 2; c < results.size(); c += 3) {
        EXPECT_EQ(results[c].validationMessages, 0u);
        for (const gpu::CullStats& stats : results[c].cullStats) {
            const render::CullCounts counts = render::countsOf(stats, true);
            EXPECT_GT(counts.computeTriangles, 0u) << "config " << c << " drew nothing in compute";
            tally.triangles += counts.triangles;
            tally.computed += counts.computeTriangles;
        }
        const auto &frames = results[c].frames, &expected = results[c - 2].frames;
        const auto& hardware = results[c - 1].frames; // the same shading, no compute path
        EXPECT_EQ(frames.size(), size_t(FRAMES));
        EXPECT_EQ(expected.size(), size_t(FRAMES));
        for (size_t f = 0; f < std::min(frames.size(), expected.size()); ++f) {
            const scene::Camera camera = scene::cameraOnPath(
                o.cameraPath, start, loaded.scene.bounds(), uint32_t(f), FRAMES);
            const Explainer explainer(loaded.scene, camera, {W, H}, configs[c].pipeline.msaa);
            for (uint32_t y = 0; y < H; ++y)
                for (uint32_t x = 0; x < W; ++x) {
                    const uint32_t a = expected[f].ids[size_t(y) * W + x];
                    const uint32_t b = frames[f].ids[size_t(y) * W + x];
                    // At 1x a pixel is its one sample: where the three agree on the part, so
                    // does colour, but where a triangle of the same part won the sample (a
                    // rounding apart).
                    if (a == b && configs[c].pipeline.msaa == 1 && f < hardware.size() &&
                        hardware[f].ids[size_t(y) * W + x] == a) {
                        int most = 0;
                        for (size_t k = 0; k < 4; ++k) {
                            const size_t i = (size_t(y) * W + x) * 4 + k;
                            most = std::max(most, std::abs(int(frames[f].color[i]) -
                                                           int(hardware[f].color[i])));
                        }
                        if (most > 1 &&
                            explainer.explain(x, y, a, a) == Explainer::Why::Unexplained)
                            tally.colour = std::max(tally.colour, most);
                    }
                    if (a == b) continue;
                    const Explainer::Why why = explainer.explain(x, y, a, b);
                    tally.pixels.add(why);
                    if (why == Explainer::Why::Unexplained)
                        std::printf("[ compute  ] %s, config %zu, frame %zu: (%u, %u) shows %u "
                                    "where vertex-fs shows %u, unexplained\n",
                                    sceneName.c_str(), c, f, x, y, b, a);
                }
        }
    }
    return tally;
}

class ComputeRasterScenes : public ::testing::TestWithParam<std::string> {};

TEST_P(ComputeRasterScenes, DrawVertexFsIdImagesButForExplainedPixels) {
    const Tally t = compareScene(GetParam(), "");
    std::printf(
        "[ compute  ] %s: %.1f %% of the triangles drawn in compute; %zu pixels differ "
        "from vertex-fs over 16 configurations x %u frames: %zu within a subpixel step "
        "of an edge, %zu within 2 ulps of depth, %zu unexplained; colour within %d of "
        "visbuffer's elsewhere where the part agrees (1x)\n",
        GetParam().c_str(), 100.0 * double(t.computed) / double(std::max<uint64_t>(t.triangles, 1)),
        t.pixels.differ, FRAMES, t.pixels.nearEdge, t.pixels.depth, t.pixels.unexplained, t.colour);
    EXPECT_EQ(t.pixels.unexplained, 0u);
    EXPECT_LE(t.colour, 1) << "colour where the part agrees, 1x";
}

INSTANTIATE_TEST_SUITE_P(Lavapipe, ComputeRasterScenes,
                         ::testing::Values("small", "engine", "shared-vertices", "cad-bearing"),
                         [](const auto& info) { return testing_support::testName(info.param); });

// The top-left rule turned around in raster.glsl: pixels the rules do not explain.
TEST(ComputeRaster, TheBottomRightRuleIsCaught) {
    const std::filesystem::path dir =
        testing_support::shaderCopy("compute-raster-" + std::to_string(getpid()));
    testing_support::replaceInFile(dir / "raster.glsl", "return d.y < 0 || (d.y == 0 && d.x > 0);",
                                   "return !(d.y < 0 || (d.y == 0 && d.x > 0));");
    const Tally t = compareScene("small", dir.string());
    std::printf("[ compute  ] the bottom-right rule: %zu pixels differ, %zu unexplained\n",
                t.pixels.differ, t.pixels.unexplained);
    EXPECT_GT(t.pixels.unexplained, 0u) << "the turned rule drew nothing the rules cannot explain";
    std::filesystem::remove_all(dir);
}

} // namespace
