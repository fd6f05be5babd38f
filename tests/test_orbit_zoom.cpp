// test_orbit_zoom.cpp - the wheel's zoom toward the point under the cursor
// (OrbitCamera::zoomToward): the point stays at its pixel in both projections, beside the
// panel too, over several steps in and out, and the orbit target closes in on it.
#include <gtest/gtest.h>

#include <cmath>

#include "app/viewer/orbit_camera.h"

namespace {

constexpr glm::vec2 windowSize(1280.0f, 720.0f);

scene::Bounds box(glm::vec3 min, glm::vec3 max) {
    scene::Bounds b;
    b.min = min;
    b.max = max;
    return b;
}

// Where `point` shows in the window, in pixels, as the viewer draws it (lens shift included).
glm::vec2 pixelOf(const app::OrbitCamera& camera, bool ortho, glm::vec3 point) {
    const float aspect = windowSize.x / windowSize.y;
    const glm::mat4 viewProj =
        camera.shiftMatrix() * camera.camera(1.0f, ortho).viewProjection(aspect);
    const glm::vec4 clip = viewProj * glm::vec4(point, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return (ndc * 0.5f + 0.5f) * windowSize;
}

app::OrbitCamera openedCamera(const scene::Bounds& bounds) {
    const scene::Camera start = scene::fitCamera(bounds, glm::vec3(0.9f, -1.6f, 1.2f), {0, 0, 1},
                                                 glm::radians(40.0f), windowSize.x / windowSize.y);
    app::OrbitCamera camera(start, bounds);
    camera.fit(bounds, windowSize.x / windowSize.y, app::FreeSpan{0.3f, 1.0f}); // the panel
    return camera;
}

} // namespace

TEST(OrbitZoom, ThePointUnderTheCursorKeepsItsPixel) {
    const scene::Bounds bounds = box({-40.0f, -25.0f, 0.0f}, {60.0f, 30.0f, 20.0f});
    // A corner of the model far from the target, and a point on the near face.
    for (const glm::vec3 point : {glm::vec3(55.0f, -20.0f, 18.0f), glm::vec3(-30.0f, 10.0f, 2.0f)})
        for (bool ortho : {false, true}) {
            app::OrbitCamera camera = openedCamera(bounds);
            const glm::vec2 before = pixelOf(camera, ortho, point);
            ASSERT_GT(glm::distance(before, pixelOf(camera, ortho, camera.target())), 100.0f);
            for (float steps : {1.0f, 1.0f, 3.0f, -2.0f, 1.0f, 4.0f, -1.0f}) {
                camera.zoomToward(point, steps);
                EXPECT_LT(glm::distance(pixelOf(camera, ortho, point), before), 1.0f)
                    << "ortho " << ortho << " after " << steps << " steps";
            }
            // What plain zoom does, for contrast: the point slides toward the target.
            app::OrbitCamera plain = openedCamera(bounds);
            plain.zoom(5.0f);
            EXPECT_GT(glm::distance(pixelOf(plain, ortho, point), before), 10.0f);
        }
}

TEST(OrbitZoom, TheTargetClosesInOnThePointAndTheViewKeepsItsDirection) {
    const scene::Bounds bounds = box({-40.0f, -25.0f, 0.0f}, {60.0f, 30.0f, 20.0f});
    const glm::vec3 point(55.0f, -20.0f, 18.0f);
    app::OrbitCamera camera = openedCamera(bounds);
    const glm::vec3 direction = glm::normalize(camera.eye() - camera.target());
    const float before = glm::distance(camera.target(), point);
    const float distance = camera.distance();
    camera.zoomToward(point, 4.0f);
    const float factor = std::pow(app::OrbitCamera::zoomPerStep, 4.0f);
    // Closer by the zoom's factor, so the next orbit turns near what the user zoomed into...
    EXPECT_NEAR(glm::distance(camera.target(), point), before * factor, 1e-3f * before);
    EXPECT_NEAR(camera.distance(), distance * factor, 1e-4f * distance);
    // ...and zooming out again moves it back, the view never turning.
    camera.zoomToward(point, -4.0f);
    EXPECT_NEAR(glm::distance(camera.target(), point), before, 1e-3f * before);
    EXPECT_LT(glm::distance(glm::normalize(camera.eye() - camera.target()), direction), 1e-5f);
}

TEST(OrbitZoom, TheDistanceStaysWithinTheZoomLimits) {
    const scene::Bounds bounds = box({-1.0f, -1.0f, -1.0f}, {1.0f, 1.0f, 1.0f});
    app::OrbitCamera camera = openedCamera(bounds);
    const glm::vec3 point(0.9f, 0.9f, 0.9f);
    const glm::vec2 before = pixelOf(camera, false, point);
    for (int i = 0; i < 30; ++i) camera.zoomToward(point, 1.0f); // a hundred times closer
    EXPECT_LT(glm::distance(pixelOf(camera, false, point), before), 1.0f);
    // Far past the closest limit, where floats no longer place the eye to a pixel: the limit
    // holds, and steps past it move nothing.
    for (int i = 0; i < 200; ++i) camera.zoomToward(point, 1.0f);
    EXPECT_GE(camera.distance(), bounds.radius() * 1e-5f * 0.999f);
    const glm::vec3 target = camera.target();
    camera.zoomToward(point, 1.0f);
    EXPECT_EQ(camera.target(), target);
}

TEST(OrbitZoom, HomeComesBackToTheViewSetHomeKept) {
    const scene::Bounds bounds = box({-40.0f, -25.0f, 0.0f}, {60.0f, 30.0f, 20.0f});
    app::OrbitCamera camera = openedCamera(bounds); // fitted beside the panel
    camera.setHome();
    const glm::vec3 eye = camera.eye(), target = camera.target();
    const float shift = camera.shift();
    ASSERT_NE(shift, 0.0f);
    camera.zoomToward({55.0f, -20.0f, 18.0f}, 3.0f);
    camera.orbit({120.0f, -40.0f});
    camera.pan({30.0f, 10.0f}, 720.0f);
    camera.fit(bounds, 1.5f); // a fit over the whole window drops the shift
    camera.resetView();
    EXPECT_LT(glm::distance(camera.eye(), eye), 1e-4f * glm::distance(eye, target));
    EXPECT_LT(glm::distance(camera.target(), target), 1e-4f * glm::distance(eye, target));
    EXPECT_EQ(camera.shift(), shift);
}
