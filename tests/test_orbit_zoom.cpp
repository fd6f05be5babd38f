// test_orbit_zoom.cpp - the wheel's zoom toward the point under the cursor
// (OrbitCamera::zoomToward): the point stays at its pixel in both projections, beside the
// panel too, over several steps in and out, and the orbit target closes in on it.
#include <gtest/gtest.h>

#include <cmath>

#include "app/viewer/state/orbit_camera.h"

namespace {

constexpr glm::vec2 windowSize(1280.0, 720.0);

scene::Bounds box(glm::dvec3 min, glm::dvec3 max) {
    scene::Bounds b;
    b.min = min;
    b.max = max;
    return b;
}

// Where `point` shows in the window, in pixels, as the viewer draws it (lens shift included).
glm::vec2 pixelOf(const app::OrbitCamera& camera, bool ortho, glm::dvec3 point) {
    const double aspect = windowSize.x / windowSize.y;
    const glm::dmat4 viewProj =
        camera.shiftMatrix() * camera.camera(1.0, ortho).viewProjection(aspect);
    const glm::dvec4 clip = viewProj * glm::dvec4(point, 1.0);
    const glm::vec2 ndc = glm::vec2(glm::dvec2(clip) / clip.w);
    return (ndc * 0.5f + 0.5f) * windowSize;
}

app::OrbitCamera openedCamera(const scene::Bounds& bounds) {
    const scene::Camera start = scene::fitCamera(bounds, glm::dvec3(0.9, -1.6, 1.2), {0, 0, 1},
                                                 glm::radians(40.0), windowSize.x / windowSize.y);
    app::OrbitCamera camera(start, bounds);
    camera.fit(bounds, windowSize.x / windowSize.y, app::FreeSpan{0.3, 1.0}); // the panel
    return camera;
}

} // namespace

TEST(OrbitZoom, ThePointUnderTheCursorKeepsItsPixel) {
    const scene::Bounds bounds = box({-40.0, -25.0, 0.0}, {60.0, 30.0, 20.0});
    // A corner of the model far from the target, and a point on the near face.
    for (const glm::dvec3 point : {glm::dvec3(55.0, -20.0, 18.0), glm::dvec3(-30.0, 10.0, 2.0)})
        for (bool ortho : {false, true}) {
            app::OrbitCamera camera = openedCamera(bounds);
            const glm::vec2 before = pixelOf(camera, ortho, point);
            ASSERT_GT(glm::distance(before, pixelOf(camera, ortho, camera.target())), 100.0);
            for (double steps : {1.0, 1.0, 3.0, -2.0, 1.0, 4.0, -1.0}) {
                camera.zoomToward(point, steps);
                EXPECT_LT(glm::distance(pixelOf(camera, ortho, point), before), 1.0)
                    << "ortho " << ortho << " after " << steps << " steps";
            }
            // What plain zoom does, for contrast: the point slides toward the target.
            app::OrbitCamera plain = openedCamera(bounds);
            plain.zoom(5.0);
            EXPECT_GT(glm::distance(pixelOf(plain, ortho, point), before), 10.0);
        }
}

TEST(OrbitZoom, TheTargetClosesInOnThePointAndTheViewKeepsItsDirection) {
    const scene::Bounds bounds = box({-40.0, -25.0, 0.0}, {60.0, 30.0, 20.0});
    const glm::dvec3 point(55.0, -20.0, 18.0);
    app::OrbitCamera camera = openedCamera(bounds);
    const glm::dvec3 direction = glm::normalize(camera.eye() - camera.target());
    const double before = glm::distance(camera.target(), point);
    const double distance = camera.distance();
    camera.zoomToward(point, 4.0);
    const double factor = std::pow(app::OrbitCamera::zoomPerStep, 4.0);
    // Closer by the zoom's factor, so the next orbit turns near what the user zoomed into...
    EXPECT_NEAR(glm::distance(camera.target(), point), before * factor, 1e-3 * before);
    EXPECT_NEAR(camera.distance(), distance * factor, 1e-4 * distance);
    // ...and zooming out again moves it back, the view never turning.
    camera.zoomToward(point, -4.0);
    EXPECT_NEAR(glm::distance(camera.target(), point), before, 1e-3 * before);
    EXPECT_LT(glm::distance(glm::normalize(camera.eye() - camera.target()), direction), 1e-5);
}

TEST(OrbitZoom, TheDistanceStaysWithinTheZoomLimits) {
    const scene::Bounds bounds = box({-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0});
    app::OrbitCamera camera = openedCamera(bounds);
    const glm::dvec3 point(0.9, 0.9, 0.9);
    const glm::vec2 before = pixelOf(camera, false, point);
    for (int i = 0; i < 30; ++i) camera.zoomToward(point, 1.0); // a hundred times closer
    EXPECT_LT(glm::distance(pixelOf(camera, false, point), before), 1.0);
    // Far past the closest limit, where floats no longer place the eye to a pixel: the limit
    // holds, and steps past it move nothing.
    for (int i = 0; i < 200; ++i) camera.zoomToward(point, 1.0);
    EXPECT_GE(camera.distance(), bounds.radius() * 1e-5 * 0.999);
    const glm::dvec3 target = camera.target();
    camera.zoomToward(point, 1.0);
    EXPECT_EQ(camera.target(), target);
}

TEST(OrbitZoom, HomeComesBackToTheViewSetHomeKept) {
    const scene::Bounds bounds = box({-40.0, -25.0, 0.0}, {60.0, 30.0, 20.0});
    app::OrbitCamera camera = openedCamera(bounds); // fitted beside the panel
    camera.setHome();
    const glm::dvec3 eye = camera.eye(), target = camera.target();
    const double shift = camera.shift();
    ASSERT_NE(shift, 0.0);
    camera.zoomToward({55.0, -20.0, 18.0}, 3.0);
    camera.orbit({120.0, -40.0});
    camera.pan({30.0, 10.0}, 720.0);
    camera.fit(bounds, 1.5); // a fit over the whole window drops the shift
    camera.resetView();
    EXPECT_LT(glm::distance(camera.eye(), eye), 1e-4 * glm::distance(eye, target));
    EXPECT_LT(glm::distance(camera.target(), target), 1e-4 * glm::distance(eye, target));
    EXPECT_EQ(camera.shift(), shift);
}
