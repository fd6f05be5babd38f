// test_composition.cpp - the picture composed again over the images the last scene pass
// left (Renderer::recordComposition), as a viewer at rest draws it: a new hover, blink step,
// selection or edge setting composed alone gives, byte for byte, the picture a scene pass
// with the same state gives, whether it is composed whole or, for a step of the blink, over
// the hovered part's tiles only; the part it reads under the hovered pixel is the scene
// pass's pick there; and a composition leaves the ID image as it was. Lavapipe, validation on, at
// 1x and 4x MSAA, with edges on and off.
#include <gtest/gtest.h>

#include "app/headless.h"
#include "app/offscreen.h"
#include "app/scene_source.h"
#include "render/blink.h"
#include "scene/camera.h"
#include "test_support.h"

namespace {

constexpr uint32_t W = 200, H = 130;
constexpr uint32_t NONE = gpu::BACKGROUND_ID;

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

class Composition : public ::testing::TestWithParam<std::tuple<uint32_t, bool>> {};

TEST_P(Composition, AloneDrawsWhatAScenePassWithTheSameStateDraws) {
    const auto [msaa, edges] = GetParam();
    app::SceneSettings source;
    source.builtin = "procedural:preset=small,seed=3";
    const app::LoadedScene loaded = app::loadScene(source);
    const scene::Scene& scene = loaded.scene;
    const scene::Camera camera = app::initialCamera(loaded, float(W) / float(H));

    app::Options o = testing_support::headlessOptions(W, H);
    o.render.pipeline.msaa = msaa;
    vk::Instance instance({true, {}, false});
    {
        app::Offscreen rig(instance, o);
        render::RenderSettings settings = o.render;
        settings.edges.on = edges;
        rig.renderer.setScene(scene, settings);
        const app::Readback readback(rig.device, rig.extent);
        uint64_t frame = 0;
        render::FrameParams params = app::cameraFrame(camera, rig.extent);
        auto draw = [&](bool scenePass) {
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
        };
        // Two pixels inside two different parts, found in the first scene pass's IDs: with
        // the pixels around them of the same part, so that edges and outlines leave some of
        // the part to blink.
        const Shot first = draw(true);
        auto inside = [&](uint32_t x, uint32_t y) {
            const uint32_t id = first.ids[y * W + x];
            for (uint32_t v = y - 3; v <= y + 3; ++v)
                for (uint32_t u = x - 3; u <= x + 3; ++u)
                    if (first.ids[v * W + u] != id) return false;
            return id != NONE;
        };
        std::vector<glm::uvec2> onParts;
        for (uint32_t y = H / 4; y < H - 3 && onParts.size() < 2; y += 2)
            for (uint32_t x = W / 4; x < W - 3 && onParts.size() < 2; x += 2)
                if (inside(x, y) &&
                    (onParts.empty() ||
                     first.ids[onParts[0].y * W + onParts[0].x] != first.ids[y * W + x]))
                    onParts.push_back({x, y});
        ASSERT_EQ(onParts.size(), 2u);
        const uint32_t partA = first.ids[onParts[0].y * W + onParts[0].x];
        const uint32_t partB = first.ids[onParts[1].y * W + onParts[1].x];

        // A scene pass hovering A, strong blink, nothing selected; then, composed alone: B
        // hovered, the weak blink, A selected.
        params.pickPixel = onParts[0];
        params.time = 0.0f;
        const Shot hoveredA = draw(true);
        ASSERT_TRUE(hoveredA.pick && hoveredA.hover);
        EXPECT_EQ(hoveredA.pick->part, partA);
        EXPECT_EQ(hoveredA.hover->part, partA); // the ID image agrees with the atomicMin pick
        EXPECT_NEAR(hoveredA.hover->depth, hoveredA.pick->depth, 1e-5);
        EXPECT_NE(hoveredA.color, first.color) << "the hovered part shows";

        scene::PartSet selected(scene.uniquePartCount());
        selected.insert(partA);
        rig.renderer.setSelection(selected);
        params.pickPixel = onParts[1];
        params.time = float(0.75 / render::blinkHz); // the weak half of a period
        const Shot composed = draw(false);
        ASSERT_TRUE(composed.hover);
        EXPECT_EQ(composed.hover->part, partB);
        EXPECT_EQ(composed.hover->frame, frame - 1);
        EXPECT_EQ(composed.ids, hoveredA.ids) << "a composition leaves the IDs as they are";
        EXPECT_NE(composed.color, hoveredA.color);

        // The same state through a scene pass: the same picture, byte for byte, and the
        // same part and depth under the hovered pixel.
        const Shot drawn = draw(true);
        EXPECT_EQ(drawn.ids, composed.ids);
        EXPECT_TRUE(drawn.color == composed.color) << "composed alone differs from a scene pass";
        ASSERT_TRUE(drawn.pick && drawn.hover);
        EXPECT_EQ(drawn.pick->part, partB);
        EXPECT_EQ(drawn.hover->part, partB);
        EXPECT_EQ(drawn.hover->depth, composed.hover->depth);

        // The next step of the blink, nothing else changed: only the hovered part's tiles
        // are composed again, and the picture is the one a scene pass draws.
        params.time = float(1.0 / render::blinkHz); // the strong half of the next period
        const Shot stepped = draw(false);
        EXPECT_TRUE(composedTiles(rig));
        EXPECT_NE(stepped.color, composed.color) << "the blink stepped";
        ASSERT_TRUE(stepped.hover);
        EXPECT_EQ(stepped.hover->part, partB);
        EXPECT_EQ(stepped.hover->frame, frame - 1) << "the hovered pixel is read in every step";
        const Shot steppedDrawn = draw(true);
        EXPECT_FALSE(rig.renderer.lastComposedTiles());
        EXPECT_TRUE(steppedDrawn.color == stepped.color)
            << "the hovered part's tiles alone differ from a scene pass";
        // The scene pass composed its images whole; the steps after it are over the tiles.
        params.time = float(1.75 / render::blinkHz);
        const Shot weakAgain = draw(false);
        EXPECT_TRUE(composedTiles(rig));
        EXPECT_TRUE(weakAgain.color == composed.color);
        params.time = float(2.0 / render::blinkHz);
        const Shot strongAgain = draw(false);
        EXPECT_TRUE(composedTiles(rig));
        EXPECT_TRUE(strongAgain.color == stepped.color);
        // A new selection is composed whole.
        rig.renderer.setSelection(scene::PartSet(scene.uniquePartCount()));
        draw(false);
        EXPECT_FALSE(rig.renderer.lastComposedTiles());

        // Over background the composition hovers nothing.
        params.pickPixel = glm::uvec2(0, 0);
        ASSERT_EQ(first.ids[0], NONE);
        const Shot background = draw(false);
        ASSERT_TRUE(background.hover);
        EXPECT_FALSE(background.hover->part.has_value());
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Lavapipe, Composition,
                         ::testing::Combine(::testing::Values(1u, 4u), ::testing::Bool()),
                         [](const auto& info) {
                             return "msaa" + std::to_string(std::get<0>(info.param)) +
                                    (std::get<1>(info.param) ? "_edges" : "_plain");
                         });

} // namespace
