// test_pacer.cpp - the viewer's decisions to draw or rest (app/viewer/pacer.h): nothing is
// drawn while nothing changes, an event buys a few frames, the blink steps at its own pace,
// and only a changed SceneKey asks for the scene pass.
#include <gtest/gtest.h>

#include "app/viewer/pacer.h"
#include "render/blink.h"

namespace {

// Draws every frame that is due at `wants`, composing unless the key changed; returns how
// many were drawn before the pacer let the loop rest.
int drawWhileDue(app::FramePacer& pacer, const app::FrameWants& wants, const app::SceneKey& key) {
    int frames = 0;
    while (pacer.due(wants) && frames < 100) {
        pacer.drew(wants, pacer.needsScene(key, wants.continuous), key);
        ++frames;
    }
    return frames;
}

TEST(FramePacer, RestsOnceSettledAndDrawsNoSceneWhileNothingChanges) {
    app::FramePacer pacer;
    app::FrameWants wants;
    const app::SceneKey key;
    // The first frame is a scene pass, the settle frames after it compositions.
    EXPECT_EQ(drawWhileDue(pacer, wants, key), 1 + app::FramePacer::settleFrames);
    EXPECT_EQ(pacer.scenePasses(), 1u);
    EXPECT_EQ(pacer.compositions(), uint64_t(app::FramePacer::settleFrames));
    EXPECT_FALSE(pacer.due(wants));
    EXPECT_EQ(pacer.rest(wants), std::nullopt); // nothing to wake for: wait for an event
    // Ten seconds later with nothing hovered: still nothing to draw.
    wants.now = 10.0;
    EXPECT_FALSE(pacer.due(wants));
}

TEST(FramePacer, AnEventComposesWithoutASceneWhenTheKeyStands) {
    app::FramePacer pacer;
    app::FrameWants wants;
    app::SceneKey key;
    drawWhileDue(pacer, wants, key);
    wants.events = 1; // the cursor moved over the picture
    EXPECT_EQ(drawWhileDue(pacer, wants, key), app::FramePacer::settleFrames);
    EXPECT_EQ(pacer.scenePasses(), 1u);
    // The camera turned: the next frame is a scene pass.
    key.viewProj[0][0] = 2.0f;
    wants.events = 2;
    EXPECT_TRUE(pacer.due(wants));
    EXPECT_TRUE(pacer.needsScene(key, false));
    drawWhileDue(pacer, wants, key);
    EXPECT_EQ(pacer.scenePasses(), 2u);
    // Edges are not in the key (the viewer clears them): settings that are compare.
    app::SceneKey hidden = key;
    hidden.renderer = 7;
    EXPECT_TRUE(pacer.needsScene(hidden, false));
    app::SceneKey cut = key;
    cut.settings.section.planes[0].on = true;
    EXPECT_TRUE(pacer.needsScene(cut, false));
}

TEST(FramePacer, AHoveredPartComposesOncePerBlinkStepAndNoSceneAtAll) {
    app::FramePacer pacer;
    app::FrameWants wants;
    const app::SceneKey key;
    drawWhileDue(pacer, wants, key);
    wants.hovering = true;
    uint64_t frames = 0;
    // Ten seconds of resting over a part, the loop woken when the pacer says.
    while (wants.now < 10.0) {
        const auto wait = pacer.rest(wants);
        ASSERT_TRUE(wait.has_value());
        ASSERT_GT(*wait, 0.0);
        wants.now += *wait + 1e-9;
        frames += drawWhileDue(pacer, wants, key);
    }
    EXPECT_EQ(pacer.scenePasses(), 1u);
    // Two steps a period: 2 * 1.5 * 10 = 30 compositions, give or take the ends.
    EXPECT_NEAR(double(frames), 2.0 * render::blinkHz * 10.0, 1.0);
}

TEST(FramePacer, ContinuousDrawsAScenePassEveryFrame) {
    app::FramePacer pacer;
    app::FrameWants wants;
    wants.continuous = true;
    const app::SceneKey key;
    for (int i = 0; i < 5; ++i) {
        ASSERT_TRUE(pacer.due(wants));
        ASSERT_TRUE(pacer.needsScene(key, true));
        pacer.drew(wants, true, key);
    }
    EXPECT_EQ(pacer.scenePasses(), 5u);
}

TEST(FramePacer, ALoadShowsItsProgressAtItsInterval) {
    app::FramePacer pacer;
    app::FrameWants wants;
    const app::SceneKey key;
    drawWhileDue(pacer, wants, key);
    wants.loading = true;
    EXPECT_FALSE(pacer.due(wants));
    EXPECT_EQ(pacer.rest(wants), app::FramePacer::progressInterval);
    wants.now += app::FramePacer::progressInterval;
    EXPECT_TRUE(pacer.due(wants));
}

TEST(FramePacer, WakesWhenThePictureChangesByItself) {
    app::FramePacer pacer;
    app::FrameWants wants;
    const app::SceneKey key;
    drawWhileDue(pacer, wants, key);
    wants.changeAt = 4.0; // a notice that goes at 4 s
    EXPECT_FALSE(pacer.due(wants));
    EXPECT_EQ(pacer.rest(wants), 4.0);
    wants.now = 4.0;
    EXPECT_TRUE(pacer.due(wants));
    pacer.drew(wants, false, key);
    wants.now = 5.0;
    EXPECT_FALSE(pacer.due(wants)); // once
}

TEST(Blink, StepsBetweenTwoWeightsTwiceAPeriod) {
    EXPECT_EQ(render::blinkWeight(0.0), render::blinkStrong);
    const double half = 0.5 / render::blinkHz;
    EXPECT_EQ(render::blinkWeight(half * 1.01), render::blinkWeak);
    EXPECT_EQ(render::blinkWeight(half * 2.01), render::blinkStrong);
    EXPECT_NEAR(render::nextBlinkChange(0.1), half, 1e-12);
    EXPECT_NEAR(render::nextBlinkChange(half * 1.5), 2.0 * half, 1e-12);
}

} // namespace
