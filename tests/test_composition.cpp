// test_composition.cpp - the picture composed again over the images the last scene pass
// left (Renderer::recordComposition), as a viewer at rest draws it: a new hover, blink step,
// selection or edge setting composed alone gives, byte for byte, the picture a scene pass
// with the same state gives; the part it reads under the hovered pixel is the scene pass's
// pick there; and a composition leaves the ID image as it was. Lavapipe, validation on, at
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
        // Two pixels on two different parts, found in the first scene pass's IDs.
        const Shot first = draw(true);
        std::vector<glm::uvec2> onParts;
        for (uint32_t y = H / 4; y < H && onParts.size() < 2; y += 7)
            for (uint32_t x = W / 4; x < W && onParts.size() < 2; x += 5) {
                const uint32_t id = first.ids[y * W + x];
                if (id != NONE &&
                    (onParts.empty() || first.ids[onParts[0].y * W + onParts[0].x] != id))
                    onParts.push_back({x, y});
            }
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
