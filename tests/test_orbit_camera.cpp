// test_orbit_camera.cpp - the viewer camera's maths: fitting contains the scene, the planes
// stay valid for any model size and zoom, orbiting keeps the distance, zoom never crosses
// the target, and reset returns to the opening view.
#include <gtest/gtest.h>

#include <cmath>

#include "app/viewer/orbit_camera.h"

namespace {

scene::Bounds box(glm::vec3 min, glm::vec3 max) {
    scene::Bounds b;
    b.min = min;
    b.max = max;
    return b;
}

scene::Camera opening(const scene::Bounds& bounds, glm::vec3 up, float aspect) {
    return scene::fitCamera(bounds, glm::vec3(0.9f, -1.6f, 1.2f), up, glm::radians(40.0f), aspect);
}

// Every corner of `bounds` lies inside the camera's view volume.
void expectContains(const scene::Camera& camera, const scene::Bounds& bounds, float aspect) {
    const glm::mat4 viewProj = camera.viewProjection(aspect);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? bounds.max.x : bounds.min.x,
                          (corner & 2) ? bounds.max.y : bounds.min.y,
                          (corner & 4) ? bounds.max.z : bounds.min.z);
        const glm::vec4 clip = viewProj * glm::vec4(p, 1.0f);
        ASSERT_GT(clip.w, 0.0f);
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        EXPECT_LE(std::abs(ndc.x), 1.0f + 1e-4f) << "corner " << corner;
        EXPECT_LE(std::abs(ndc.y), 1.0f + 1e-4f) << "corner " << corner;
        EXPECT_GE(ndc.z, -1e-5f) << "corner " << corner;
        EXPECT_LE(ndc.z, 1.0f + 1e-5f) << "corner " << corner;
    }
}

void expectValidPlanes(const scene::Camera& camera) {
    EXPECT_GT(camera.nearPlane, 0.0f);
    EXPECT_GT(camera.farPlane, camera.nearPlane);
    EXPECT_TRUE(std::isfinite(camera.farPlane));
}

} // namespace

TEST(OrbitCamera, FitContainsTheBoundsAtEverySize) {
    // From a millimetre part to a kilometre plant, off the origin, wide and tall windows.
    for (float size : {1e-3f, 1.0f, 5e3f})
        for (float aspect : {0.5f, 1.6f, 3.0f}) {
            const scene::Bounds bounds =
                box(glm::vec3(10.0f, -3.0f, 2.0f) * size, glm::vec3(12.0f, 1.0f, 2.5f) * size);
            app::OrbitCamera camera(opening(bounds, {0, 0, 1}, aspect), bounds);
            camera.orbit({123.0f, -45.0f});
            camera.zoom(6.0f); // somewhere else first: fit must find the scene again
            camera.pan({200.0f, 80.0f}, 720.0f);
            camera.fit(aspect);
            SCOPED_TRACE("size " + std::to_string(size) + " aspect " + std::to_string(aspect));
            expectValidPlanes(camera.camera());
            expectContains(camera.camera(), bounds, aspect);
        }
}

TEST(OrbitCamera, PlanesStayValidWhenZoomedIntoTheScene) {
    const scene::Bounds bounds = box({-500, -500, -20}, {500, 500, 20});
    app::OrbitCamera camera(opening(bounds, {0, 0, 1}, 1.5f), bounds);
    for (int i = 0; i < 200; ++i) {
        camera.zoom(1.0f);
        const scene::Camera c = camera.camera();
        expectValidPlanes(c);
        // The target stays in front of the near plane so what the user zooms to is visible.
        EXPECT_LT(c.nearPlane, glm::length(c.eye - c.target));
    }
}

TEST(OrbitCamera, ReachWidensThePlanesForExplodedViews) {
    const scene::Bounds bounds = box({-1, -1, -1}, {1, 1, 1});
    app::OrbitCamera camera(opening(bounds, {0, 0, 1}, 1.0f), bounds);
    camera.zoom(-6.0f); // back far enough to see the exploded sphere whole
    const scene::Camera rest = camera.camera();
    const scene::Camera exploded = camera.camera(2.0f);
    expectValidPlanes(exploded);
    EXPECT_LT(exploded.nearPlane, rest.nearPlane);
    EXPECT_GT(exploded.farPlane, rest.farPlane);
    expectContains(exploded, box({-2, -2, -2}, {2, 2, 2}), 1.0f);
}

