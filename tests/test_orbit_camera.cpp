// test_orbit_camera.cpp - the viewer camera's maths: fitting contains the scene, the planes
// stay valid for any model size and zoom, orbiting keeps the distance, zoom never crosses
// the target, and reset returns to the opening view.
#include <gtest/gtest.h>

#include <cmath>

#include "app/viewer/state/orbit_camera.h"

namespace {

scene::Bounds box(glm::dvec3 min, glm::dvec3 max) {
    scene::Bounds b;
    b.min = min;
    b.max = max;
    return b;
}

scene::Camera opening(const scene::Bounds& bounds, glm::dvec3 up, double aspect) {
    return scene::fitCamera(bounds, glm::dvec3(0.9, -1.6, 1.2), up, glm::radians(40.0), aspect);
}

// Every corner of `bounds` lies inside the camera's view volume.
void expectContains(const scene::Camera& camera, const scene::Bounds& bounds, double aspect) {
    const glm::dmat4 viewProj = camera.viewProjection(aspect);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p((corner & 1) ? bounds.max.x : bounds.min.x,
                           (corner & 2) ? bounds.max.y : bounds.min.y,
                           (corner & 4) ? bounds.max.z : bounds.min.z);
        const glm::dvec4 clip = viewProj * glm::dvec4(p, 1.0);
        ASSERT_GT(clip.w, 0.0);
        const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
        EXPECT_LE(std::abs(ndc.x), 1.0 + 1e-4) << "corner " << corner;
        EXPECT_LE(std::abs(ndc.y), 1.0 + 1e-4) << "corner " << corner;
        EXPECT_GE(ndc.z, -1e-5) << "corner " << corner;
        EXPECT_LE(ndc.z, 1.0 + 1e-5) << "corner " << corner;
    }
}

void expectValidPlanes(const scene::Camera& camera) {
    EXPECT_GT(camera.nearPlane, 0.0);
    EXPECT_GT(camera.farPlane, camera.nearPlane);
    EXPECT_TRUE(std::isfinite(camera.farPlane));
}

} // namespace

TEST(OrbitCamera, FitContainsTheBoundsAtEverySize) {
    // From a millimetre part to a kilometre plant, off the origin, wide and tall windows.
    for (double size : {1e-3, 1.0, 5e3})
        for (double aspect : {0.5, 1.6, 3.0}) {
            const scene::Bounds bounds =
                box(glm::dvec3(10.0, -3.0, 2.0) * size, glm::dvec3(12.0, 1.0, 2.5) * size);
            app::OrbitCamera camera(opening(bounds, {0, 0, 1}, aspect), bounds);
            camera.orbit({123.0, -45.0});
            camera.zoom(6.0); // somewhere else first: fit must find the scene again
            camera.pan({200.0, 80.0}, 720.0);
            camera.fit(aspect);
            SCOPED_TRACE("size " + std::to_string(size) + " aspect " + std::to_string(aspect));
            expectValidPlanes(camera.camera());
            expectContains(camera.camera(), bounds, aspect);
        }
}

TEST(OrbitCamera, PlanesStayValidWhenZoomedIntoTheScene) {
    const scene::Bounds bounds = box({-500, -500, -20}, {500, 500, 20});
    app::OrbitCamera camera(opening(bounds, {0, 0, 1}, 1.5), bounds);
    for (int i = 0; i < 200; ++i) {
        camera.zoom(1.0);
        const scene::Camera c = camera.camera();
        expectValidPlanes(c);
        // The target stays in front of the near plane so what the user zooms to is visible.
        EXPECT_LT(c.nearPlane, glm::length(c.eye - c.target));
    }
}

TEST(OrbitCamera, ReachWidensThePlanesForExplodedViews) {
    const scene::Bounds bounds = box({-1, -1, -1}, {1, 1, 1});
    app::OrbitCamera camera(opening(bounds, {0, 0, 1}, 1.0), bounds);
    camera.zoom(-6.0); // back far enough to see the exploded sphere whole
    const scene::Camera rest = camera.camera();
    const scene::Camera exploded = camera.camera(2.0);
    expectValidPlanes(exploded);
    EXPECT_LT(exploded.nearPlane, rest.nearPlane);
    EXPECT_GT(exploded.farPlane, rest.farPlane);
    expectContains(exploded, box({-2, -2, -2}, {2, 2, 2}), 1.0);
}

