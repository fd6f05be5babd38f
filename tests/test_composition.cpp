// test_composition.cpp - the picture composed again over the images the last scene pass
// left (Renderer::recordComposition), as a viewer at rest draws it: a new hover, blink step,
// selection or edge setting composed alone gives, byte for byte, the picture a scene pass
// with the same state gives, whether it is composed whole or, for a step of the blink, over
// the hovered part's tiles only; the part it reads under the hovered pixel is the scene
// pass's pick there; and a composition leaves the ID image as it was. The tint by visibility
// moves the tinted parts' colours alone. Lavapipe, validation on, at
// 1x and 4x MSAA, with edges on and off.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include <glm/gtc/packing.hpp>

#include "app/camera_frame.h"
#include "app/headless.h"
#include "app/offscreen.h"
#include "app/scene_source.h"
#include "image_compare.h"
#include "render/blink.h"
#include "scene/camera.h"
#include "test_support.h"

namespace {

constexpr uint32_t W = 200, H = 130;
constexpr uint32_t NONE = gpu::BACKGROUND_ID;
using testing_support::sameColours;
using testing_support::sameIds;

struct Shot {
    std::vector<uint8_t> color;
    std::vector<uint32_t> ids;
    std::optional<render::PickReading> pick, hover;
};

// Whether the last composition made only the hovered part's tiles again, and fewer than all.
bool composedTiles(const app::Offscreen& rig) {
    const auto& tiles = rig.renderer.lastComposedTiles();
    const glm::uvec2 all((W + gpu::ID_PASS_TILE - 1) / gpu::ID_PASS_TILE,
                         (H + gpu::ID_PASS_TILE - 1) / gpu::ID_PASS_TILE);
    return tiles && tiles->count.x * tiles->count.y > 0 &&
           tiles->count.x * tiles->count.y < all.x * all.y;
}

// One renderer drawing frames of one scene as a viewer at rest does, each a scene pass or a
// composition alone, read back and waited for.
struct Drawing {
    Drawing(vk::Instance& instance, const app::Options& o, const scene::Scene& scene,
            const scene::Camera& camera, bool edges)
        : rig(instance, o), readback(rig.device, rig.extent),
          params(app::cameraFrame(camera, rig.extent)) {
        render::RenderSettings settings = o.live.render;
        settings.edges.on = edges;
        rig.renderer.setScene(scene, settings);
    }

    Shot draw(bool scenePass) {
        render::FrameSlot& slot = rig.slots.begin(frame++);
        params.hoveredTiles = rig.slots.latestHoveredTiles();
        if (scenePass)
            rig.renderer.record(slot, rig.targets, params);
        else
            rig.renderer.recordComposition(slot, rig.targets, params);
        readback.record(slot.cmd, *rig.targets);
        rig.slots.submit(slot);
        rig.slots.finish();
        Shot shot{readback.colorBytes(), readback.idValues(), std::nullopt, std::nullopt};
        if (scenePass) shot.pick = rig.slots.latestPick();
        shot.hover = rig.slots.latestHover();
        return shot;
    }