TEST(OrbitCamera, OrbitKeepsTheDistanceAndTarget) {
    const scene::Bounds bounds = box({0, 0, 0}, {2, 3, 1});
    app::OrbitCamera camera(opening(bounds, {0, 1, 0}, 1.0f), bounds);
    const float distance = camera.distance();
    const glm::vec3 target = camera.target();
    for (glm::vec2 drag : {glm::vec2(40, 0), glm::vec2(0, 900), glm::vec2(-333, -2000)}) {
        camera.orbit(drag);
        EXPECT_NEAR(glm::length(camera.eye() - camera.target()), distance, distance * 1e-5f);
        EXPECT_EQ(camera.target(), target);
        // Never over the pole, where the up vector would be undefined.
        const glm::vec3 dir = glm::normalize(camera.eye() - camera.target());
        EXPECT_LT(std::abs(glm::dot(dir, glm::vec3(0, 1, 0))), 0.99999f);
    }
}

TEST(OrbitCamera, ZoomNeverReachesOrCrossesTheTarget) {
    const scene::Bounds bounds = box({-1, -1, -1}, {1, 1, 1});
    app::OrbitCamera camera(opening(bounds, {0, 0, 1}, 1.0f), bounds);
    const glm::vec3 direction = glm::normalize(camera.eye() - camera.target());
    for (float steps : {1.0f, 10.0f, 1e3f, 1e9f}) {
        camera.zoom(steps);
        EXPECT_GT(camera.distance(), 0.0f);
        EXPECT_GT(glm::dot(camera.eye() - camera.target(), direction), 0.0f);
        expectValidPlanes(camera.camera());
    }
    const float closest = camera.distance();
    camera.zoom(-3.0f);
    EXPECT_GT(camera.distance(), closest); // and it comes back out
    camera.zoom(-1e9f);
    EXPECT_TRUE(std::isfinite(camera.distance()));
    expectValidPlanes(camera.camera());
}

TEST(OrbitCamera, PanMovesTargetAndEyeTogether) {
    const scene::Bounds bounds = box({-1, -1, -1}, {1, 1, 1});
    app::OrbitCamera camera(opening(bounds, {0, 0, 1}, 1.0f), bounds);
    const glm::vec3 offset = camera.eye() - camera.target();
    const glm::vec3 target = camera.target();
    camera.pan({50.0f, -20.0f}, 600.0f);
    EXPECT_GT(glm::length(camera.target() - target), 0.0f);
    const glm::vec3 moved = camera.eye() - camera.target();
    EXPECT_NEAR(glm::length(moved - offset), 0.0f, 1e-5f);
}

TEST(OrbitCamera, ResetReturnsToTheOpeningView) {
    const scene::Bounds bounds = box({0, 0, 0}, {4, 1, 2});
    const scene::Camera start = opening(bounds, {0, 0, 1}, 1.5f);
    app::OrbitCamera camera(start, bounds);
    EXPECT_NEAR(glm::length(camera.eye() - start.eye), 0.0f, 1e-4f);
    camera.orbit({300, 100});
    camera.pan({30, 30}, 500);
    camera.zoom(4);
    camera.resetView();
    EXPECT_NEAR(glm::length(camera.eye() - start.eye), 0.0f, 1e-4f);
    EXPECT_NEAR(glm::length(camera.target() - start.target), 0.0f, 1e-5f);
    EXPECT_EQ(camera.camera().up, start.up);
}

// The standard view keys turn the orbit camera to the view scene::turnedTo gives (itself
// checked against FreeCAD's rotations), top and bottom on the poles included, for Z-up and
// Y-up models, at the same target and distance; Home comes back to an opening standard view.
TEST(OrbitCamera, StandardViewsLookAsTheSceneDefinesThem) {
    const scene::Bounds bounds = box({-1, -2, 0}, {3, 1, 2});
    for (glm::vec3 up : {glm::vec3(0, 0, 1), glm::vec3(0, 1, 0)}) {
        const scene::Camera start = opening(bounds, up, 1.5f);
        app::OrbitCamera camera(start, bounds);
        camera.orbit({77, 31});
        for (const scene::StandardView& view : scene::standardViews()) {
            camera.turnTo(view);
            const scene::Camera expected = scene::turnedTo(camera.camera(), view, up);
            const scene::Camera got = camera.camera();
            const glm::mat4 a = got.view(), b = expected.view();
            for (int c = 0; c < 4; ++c)
                EXPECT_LT(glm::length(glm::vec3(a[c]) - glm::vec3(b[c])), 1e-4f * (c == 3 ? 10 : 1))
                    << view.name << " up " << up.y;
            EXPECT_NEAR(camera.distance(), glm::length(start.eye - start.target), 1e-4f);
            // On the poles too, panning and orbiting stay finite.
            app::OrbitCamera moved = camera;
            moved.pan({10, 5}, 500.0f);
            EXPECT_TRUE(std::isfinite(moved.target().x + moved.target().y + moved.target().z))
                << view.name;
            EXPECT_LT(glm::length(moved.target() - camera.target()), bounds.radius()) << view.name;
        }
        app::OrbitCamera top(start, bounds, scene::findStandardView("top"));
        top.orbit({100, 100});
        top.resetView();
        const glm::vec3 down = glm::normalize(top.target() - top.eye());
        EXPECT_NEAR(glm::dot(down, -up), 1.0f, 1e-5f);
    }
}

