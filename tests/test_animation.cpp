// test_animation.cpp - the exploded-view animation: the offsets and the CPU reference by hand,
// then, on lavapipe with validation on, the GPU-animated ID image must equal bit for bit the
// image of the CPU-exploded scene drawn at rest (and differ from the unexploded image), the
// pick must name what the animated image shows, and explode 0 must bring the rest back.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "app/headless.h"
#include "app/offscreen.h"
#include "app/scene_source.h"
#include "render/technique.h"
#include "scene/explode.h"
#include "test_support.h"
#include "vk/context.h"

namespace {

constexpr uint32_t W = 160, H = 100;

// Two placements of one triangle whose bounds are easy to write down.
scene::Scene twoTriangles() {
    scene::Scene s;
    s.vertices = {{{0, 0, 0}, {0, 0, 1}}, {{1, 0, 0}, {0, 0, 1}}, {{0, 1, 0}, {0, 0, 1}}};
    s.indices = {0, 1, 2};
    s.parts = {{0, 1}};
    s.geometries = {{"triangle", 0, 3, 0, 1, 0, 1, {}, {}, {}, {}, 0, 0.0f}};
    scene::addMaterial(s, "grey", glm::vec4(0.5f));
    glm::mat4 a(1.0f), b(2.0f); // b scales by 2
    a[3] = {-3, 0, 0, 1};
    b[3] = {5, 0, 2, 1};
    scene::addObject(s, 0, 0, a);
    scene::addObject(s, 0, 0, b);
    return s;
}

TEST(ExplodeMaths, OffsetsPointFromSceneCentreToObjectCentres) {
    // Object bounds: x -3..-2, y 0..1, z 0 and x 5..7, y 0..2, z 2; the scene's centre is
    // (2, 1, 1).
    const auto offsets = scene::explodeOffsets(twoTriangles());
    ASSERT_EQ(offsets.size(), 2u);
    EXPECT_EQ(offsets[0], glm::vec4(-4.5f, -0.5f, -1.0f, 0.0f));
    EXPECT_EQ(offsets[1], glm::vec4(4.0f, 0.0f, 1.0f, 0.0f));
}

TEST(ExplodeMaths, ExplodedSceneMovesTranslationsOnly) {
    const scene::Scene rest = twoTriangles();
    const scene::Scene none = scene::explodedScene(rest, 0.0f);
    for (size_t i = 0; i < rest.objects.size(); ++i)
        EXPECT_EQ(none.objects[i].world, rest.objects[i].world);

    // At 1 each object's centre is twice as far from the scene centre: (-2.5, 0.5, 0) goes to
    // (-7, 0, -1) and (6, 1, 2) to (10, 1, 3).
    const scene::Scene full = scene::explodedScene(rest, 1.0f);
    EXPECT_EQ(full.objects[0].world[3], glm::dvec4(-7.5, -0.5, -1.0, 1.0));
    EXPECT_EQ(full.objects[1].world[3], glm::dvec4(9.0, 0.0, 3.0, 1.0));
    for (size_t i = 0; i < rest.objects.size(); ++i) {
        for (int c = 0; c < 3; ++c) EXPECT_EQ(full.objects[i].world[c], rest.objects[i].world[c]);
        EXPECT_EQ(full.objects[i].uniquePartOffset, rest.objects[i].uniquePartOffset);
    }

    const scene::Scene some = scene::explodedScene(rest, 0.6f);
    // The reference's operations, rounded the same way: the step in float, the add in double.
    const double x = -3.0 + double(-4.5f * 0.6f);
    EXPECT_EQ(some.objects[0].world[3].x, x);
}

TEST(ExplodeMaths, LoopGoesOutAndBackInFourSeconds) {
    EXPECT_EQ(scene::explodeLoop(0.0f), 0.0f);
    EXPECT_NEAR(scene::explodeLoop(1.0f), 0.5f, 1e-6f);
    EXPECT_NEAR(scene::explodeLoop(2.0f), 1.0f, 1e-6f);
    EXPECT_NEAR(scene::explodeLoop(4.0f), 0.0f, 1e-6f);
    EXPECT_NEAR(scene::explodeLoop(5.0f), scene::explodeLoop(1.0f), 1e-6f);
}

TEST(AnimationFlags, ParseAnimateAndTime) {
    const app::Options o = app::parseArgs({"--animate", "--time", "1.5"});
    EXPECT_TRUE(o.animation.animate);
    ASSERT_TRUE(o.animation.time.has_value());
    EXPECT_EQ(*o.animation.time, 1.5f);
    EXPECT_FALSE(app::parseArgs(std::vector<std::string>{}).animation.time.has_value());
    EXPECT_THROW(app::parseArgs({"--time", "1"}), app::UsageError); // needs --animate
    EXPECT_THROW(app::parseArgs({"--animate", "--time", "soon"}), app::UsageError);
    EXPECT_THROW(app::parseArgs({"--animate", "--time=-1"}), app::UsageError);
    EXPECT_THROW(app::parseArgs({"--animate", "--time", "nan"}), app::UsageError);
    EXPECT_NE(app::usage().find("--animate"), std::string::npos);
}

app::Options renderOptions(const render::Technique& technique, const render::DrawMode& mode) {
    app::Options o = testing_support::headlessOptions(W, H, 2);
    o.render = testing_support::settingsFor(technique, mode);
    return o;
}

struct Fixture {
    app::LoadedScene loaded;
    scene::Camera camera; // fitted to the scene at rest; exploded objects may leave the view
};

Fixture& fixture() {
    static Fixture f = [] {
        app::SceneSettings source;
        source.builtin = "procedural:preset=small,seed=1";
        Fixture made;
        made.loaded = app::loadScene(source);
        made.camera = app::initialCamera(made.loaded, float(W) / float(H));
        return made;
    }();
    return f;
}

size_t countDifferences(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b) {
    size_t n = 0;
    for (size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
    return n;
}

struct Combination {
    const render::Technique* technique;
    const render::DrawMode* mode;
};

void PrintTo(const Combination& c, std::ostream* os) {
    *os << c.technique->name << " + " << c.mode->name;
}

class GpuAnimation : public ::testing::TestWithParam<Combination> {};

TEST_P(GpuAnimation, MatchesCpuExplodedSceneBitForBitAndPicksWhatItShows) {
    const Combination& c = GetParam();
    Fixture& f = fixture();
    const float explode = 0.6f;

    app::Options animated = renderOptions(*c.technique, *c.mode);
    animated.animation.explode = explode;
    // Picks across the image: they run before the timed frames, at the same explode.
    for (uint32_t y = 5; y < H; y += 18)
        for (uint32_t x = 5; x < W; x += 25) animated.picks.push_back({x, y});
    const app::HeadlessResult gpu = app::renderHeadless(animated, f.loaded.scene, f.camera);
    const app::Options still = renderOptions(*c.technique, *c.mode);
    const app::HeadlessResult cpu =
        app::renderHeadless(still, scene::explodedScene(f.loaded.scene, explode), f.camera);
    const app::HeadlessResult rest = app::renderHeadless(still, f.loaded.scene, f.camera);
    EXPECT_EQ(gpu.validationMessages, 0u);
    EXPECT_EQ(cpu.validationMessages, 0u);
    EXPECT_EQ(rest.validationMessages, 0u);

    ASSERT_EQ(gpu.ids.size(), size_t(W) * H);
    ASSERT_EQ(cpu.ids.size(), gpu.ids.size());
    const size_t differing = countDifferences(gpu.ids, cpu.ids);
    size_t first = 0;
    while (differing && gpu.ids[first] == cpu.ids[first]) ++first;
    EXPECT_EQ(differing, 0u) << "first at pixel " << first % W << "," << first / W << ": "
                             << gpu.ids[first] << " instead of " << cpu.ids[first];
    // The motion is real: a good share of the image changed against the scene at rest.
    EXPECT_GT(countDifferences(gpu.ids, rest.ids), gpu.ids.size() / 20);

    ASSERT_EQ(gpu.picks.size(), animated.picks.size());
    size_t onParts = 0;
    for (const auto& pick : gpu.picks) {
        const uint32_t shown = gpu.ids[size_t(pick.pixel.y) * W + pick.pixel.x];
        EXPECT_EQ(pick.part.value_or(gpu::BACKGROUND_ID), shown)
            << "pick at " << pick.pixel.x << "," << pick.pixel.y;
        onParts += pick.part.has_value();
    }
    EXPECT_GT(onParts, 3u) << "too few picks hit a part to mean anything";
}

std::string nameOf(const ::testing::TestParamInfo<Combination>& info) {
    return testing_support::testName(std::string(info.param.technique->name) + "_" +
                                     info.param.mode->name);
}

// Every part-ID technique of the registry, the modes taken in turn.
std::vector<Combination> combinations() {
    std::vector<Combination> all;
    const auto& modes = render::drawModes();
    for (const render::Technique* t : render::partIdTechniques())
        all.push_back({t, &modes[all.size() % modes.size()]});
    return all;
}

INSTANTIATE_TEST_SUITE_P(Lavapipe, GpuAnimation, ::testing::ValuesIn(combinations()), nameOf);

// --animate --time T renders the loop's explode at T, identical to the CPU reference.
TEST(GpuAnimationLoop, AnimateAtTimeFollowsTheLoop) {
    Fixture& f = fixture();
    const render::Technique& technique = *render::partIdTechniques().back();
    app::Options o = renderOptions(technique, render::defaultDrawMode());
    o.animation.animate = true;
    o.animation.time = 1.3f;
    const app::HeadlessResult gpu = app::renderHeadless(o, f.loaded.scene, f.camera);
    const app::HeadlessResult cpu = app::renderHeadless(
        renderOptions(technique, render::defaultDrawMode()),
        scene::explodedScene(f.loaded.scene, scene::explodeLoop(1.3f)), f.camera);
    EXPECT_EQ(gpu.validationMessages, 0u);
    EXPECT_EQ(countDifferences(gpu.ids, cpu.ids), 0u);
}

// One renderer, frames in flight: exploded, then back to explode 0, which must restore the
// rest matrices (the dispatch runs once more) even though nothing is recorded afterwards.
TEST(GpuAnimationLoop, ExplodeZeroAfterMotionRestoresTheRestPose) {
    Fixture& f = fixture();
    const app::Options o = renderOptions(render::defaultTechnique(), render::drawModes().back());
    const app::HeadlessResult rest = app::renderHeadless(o, f.loaded.scene, f.camera);
    const app::HeadlessResult moved =
        app::renderHeadless(o, scene::explodedScene(f.loaded.scene, 1.0f), f.camera);
    // A pixel whose part changes with the motion, both images showing a part there.
    size_t at = rest.ids.size();
    for (size_t i = 0; i < rest.ids.size() && at == rest.ids.size(); ++i)
        if (rest.ids[i] != moved.ids[i] && rest.ids[i] != gpu::BACKGROUND_ID &&
            moved.ids[i] != gpu::BACKGROUND_ID)
            at = i;
    ASSERT_LT(at, rest.ids.size());
    const glm::uvec2 pixel(at % W, at / W);

    vk::Instance instance({true, {}});
    std::vector<std::optional<uint32_t>> picked;
    {
        app::Offscreen rig(instance, o);
        rig.renderer.setScene(f.loaded.scene, o.render);
        render::FrameParams params = app::cameraFrame(f.camera, rig.extent);
        params.pickPixel = pixel;
        uint64_t frame = 0;
        // Two frames in flight per explode value, then wait and read the pick.
        for (float explode : {1.0f, 0.0f, 0.0f, 1.0f, 0.0f}) {
            params.explode = explode;
            for (int i = 0; i < 2; ++i) {
                render::FrameSlot& slot = rig.slots.begin(frame++);
                rig.renderer.record(slot, rig.targets, params);
                rig.slots.submit(slot);
            }
            rig.slots.finish();
            picked.push_back(rig.slots.latestPick()->part);
        }
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
    const std::optional<uint32_t> atRest = rest.ids[at], atOne = moved.ids[at];
    EXPECT_EQ(picked, (std::vector<std::optional<uint32_t>>{atOne, atRest, atRest, atOne, atRest}));
}

} // namespace
