// test_clear_paths.cpp - the two ways a frame starts and resolves (render::ClearPath, issue 37)
// draw the same pictures, on lavapipe with validation on: every technique x mode, culling off
// and occlusion, 1x and 4x MSAA, and with levels of detail, section planes, hidden parts,
// X-ray and edges, give the same ID image byte for byte and colour within 1 per channel on
// the pass path and the compute path; on each path the techniques agree and culling draws
// culling off's images; background is the clear colour and no part, a covered pixel the part
// a CPU ray cast finds; and the renderer says which path it drew with.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>

#include "app/camera_frame.h"
#include "app/headless.h"
#include "app/offscreen.h"
#include "app/scene_source.h"
#include "image_compare.h"
#include "raster_explainer.h"
#include "render/culling.h"
#include "render/technique.h"
#include "scene/camera_path.h"
#include "scene/lod.h"
#include "scene/raycast.h"
#include "test_support.h"

namespace {

constexpr uint32_t W = 96, H = 64;
constexpr uint32_t NONE = gpu::BACKGROUND_ID;
using render::ClearPath;
using testing_support::colourDifference;
using testing_support::sameColours;
using testing_support::sameIds;
// Each test renders every case on both paths, the pass path first.
constexpr std::array<ClearPath, 2> kPaths = {ClearPath::Pass, ClearPath::Compute};
// The background colour (render::backgroundColor) as the UNORM colour image holds it.
const std::array<int, 4> kBackground = {int(std::lround(render::backgroundColor.r * 255.0f)),
                                        int(std::lround(render::backgroundColor.g * 255.0f)),
                                        int(std::lround(render::backgroundColor.b * 255.0f)),
                                        int(std::lround(render::backgroundColor.a * 255.0f))};

app::LoadedScene smallScene(uint32_t lodLevels = 1) {
    app::SceneSettings source;
    source.builtin = "procedural:preset=small,seed=1";
    source.copies = 2;
    source.lodLevels = lodLevels;
    return app::loadScene(source);
}

// The opening view with the camera halfway to its target: the small scene then covers about a
// quarter of the image.
scene::Camera closeCamera(const app::LoadedScene& loaded) {
    scene::Camera camera = app::initialCamera(loaded, float(W) / float(H));
    camera.eye = camera.target + (camera.eye - camera.target) / 2.0;
    scene::fitPlanes(camera, loaded.scene.bounds());
    return camera;
}

std::string nameOf(const render::RenderSettings& s) {
    return std::string(s.pipeline.technique->name) + " + " + s.pipeline.mode->name + ", culling " +
           render::cullModeName(s.culling.mode) + ", msaa " + std::to_string(s.pipeline.msaa);
}

// `configs` rendered on each path in turn (kPaths' order), each path by a renderer of its own.
std::array<std::vector<app::HeadlessResult>, 2>
renderOnBothPaths(const app::Options& options, const scene::Scene& scene,
                  const scene::Camera& camera, std::vector<render::RenderSettings> configs) {
    std::array<std::vector<app::HeadlessResult>, 2> results;
    for (size_t p = 0; p < kPaths.size(); ++p) {
        for (render::RenderSettings& s : configs) s.clear = kPaths[p];
        results[p] = app::renderHeadlessSequence(options, scene, camera, configs);
        EXPECT_EQ(results[p].size(), configs.size());
        EXPECT_EQ(results[p].front().validationMessages, 0u)
            << render::clearPathName(kPaths[p]) << " path";
    }
    return results;
}

// Every frame a result kept (Options::keepEveryFrame), or its last.
std::vector<app::HeadlessResult::Images> framesOf(const app::HeadlessResult& r) {
    if (!r.frames.empty()) return r.frames;
    return {{r.ids, r.color}};
}

// The compute path's frames against the pass path's: the same IDs byte for byte (where the
// technique writes IDs: `ids`) and colour within 1 per channel. Returns the largest colour
// difference seen.
int expectSameImages(const app::HeadlessResult& pass, const app::HeadlessResult& compute, bool ids,
                     const std::string& name) {
    const auto passFrames = framesOf(pass), computeFrames = framesOf(compute);
    EXPECT_EQ(computeFrames.size(), passFrames.size()) << name;
    int most = 0;
    for (size_t f = 0; f < std::min(passFrames.size(), computeFrames.size()); ++f) {
        if (ids) {
            EXPECT_TRUE(sameIds(computeFrames[f].ids, passFrames[f].ids, W))
                << name << ", frame " << f;
        }
        const auto colour = colourDifference(computeFrames[f].color, passFrames[f].color, W, 1);
        EXPECT_TRUE(colour.same()) << name << ", frame " << f << ": " << colour.message;
        most = std::max(most, colour.sizesDiffer ? 256 : colour.largest);
    }
    return most;
}

// expectSameImages for every case (IDs included: the floors' are background on both paths);
// the largest colour difference among them.
int expectSameImagesInEveryCase(const std::array<std::vector<app::HeadlessResult>, 2>& results,
                                const std::vector<render::RenderSettings>& configs) {
    int most = 0;
    for (size_t c = 0; c < configs.size(); ++c)
        most = std::max(most,
                        expectSameImages(results[0][c], results[1][c], true, nameOf(configs[c])));
    return most;
}

void reportColourDifference(const char* test, int most) {
    std::printf("[ clear    ] %s: colour differs by at most %d per channel between the paths\n",
                test, most);
}

class EveryTechnique : public ::testing::TestWithParam<uint32_t> {}; // MSAA samples

// Every technique of the registry (the floors' colour alone: they write no IDs) in every mode,
// culling off and occlusion, on the two frames of an orbit (the view from the other side, whose
// occlusion test uses the first frame's history): the paths give the same images; on each path
// every part-ID technique draws per-draw + push's ID image and occlusion culling draws culling
// off's images byte for byte, as the culling and technique tests check on the default path.
TEST_P(EveryTechnique, BothPathsDrawTheSameImagesAndEachAgreesWithItself) {
    const uint32_t msaa = GetParam();
    const app::LoadedScene loaded = smallScene();
    const scene::Camera camera = closeCamera(loaded);
    std::vector<render::RenderSettings> configs;
    for (const render::Technique& t : render::techniques())
        for (const render::DrawMode& m : render::drawModes())
            for (render::CullMode cull : {render::CullMode::Off, render::CullMode::Occlusion}) {
                configs.push_back(testing_support::settingsFor(t, m));
                configs.back().culling.mode = cull;
                configs.back().pipeline.msaa = msaa;
            }
    ASSERT_FALSE(configs.front().pipeline.technique->isFloor()); // the reference writes IDs
    app::Options o = testing_support::headlessOptions(W, H, 2);
    o.cameraPath = scene::CameraPath::Orbit;
    o.keepEveryFrame = true;
    const auto results = renderOnBothPaths(o, loaded.scene, camera, configs);
    ASSERT_EQ(results[1].size(), configs.size());

    const int most = expectSameImagesInEveryCase(results, configs);
    reportColourDifference("every technique", most);

    for (size_t p = 0; p < kPaths.size(); ++p) {
        const auto reference = framesOf(results[p].front());
        ASSERT_EQ(reference.size(), 2u);
        for (const auto& f : reference) {
            const std::set<uint32_t> shown(f.ids.begin(), f.ids.end());
            EXPECT_GE(shown.size(), 20u) << "the reference shows too little to compare";
            EXPECT_TRUE(shown.count(NONE)) << "the reference shows no background";
        }
        for (size_t c = 0; c < configs.size(); ++c) {
            const std::string name =
                nameOf(configs[c]) + " on the " + render::clearPathName(kPaths[p]) + " path";
            const auto frames = framesOf(results[p][c]);
            ASSERT_EQ(frames.size(), reference.size()) << name;
            // Culling off is the config before occlusion's.
            const auto off = c % 2 ? framesOf(results[p][c - 1]) : frames;
            const bool floor = configs[c].pipeline.technique->isFloor();
            for (size_t f = 0; f < frames.size(); ++f) {
                if (floor) {
                    EXPECT_EQ(std::count(frames[f].ids.begin(), frames[f].ids.end(), NONE),
                              ptrdiff_t(frames[f].ids.size()))
                        << name << ", frame " << f << ": a floor's ID image is all background";
                } else {
                    const scene::Camera at = scene::cameraOnPath(
                        o.cameraPath, camera, loaded.scene.bounds(), uint32_t(f), 2);
                    EXPECT_TRUE(testing_support::sameIdsAs(
                        *configs[c].pipeline.technique, frames[f].ids, reference[f].ids,
                        loaded.scene, at, {W, H}, configs[c].pipeline.msaa))
                        << name << ", frame " << f;
                    EXPECT_TRUE(sameIds(frames[f].ids, off[f].ids, W)) << name << ", frame " << f;
                }
                EXPECT_TRUE(sameColours(frames[f].color, off[f].color, W))
                    << name << ", frame " << f;
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(ClearPaths, EveryTechnique, ::testing::Values(1u, 4u),
                         [](const auto& info) { return "msaa" + std::to_string(info.param); });

// The default technique and a mesh technique in a mode whose GPU lists choose levels, at 1x
// and 4x: `configure` changes each one.
std::vector<render::RenderSettings> featureConfigs() {
    std::vector<render::RenderSettings> configs;
    const render::DrawMode* gpuMode = nullptr;
    for (const render::DrawMode& m : render::drawModes())
        if (!gpuMode &&
            render::cullPlan(render::defaultTechnique(), m, render::CullMode::Occlusion).gpuLists)
            gpuMode = &m;
    const render::Technique* mesh = nullptr;
    for (const render::Technique* t : render::partIdTechniques())
        if (!mesh && t->usesMeshShader()) mesh = t;
    EXPECT_TRUE(gpuMode && mesh);
    if (!gpuMode || !mesh) return configs;
    for (uint32_t msaa : {1u, 4u})
        for (const render::Technique* t : {&render::defaultTechnique(), mesh}) {
            configs.push_back(testing_support::settingsFor(*t, *gpuMode));
            configs.back().pipeline.msaa = msaa;
            configs.back().culling.mode = render::CullMode::Occlusion;
            configs.back().edges.on = true;
        }
    return configs;
}

// Levels of detail chosen at a one-pixel error with occlusion culling, a section plane through
// the middle, some parts hidden and edges on, along three frames of a dolly path: the same
// images on both paths. Each feature is seen to act, so the comparison covers it.
TEST(ClearPaths, LevelsSectionsHiddenPartsAndEdgesDrawTheSameImages) {
    const app::LoadedScene loaded = smallScene(scene::maxLevels);
    const scene::Camera camera = closeCamera(loaded);
    std::vector<render::RenderSettings> configs = featureConfigs();
    ASSERT_FALSE(configs.empty());
    const glm::vec3 look = camera.target - camera.eye;
    const glm::vec3 size = glm::abs(look);
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
    for (render::RenderSettings& s : configs) {
        s.lod.errorPixels = 1.0f;
        s.section.planes[0] = scene::axisPlane(axis, camera.target[axis], look[axis] > 0.0f);
    }
    // The first uncut, to see that the plane cuts something.
    configs.push_back(configs.front());
    configs.back().section = {};
    app::Options o = testing_support::headlessOptions(W, H, 3);
    o.cameraPath = scene::CameraPath::Dolly;
    o.keepEveryFrame = true;
    o.hide = {0, 1, 2, 3, 40, 41};
    const auto results = renderOnBothPaths(o, loaded.scene, camera, configs);
    ASSERT_EQ(results[1].size(), configs.size());

    const int most = expectSameImagesInEveryCase(results, configs);
    for (size_t c = 0; c < configs.size(); ++c) {
        const std::string name = nameOf(configs[c]);
        for (size_t p = 0; p < kPaths.size(); ++p) {
            const app::HeadlessResult& r = results[p][c];
            for (uint32_t hidden : o.hide)
                EXPECT_EQ(std::count(r.ids.begin(), r.ids.end(), hidden), 0) << name;
            uint64_t coarser = 0;
            const bool mesh = configs[c].pipeline.technique->usesMeshShader();
            for (const gpu::CullStats& stats : r.cullStats) {
                const render::CullCounts counts = render::countsOf(stats, mesh);
                for (size_t l = 1; l < counts.levelTriangles.size(); ++l)
                    coarser += counts.levelTriangles[l];
            }
            EXPECT_GT(coarser, 0u) << name << ": no coarser level drawn";
        }
    }
    EXPECT_FALSE(sameIds(results[0].back().ids, results[0].front().ids, W))
        << "the plane cut nothing";
    reportColourDifference("levels, section, hidden, edges", most);
}

// X-ray: the parts in a box in the middle selected (a part set pass over the ID image), the
// rest drawn translucent, a few hidden, edges on, picks in the middle and on background, the
// visible parts counted, under synchronization validation (the resolve's barriers): the same
// images, selection, picks, hovers and visible parts on both paths, and on each only the
// selection in the ID image.
TEST(ClearPaths, XrayPicksAndPartSetsAreTheSameOnBothPaths) {
    const app::LoadedScene loaded = smallScene();
    const scene::Camera camera = closeCamera(loaded);
    const std::vector<render::RenderSettings> configs = featureConfigs();
    ASSERT_FALSE(configs.empty());
    app::Options o = testing_support::headlessOptions(W, H);
    o.selectRect = render::PartSetQuery{{W / 2 - 10, H / 2 - 6}, {W / 2 + 10, H / 2 + 6}};
    o.live.xray = true;
    o.hide = {0, 1, 2, 3, 40, 41};
    // Background, then points in the box: some of them on the selection.
    o.picks = {{0, 0}};
    for (uint32_t y = H / 2 - 6; y <= H / 2 + 6; y += 6)
        for (uint32_t x = W / 2 - 10; x <= W / 2 + 10; x += 10) o.picks.push_back({x, y});
    o.visibleParts = true;
    o.syncValidation = true;
    const auto results = renderOnBothPaths(o, loaded.scene, camera, configs);
    ASSERT_EQ(results[1].size(), configs.size());
    const int most = expectSameImagesInEveryCase(results, configs);
    for (size_t c = 0; c < configs.size(); ++c) {
        const std::string name = nameOf(configs[c]);
        for (size_t p = 0; p < kPaths.size(); ++p) {
            const app::HeadlessResult& r = results[p][c];
            ASSERT_TRUE(r.rectParts.has_value()) << name;
            EXPECT_GE(r.rectParts->size(), 2u) << name;
            size_t selected = 0, others = 0;
            for (uint32_t id : r.ids) {
                selected += id != NONE && r.rectParts->contains(id);
                others += id != NONE && !r.rectParts->contains(id);
            }
            EXPECT_GT(selected, 50u) << name;
            EXPECT_EQ(others, 0u) << name;
            ASSERT_EQ(r.picks.size(), o.picks.size()) << name;
            EXPECT_FALSE(r.picks.front().part.has_value()) << name << ": background picked";
            EXPECT_GE(std::count_if(r.picks.begin(), r.picks.end(),
                                    [](const render::PickReading& pick) { return pick.part; }),
                      3)
                << name << ": the box's picks found too little";
        }
        const app::HeadlessResult &pass = results[0][c], &compute = results[1][c];
        EXPECT_TRUE(compute.rectParts == pass.rectParts) << name;
        ASSERT_EQ(compute.picks.size(), pass.picks.size()) << name;
        ASSERT_EQ(compute.hovers.size(), pass.hovers.size()) << name;
        for (size_t i = 0; i < pass.picks.size(); ++i) {
            EXPECT_EQ(compute.picks[i].part, pass.picks[i].part) << name << ", pick " << i;
            EXPECT_EQ(compute.picks[i].depth, pass.picks[i].depth) << name << ", pick " << i;
            EXPECT_EQ(compute.hovers[i].part, pass.hovers[i].part) << name << ", hover " << i;
        }
        EXPECT_TRUE(compute.visibleParts == pass.visibleParts) << name;
        EXPECT_EQ(compute.visibleCount, pass.visibleCount) << name;
        EXPECT_GT(pass.visibleCount, 2u) << name;
    }
    reportColourDifference("X-ray", most);
}

// Sample 0's place in a pixel and the other samples' (Vulkan's standard locations).
std::vector<glm::dvec2> samplesOf(uint32_t msaa) {
    if (msaa == 4) return {{0.375, 0.125}, {0.875, 0.375}, {0.125, 0.625}, {0.625, 0.875}};
    return {{0.5, 0.5}};
}

// What the CPU ray cast sees at pixel (x, y) where the answer does not hang on where exactly one
// looks: the part at sample 0 when points around it (and no second part at the same depth)
// agree; NONE when no sample of the pixel, nor its corners, meets a part; nullopt otherwise.
std::optional<uint32_t> stableSeen(const scene::RayCaster& caster, const glm::dmat4& viewProj,
                                   uint32_t x, uint32_t y, uint32_t msaa, uint32_t partCount) {
    const glm::dvec2 pixel(x, y), size(W, H);
    auto cast = [&](glm::dvec2 at) {
        return caster.cast(scene::pixelRay(viewProj, size, pixel + at));
    };
    const glm::dvec2 zero = samplesOf(msaa).front();
    const auto hit = cast(zero);
    if (!hit) {
        std::vector<glm::dvec2> probes = samplesOf(msaa);
        probes.insert(probes.end(), {{0.02, 0.02}, {0.98, 0.02}, {0.02, 0.98}, {0.98, 0.98}});
        for (glm::dvec2 at : probes)
            if (cast(at)) return std::nullopt;
        return NONE;
    }
    for (glm::dvec2 step :
         {glm::dvec2(0.15, 0), glm::dvec2(-0.15, 0), glm::dvec2(0, 0.15), glm::dvec2(0, -0.15)}) {
        const auto near = cast(zero + step);
        if (!near || near->uniquePartId != hit->uniquePartId) return std::nullopt;
    }
    scene::PartSet nearest(partCount);
    nearest.insert(hit->uniquePartId);
    const auto behind =
        caster.cast(scene::pixelRay(viewProj, size, pixel + zero), &nearest, nullptr);
    if (behind && behind->t - hit->t <= 1e-6 * hit->t) return std::nullopt; // a tie
    return hit->uniquePartId;
}

// So that a path that wrote nothing (or wrote background everywhere) cannot pass: on each path,
// at 1x and 4x, every pixel the ray cast sees no part in has no part in the ID image and the
// clear colour, and every pixel where it sees a part stably has that part's ID.
TEST(ClearPaths, BackgroundIsTheClearColourAndPartsAreWhatTheRayCastSees) {
    const app::LoadedScene loaded = smallScene();
    const scene::Scene& scene = loaded.scene;
    const scene::Camera camera = closeCamera(loaded);
    std::vector<render::RenderSettings> configs;
    for (uint32_t msaa : {1u, 4u}) {
        configs.push_back(
            testing_support::settingsFor(render::defaultTechnique(), render::defaultDrawMode()));
        configs.back().pipeline.msaa = msaa;
    }
    const auto results =
        renderOnBothPaths(testing_support::headlessOptions(W, H), scene, camera, configs);
    ASSERT_EQ(results[1].size(), configs.size());
    const scene::RayCaster caster(scene);
    const glm::dmat4 viewProj = camera.viewProjection(double(W) / double(H));
    for (size_t c = 0; c < configs.size(); ++c) {
        const uint32_t msaa = configs[c].pipeline.msaa;
        std::vector<std::optional<uint32_t>> seen(size_t(W) * H);
        for (uint32_t y = 0; y < H; ++y)
            for (uint32_t x = 0; x < W; ++x)
                seen[size_t(y) * W + x] =
                    stableSeen(caster, viewProj, x, y, msaa, scene.uniquePartCount());
        for (size_t p = 0; p < kPaths.size(); ++p) {
            const app::HeadlessResult& r = results[p][c];
            const std::string name =
                nameOf(configs[c]) + " on the " + render::clearPathName(kPaths[p]) + " path";
            size_t background = 0, covered = 0, wrongIds = 0, wrongBackground = 0, asBackground = 0;
            for (size_t i = 0; i < seen.size(); ++i) {
                if (!seen[i]) continue;
                if (*seen[i] != r.ids[i] && wrongIds++ < 5)
                    ADD_FAILURE() << name << ": pixel " << i % W << "," << i / W << " has ID "
                                  << r.ids[i] << ", the ray cast sees " << *seen[i];
                int difference = 0;
                for (size_t ch = 0; ch < 4; ++ch)
                    difference =
                        std::max(difference, std::abs(int(r.color[4 * i + ch]) - kBackground[ch]));
                if (*seen[i] == NONE) {
                    ++background;
                    wrongBackground += difference > 1;
                } else {
                    ++covered;
                    asBackground += difference <= 1;
                }
            }
            EXPECT_EQ(wrongIds, 0u) << name;
            EXPECT_EQ(wrongBackground, 0u) << name << ": background pixels not in the clear colour";
            // Enough of each kind that the checks mean something; parts are not painted over.
            EXPECT_GT(background, size_t(W) * H / 3) << name;
            EXPECT_GT(covered, size_t(W) * H / 10) << name;
            std::printf("[ clear    ] %s: %zu background and %zu covered pixels checked\n",
                        name.c_str(), background, covered);
            EXPECT_LT(asBackground, covered / 20) << name << ": parts in the clear colour";
        }
    }
}

// Renderer::clearPath(): the forced path when one is forced (and no timing then), with Auto one
// of the two (the faster, where it timed them), at 1x and 4x, switched at run time.
TEST(ClearPaths, TheRendererReportsThePathItDrawsWith) {
    const app::LoadedScene loaded = smallScene();
    const scene::Camera camera = closeCamera(loaded);
    app::Options o = testing_support::headlessOptions(W, H);
    vk::Instance instance({true, {}, false});
    {
        app::Offscreen rig(instance, o);
        uint64_t frame = 0;
        for (uint32_t msaa : {1u, 4u})
            for (ClearPath path : {ClearPath::Pass, ClearPath::Compute, ClearPath::Auto}) {
                render::RenderSettings settings = o.live.render;
                settings.pipeline.msaa = msaa;
                settings.clear = path;
                const std::string name =
                    std::string(render::clearPathName(path)) + ", msaa " + std::to_string(msaa);
                if (frame == 0)
                    rig.renderer.setScene(loaded.scene, settings);
                else
                    rig.renderer.configure(loaded.scene, settings);
                rig.useMsaa(msaa);
                render::FrameSlot& slot = rig.slots.begin(frame++);
                rig.renderer.record(slot, rig.targets, app::cameraFrame(camera, rig.extent));
                rig.slots.submit(slot);
                rig.slots.finish();
                // By name, which gtest prints.
                const std::string drawn = render::clearPathName(rig.renderer.clearPath());
                const auto timing = rig.renderer.clearTiming(msaa);
                if (path == ClearPath::Auto) {
                    EXPECT_NE(drawn, "auto") << name;
                    if (timing) {
                        EXPECT_EQ(drawn, render::clearPathName(timing->faster())) << name;
                    }
                } else {
                    EXPECT_EQ(drawn, render::clearPathName(path)) << name;
                    EXPECT_FALSE(timing.has_value()) << name;
                }
            }
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
}

} // namespace