// F with a selection frames the selection's box, in either projection.
TEST(OrbitCamera, FitFramesTheSelectionInBothProjections) {
    const scene::Bounds scene = box({-100, -100, -10}, {100, 100, 10});
    const scene::Bounds selected = box({40, 50, 0}, {42, 53, 1});
    for (float aspect : {0.6f, 1.8f}) {
        app::OrbitCamera camera(opening(scene, {0, 0, 1}, aspect), scene);
        camera.fit(selected, aspect);
        EXPECT_EQ(camera.target(), selected.center());
        for (bool ortho : {false, true}) {
            expectContains(camera.camera(1.0f, ortho), selected, aspect);
            // Tight: the selection spans much of the view, not a speck of the scene's.
            const scene::Camera c = camera.camera(1.0f, ortho);
            const glm::vec4 clip = c.viewProjection(aspect) *
                                   glm::vec4(selected.center() + glm::vec3(1, 1.5f, 0.5f), 1.0f);
            EXPECT_GT(glm::length(glm::vec2(clip) / clip.w), 0.3f) << "ortho " << ortho;
        }
    }
}

TEST(OrbitCamera, FreeSpanIsTheWiderSideOfThePanel) {
    const app::FreeSpan right = app::freeSpan(1280.0f, 8.0f, 348.0f); // a left column
    EXPECT_FLOAT_EQ(right.left, 348.0f / 1280.0f);
    EXPECT_FLOAT_EQ(right.right, 1.0f);
    const app::FreeSpan left = app::freeSpan(1280.0f, 932.0f, 1272.0f); // moved to the right
    EXPECT_FLOAT_EQ(left.left, 0.0f);
    EXPECT_FLOAT_EQ(left.right, 932.0f / 1280.0f);
    const app::FreeSpan none = app::freeSpan(1280.0f, 0.0f, 0.0f); // hidden
    EXPECT_FLOAT_EQ(none.left, 0.0f);
    EXPECT_FLOAT_EQ(none.right, 1.0f);
    const app::FreeSpan covered = app::freeSpan(400.0f, 8.0f, 348.0f); // too little left
    EXPECT_FLOAT_EQ(covered.right - covered.left, 1.0f);
}

TEST(OrbitCamera, FitBesideThePanelCentresTheBoundsInTheFreeSpan) {
    const float aspect = 1280.0f / 720.0f;
    const scene::Bounds bounds = box({-1.0f, -2.0f, 0.0f}, {3.0f, 1.0f, 2.0f});
    for (bool ortho : {false, true}) {
        app::OrbitCamera camera(opening(bounds, {0, 0, 1}, aspect), bounds);
        const app::FreeSpan span{0.3f, 1.0f};
        camera.fit(bounds, aspect, span);
        const scene::Camera c = camera.camera(1.0f, ortho);
        const glm::mat4 viewProj = camera.shiftMatrix() * c.viewProjection(aspect);
        auto ndc = [&](glm::vec3 p) {
            const glm::vec4 clip = viewProj * glm::vec4(p, 1.0f);
            return glm::vec2(clip) / clip.w;
        };
        // The centre shows in the middle of the span (device x from -1 to 1)...
        EXPECT_NEAR(ndc(bounds.center()).x, span.left + span.right - 1.0f, 1e-4f) << ortho;
        // ...and every corner inside it.
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 p((corner & 1) ? bounds.max.x : bounds.min.x,
                              (corner & 2) ? bounds.max.y : bounds.min.y,
                              (corner & 4) ? bounds.max.z : bounds.min.z);
            EXPECT_GE(ndc(p).x, 2.0f * span.left - 1.0f - 1e-4f) << ortho << " " << corner;
            EXPECT_LE(ndc(p).x, 1.0f + 1e-4f) << ortho << " " << corner;
            EXPECT_LE(std::abs(ndc(p).y), 1.0f + 1e-4f) << ortho << " " << corner;
        }
        camera.resetView(); // Home takes the shift back
        EXPECT_EQ(camera.shift(), 0.0f);
    }
}