TEST(OrbitCamera, OrbitKeepsTheDistanceAndTarget) {
    const scene::Bounds bounds = box({0, 0, 0}, {2, 3, 1});
    app::OrbitCamera camera(opening(bounds, {0, 1, 0}, 1.0), bounds);
    const double distance = camera.distance();
    const glm::dvec3 target = camera.target();
    for (glm::vec2 drag : {glm::vec2(40, 0), glm::vec2(0, 900), glm::vec2(-333, -2000)}) {
        camera.orbit(drag);
        EXPECT_NEAR(glm::length(camera.eye() - camera.target()), distance, distance * 1e-5);
        EXPECT_EQ(camera.target(), target);
        // Never over the pole, where the up vector would be undefined.
        const glm::dvec3 dir = glm::normalize(camera.eye() - camera.target());
        EXPECT_LT(std::abs(glm::dot(dir, glm::dvec3(0, 1, 0))), 0.99999);
    }
}

TEST(OrbitCamera, ZoomNeverReachesOrCrossesTheTarget) {
    const scene::Bounds bounds = box({-1, -1, -1}, {1, 1, 1});
    app::OrbitCamera camera(opening(bounds, {0, 0, 1}, 1.0), bounds);
    const glm::dvec3 direction = glm::normalize(camera.eye() - camera.target());
    for (double steps : {1.0, 10.0, 1e3, 1e9}) {
        camera.zoom(steps);
        EXPECT_GT(camera.distance(), 0.0);
        EXPECT_GT(glm::dot(camera.eye() - camera.target(), direction), 0.0);
        expectValidPlanes(camera.camera());
    }
    const double closest = camera.distance();
    camera.zoom(-3.0);
    EXPECT_GT(camera.distance(), closest); // and it comes back out
    camera.zoom(-1e9);
    EXPECT_TRUE(std::isfinite(camera.distance()));
    expectValidPlanes(camera.camera());
}

TEST(OrbitCamera, PanMovesTargetAndEyeTogether) {
    const scene::Bounds bounds = box({-1, -1, -1}, {1, 1, 1});
    app::OrbitCamera camera(opening(bounds, {0, 0, 1}, 1.0), bounds);
    const glm::dvec3 offset = camera.eye() - camera.target();
    const glm::dvec3 target = camera.target();
    camera.pan({50.0, -20.0}, 600.0);
    EXPECT_GT(glm::length(camera.target() - target), 0.0);
    const glm::dvec3 moved = camera.eye() - camera.target();
    EXPECT_NEAR(glm::length(moved - offset), 0.0, 1e-5);
}

TEST(OrbitCamera, ResetReturnsToTheOpeningView) {
    const scene::Bounds bounds = box({0, 0, 0}, {4, 1, 2});
    const scene::Camera start = opening(bounds, {0, 0, 1}, 1.5);
    app::OrbitCamera camera(start, bounds);
    EXPECT_NEAR(glm::length(camera.eye() - start.eye), 0.0, 1e-4);
    camera.orbit({300, 100});
    camera.pan({30, 30}, 500);
    camera.zoom(4);
    camera.resetView();
    EXPECT_NEAR(glm::length(camera.eye() - start.eye), 0.0, 1e-4);
    EXPECT_NEAR(glm::length(camera.target() - start.target), 0.0, 1e-5);
    EXPECT_EQ(camera.camera().up, start.up);
}