    app::Offscreen rig;
    const app::Readback readback;
    render::FrameParams params;
    uint64_t frame = 0;
};

// Two pixels inside two different parts of `ids`, each with the pixels around it of the same
// part, so that edges and outlines leave some of the part to blink.
std::vector<glm::uvec2> pixelsInsideTwoParts(const std::vector<uint32_t>& ids) {
    auto inside = [&](uint32_t x, uint32_t y) {
        const uint32_t id = ids[y * W + x];
        for (uint32_t v = y - 3; v <= y + 3; ++v)
            for (uint32_t u = x - 3; u <= x + 3; ++u)
                if (ids[v * W + u] != id) return false;
        return id != NONE;
    };
    std::vector<glm::uvec2> onParts;
    for (uint32_t y = H / 4; y < H - 3 && onParts.size() < 2; y += 2)
        for (uint32_t x = W / 4; x < W - 3 && onParts.size() < 2; x += 2)
            if (inside(x, y) &&
                (onParts.empty() || ids[onParts[0].y * W + onParts[0].x] != ids[y * W + x]))
                onParts.push_back({x, y});
    return onParts;
}

// What the steps of one run share: the first scene pass, the two parts and the pixels on
// them, then the pictures the steps compare.
struct Pictures {
    Shot first;
    std::vector<glm::uvec2> onParts;
    uint32_t partA = NONE, partB = NONE;
    Shot composed; // B hovered at the weak blink, A selected, composed alone
    Shot stepped;  // the blink's next (strong) step over the tiles
};

// A scene pass hovering A, strong blink, nothing selected; then, composed alone: B hovered,
// the weak blink, A selected. The same state through a scene pass draws the same picture,
// byte for byte, and finds the same part and depth under the hovered pixel.
void composeAloneAsAScenePass(Drawing& d, const scene::Scene& scene, Pictures& run) {
    d.params.pickPixel = run.onParts[0];
    d.params.time = 0.0f;
    const Shot hoveredA = d.draw(true);
    ASSERT_TRUE(hoveredA.pick && hoveredA.hover);
    EXPECT_EQ(hoveredA.pick->part, run.partA);
    EXPECT_EQ(hoveredA.hover->part, run.partA); // the ID image agrees with the atomicMin pick
    EXPECT_NEAR(hoveredA.hover->depth, hoveredA.pick->depth, 1e-5);
    EXPECT_FALSE(sameColours(hoveredA.color, run.first.color, W)) << "the hovered part shows";

    scene::PartSet selected(scene.uniquePartCount());
    selected.insert(run.partA);
    d.rig.renderer.setSelection(selected);
    d.params.pickPixel = run.onParts[1];
    d.params.time = float(0.75 / render::blinkHz); // the weak half of a period
    run.composed = d.draw(false);
    const Shot& composed = run.composed;
    ASSERT_TRUE(composed.hover);
    EXPECT_EQ(composed.hover->part, run.partB);
    EXPECT_EQ(composed.hover->frame, d.frame - 1);
    EXPECT_TRUE(sameIds(composed.ids, hoveredA.ids, W))
        << "a composition leaves the IDs as they are";
    EXPECT_FALSE(sameColours(composed.color, hoveredA.color, W));

    const Shot drawn = d.draw(true);
    EXPECT_TRUE(sameIds(drawn.ids, composed.ids, W));
    EXPECT_TRUE(sameColours(drawn.color, composed.color, W))
        << "composed alone differs from a scene pass";
    ASSERT_TRUE(drawn.pick && drawn.hover);
    EXPECT_EQ(drawn.pick->part, run.partB);
    EXPECT_EQ(drawn.hover->part, run.partB);
    EXPECT_EQ(drawn.hover->depth, composed.hover->depth);
}

// The next step of the blink, nothing else changed: only the hovered part's tiles are
// composed again, and the picture is the one a scene pass draws; after that scene pass
// (composed whole) the steps are over the tiles again, and a new selection is composed whole.
void stepTheBlinkOverTheTiles(Drawing& d, const scene::Scene& scene, Pictures& run) {
    d.params.time = float(1.0 / render::blinkHz); // the strong half of the next period
    run.stepped = d.draw(false);
    const Shot& stepped = run.stepped;
    EXPECT_TRUE(composedTiles(d.rig));
    EXPECT_FALSE(sameColours(stepped.color, run.composed.color, W)) << "the blink stepped";
    ASSERT_TRUE(stepped.hover);
    EXPECT_EQ(stepped.hover->part, run.partB);
    EXPECT_EQ(stepped.hover->frame, d.frame - 1) << "the hovered pixel is read in every step";
    const Shot steppedDrawn = d.draw(true);
    EXPECT_FALSE(d.rig.renderer.lastComposedTiles());
    EXPECT_TRUE(sameColours(steppedDrawn.color, stepped.color, W))
        << "the hovered part's tiles alone differ from a scene pass";
    d.params.time = float(1.75 / render::blinkHz);
    const Shot weakAgain = d.draw(false);
    EXPECT_TRUE(composedTiles(d.rig));
    EXPECT_TRUE(sameColours(weakAgain.color, run.composed.color, W));
    d.params.time = float(2.0 / render::blinkHz);
    const Shot strongAgain = d.draw(false);
    EXPECT_TRUE(composedTiles(d.rig));
    EXPECT_TRUE(sameColours(strongAgain.color, stepped.color, W));
    d.rig.renderer.setSelection(scene::PartSet(scene.uniquePartCount()));
    d.draw(false);
    EXPECT_FALSE(d.rig.renderer.lastComposedTiles());
}

class Composition : public ::testing::TestWithParam<std::tuple<uint32_t, bool>> {};

TEST_P(Composition, AloneDrawsWhatAScenePassWithTheSameStateDraws) {
    const auto [msaa, edges] = GetParam();
    app::SceneSettings source;
    source.builtin = "procedural:preset=small,seed=3";
    const app::LoadedScene loaded = app::loadScene(source);
    const scene::Scene& scene = loaded.scene;
    const scene::Camera camera = app::initialCamera(loaded, float(W) / float(H));

    app::Options o = testing_support::headlessOptions(W, H);
    o.live.render.pipeline.msaa = msaa;
    vk::Instance instance({true, {}, false});
    {
        Drawing d(instance, o, scene, camera, edges);
        Pictures run;
        run.first = d.draw(true);
        run.onParts = pixelsInsideTwoParts(run.first.ids);
        ASSERT_EQ(run.onParts.size(), 2u);
        run.partA = run.first.ids[run.onParts[0].y * W + run.onParts[0].x];
        run.partB = run.first.ids[run.onParts[1].y * W + run.onParts[1].x];
        composeAloneAsAScenePass(d, scene, run);
        if (HasFatalFailure()) return;
        stepTheBlinkOverTheTiles(d, scene, run);
        if (HasFatalFailure()) return;

        // Over background the composition hovers nothing.
        d.params.pickPixel = glm::uvec2(0, 0);
        ASSERT_EQ(run.first.ids[0], NONE);
        const Shot background = d.draw(false);
        ASSERT_TRUE(background.hover);
        EXPECT_FALSE(background.hover->part.has_value());
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
}

// The tint by visibility (Renderer::setTint) over a scene pass's picture: the IDs and the
// pick stay as they are; each pixel of a tinted part is its colour mixed towards the part's
// tint by the tint's alpha, every other pixel (background, parts with tint 0) keeps its
// bytes; composed alone it is what a scene pass draws; off, or all 0, the picture is as before.
void tintMovesTintedPartsAlone(uint32_t msaa) {
    app::SceneSettings source;
    source.builtin = "procedural:preset=small,seed=3";
    const app::LoadedScene loaded = app::loadScene(source);
    const scene::Scene& scene = loaded.scene;
    app::Options o = testing_support::headlessOptions(W, H);
    o.live.render.pipeline.msaa = msaa;
    vk::Instance instance({true, {}, false});
    {
        Drawing d(instance, o, scene, app::initialCamera(loaded, float(W) / float(H)), false);
        const Shot before = d.draw(true);
        const std::vector<glm::uvec2> onParts = pixelsInsideTwoParts(before.ids);
        ASSERT_EQ(onParts.size(), 2u);
        const uint32_t shown = before.ids[onParts[0].y * W + onParts[0].x];
        // Every other part tinted, the part at onParts[0] among them, in colours that take turns.
        const std::array<uint32_t, 3> colours = {0xbe0000ffu, 0xbe00ff00u, 0xbeff00ffu};
        std::vector<uint32_t> tint(scene.uniquePartCount(), 0u);
        for (uint32_t id = shown % 2; id < tint.size(); id += 2) tint[id] = colours[id % 3];
        d.rig.renderer.setTint(tint);
        const Shot composed = d.draw(false);
        const Shot drawn = d.draw(true);
        EXPECT_TRUE(sameIds(composed.ids, before.ids, W)) << "the tint changed the IDs";
        EXPECT_TRUE(sameIds(drawn.ids, before.ids, W)) << "the tint changed the IDs";
        EXPECT_TRUE(sameColours(drawn.color, composed.color, W));
        size_t tinted = 0, wrong = 0;
        for (size_t i = 0; i < before.ids.size(); ++i) {
            const uint32_t id = before.ids[i];
            const uint32_t rgba = id == NONE ? 0u : tint[id];
            const glm::vec4 target = glm::unpackUnorm4x8(rgba) * 255.0f;
            for (int c = 0; c < 3; ++c) {
                const float was = before.color[4 * i + c], got = drawn.color[4 * i + c];
                const float want = was + (target[c] - was) * target.a / 255.0f;
                if (std::abs(got - want) > 1.0f && wrong++ < 3)
                    ADD_FAILURE() << "msaa " << msaa << " pixel " << i % W << "," << i / W
                                  << " part " << id << " channel " << c << ": " << got << ", want "
                                  << want;
            }
            if (rgba) ++tinted;
        }
        EXPECT_EQ(wrong, 0u);
        EXPECT_GT(tinted, 2000u) << "too few tinted pixels to tell";
        EXPECT_FALSE(sameColours(drawn.color, before.color, W));

        // The pick and the hovered part under a tinted part's pixel, with the tint and without.
        d.params.pickPixel = onParts[0];
        const Shot pickedTinted = d.draw(true);
        d.rig.renderer.setTint(std::vector<uint32_t>(tint.size(), 0u));
        const Shot pickedPlain = d.draw(true);
        ASSERT_TRUE(pickedTinted.pick && pickedPlain.pick);
        EXPECT_EQ(pickedTinted.pick->part, shown);
        EXPECT_EQ(pickedTinted.pick->part, pickedPlain.pick->part);
        EXPECT_EQ(pickedTinted.pick->depth, pickedPlain.pick->depth);
        d.params.pickPixel.reset();
        EXPECT_TRUE(sameColours(d.draw(false).color, before.color, W)) << "a tint of all 0";
        d.rig.renderer.setTint({});
        EXPECT_TRUE(sameColours(d.draw(false).color, before.color, W)) << "the tint off";
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
}

TEST(CompositionTint, TintByVisibilityMovesOnlyTheTintedPartsColours) {
    tintMovesTintedPartsAlone(1);
    tintMovesTintedPartsAlone(4);
}

INSTANTIATE_TEST_SUITE_P(Lavapipe, Composition,
                         ::testing::Combine(::testing::Values(1u, 4u), ::testing::Bool()),
                         [](const auto& info) {
                             return "msaa" + std::to_string(std::get<0>(info.param)) +
                                    (std::get<1>(info.param) ? "_edges" : "_plain");
                         });

} // namespace