// The standard view keys turn the orbit camera to the view scene::turnedTo gives (itself
// checked against FreeCAD's rotations), top and bottom on the poles included, for Z-up and
// Y-up models, at the same target and distance; Home comes back to an opening standard view.
TEST(OrbitCamera, StandardViewsLookAsTheSceneDefinesThem) {
    const scene::Bounds bounds = box({-1, -2, 0}, {3, 1, 2});
    for (glm::dvec3 up : {glm::dvec3(0, 0, 1), glm::dvec3(0, 1, 0)}) {
        const scene::Camera start = opening(bounds, up, 1.5);
        app::OrbitCamera camera(start, bounds);
        camera.orbit({77, 31});
        for (const scene::StandardView& view : scene::standardViews()) {
            camera.turnTo(view);
            const scene::Camera expected = scene::turnedTo(camera.camera(), view, up);
            const scene::Camera got = camera.camera();
            const glm::dmat4 a = got.view(), b = expected.view();
            for (int c = 0; c < 4; ++c)
                EXPECT_LT(glm::length(glm::dvec3(a[c]) - glm::dvec3(b[c])),
                          1e-4 * (c == 3 ? 10 : 1))
                    << view.name << " up " << up.y;
            EXPECT_NEAR(camera.distance(), glm::length(start.eye - start.target), 1e-4);
            // On the poles too, panning and orbiting stay finite.
            app::OrbitCamera moved = camera;
            moved.pan({10, 5}, 500.0);
            EXPECT_TRUE(std::isfinite(moved.target().x + moved.target().y + moved.target().z))
                << view.name;
            EXPECT_LT(glm::length(moved.target() - camera.target()), bounds.radius()) << view.name;
        }
        app::OrbitCamera top(start, bounds, scene::findStandardView("top"));
        top.orbit({100, 100});
        top.resetView();
        const glm::dvec3 down = glm::normalize(top.target() - top.eye());
        EXPECT_NEAR(glm::dot(down, -up), 1.0, 1e-5);
    }
}

// F with a selection frames the selection's box, in either projection.
TEST(OrbitCamera, FitFramesTheSelectionInBothProjections) {
    const scene::Bounds scene = box({-100, -100, -10}, {100, 100, 10});
    const scene::Bounds selected = box({40, 50, 0}, {42, 53, 1});
    for (double aspect : {0.6, 1.8}) {
        app::OrbitCamera camera(opening(scene, {0, 0, 1}, aspect), scene);
        camera.fit(selected, aspect);
        EXPECT_EQ(camera.target(), selected.center());
        for (bool ortho : {false, true}) {
            expectContains(camera.camera(1.0, ortho), selected, aspect);
            // Tight: the selection spans much of the view, not a speck of the scene's.
            const scene::Camera c = camera.camera(1.0, ortho);
            const glm::dvec4 clip = c.viewProjection(aspect) *
                                    glm::dvec4(selected.center() + glm::dvec3(1, 1.5, 0.5), 1.0);
            EXPECT_GT(glm::length(glm::dvec2(clip) / clip.w), 0.3) << "ortho " << ortho;
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
    EXPECT_DOUBLE_EQ(none.right, 1.0);
    const app::FreeSpan covered = app::freeSpan(400.0, 8.0, 348.0); // too little left
    EXPECT_DOUBLE_EQ(covered.right - covered.left, 1.0);
}

TEST(OrbitCamera, FitBesideThePanelCentresTheBoundsInTheFreeSpan) {
    const double aspect = 1280.0 / 720.0;
    const scene::Bounds bounds = box({-1.0, -2.0, 0.0}, {3.0, 1.0, 2.0});
    for (bool ortho : {false, true}) {
        app::OrbitCamera camera(opening(bounds, {0, 0, 1}, aspect), bounds);
        const app::FreeSpan span{0.3, 1.0};
        camera.fit(bounds, aspect, span);
        const scene::Camera c = camera.camera(1.0, ortho);
        const glm::dmat4 viewProj = camera.shiftMatrix() * c.viewProjection(aspect);
        auto ndc = [&](glm::dvec3 p) {
            const glm::dvec4 clip = viewProj * glm::dvec4(p, 1.0);
            return glm::vec2(glm::dvec2(clip) / clip.w);
        };
        // The centre shows in the middle of the span (device x from -1 to 1)...
        EXPECT_NEAR(ndc(bounds.center()).x, span.left + span.right - 1.0, 1e-4) << ortho;
        // ...and every corner inside it.
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 p((corner & 1) ? bounds.max.x : bounds.min.x,
                               (corner & 2) ? bounds.max.y : bounds.min.y,
                               (corner & 4) ? bounds.max.z : bounds.min.z);
            EXPECT_GE(ndc(p).x, 2.0 * span.left - 1.0 - 1e-4) << ortho << " " << corner;
            EXPECT_LE(ndc(p).x, 1.0 + 1e-4) << ortho << " " << corner;
            EXPECT_LE(std::abs(ndc(p).y), 1.0 + 1e-4) << ortho << " " << corner;
        }
        camera.resetView(); // Home takes the shift back
        EXPECT_EQ(camera.shift(), 0.0);
    }
}
