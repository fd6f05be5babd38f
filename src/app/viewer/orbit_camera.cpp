// orbit_camera.cpp - orbit, pan, zoom and fit, and the near/far planes that follow the eye.
#include "app/viewer/orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

namespace app {
namespace {

// Just short of the poles: at the pole itself the view's up vector would be undefined.
constexpr float maxPitch = 1.5607963f; // pi/2 - 0.01

// Scenes of a single point (or none) still get a usable camera.
float usableRadius(const scene::Bounds& bounds) {
    const float radius = bounds.radius();
    return std::isfinite(radius) && radius > 0.0f ? radius : 1.0f;
}

} // namespace

OrbitCamera::OrbitCamera(const scene::Camera& initial, const scene::Bounds& bounds)
    : bounds_(bounds), initial_(initial) {
    setFrom(initial);
}

void OrbitCamera::setFrom(const scene::Camera& camera) {
    up_ = glm::normalize(camera.up);
    // Any vector not along up gives the horizontal frame; glTF (y-up) gets a = z, b = x and
    // the built-in scenes (z-up) a = x, b = y, so yaw 0 looks along a familiar axis.
    const glm::vec3 helper = std::abs(up_.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
    a_ = glm::normalize(helper - glm::dot(helper, up_) * up_);
    b_ = glm::cross(up_, a_);
    target_ = camera.target;
    fovY_ = camera.fovY;
    const glm::vec3 offset = camera.eye - camera.target;
    distance_ = glm::length(offset);
    if (!(distance_ > 0.0f)) {
        distance_ = usableRadius(bounds_);
        yaw_ = pitch_ = 0.0f;
        return;
    }
    const glm::vec3 d = offset / distance_;
    pitch_ = std::clamp(std::asin(std::clamp(glm::dot(d, up_), -1.0f, 1.0f)), -maxPitch, maxPitch);
    yaw_ = std::atan2(glm::dot(d, b_), glm::dot(d, a_));
}

void OrbitCamera::setBounds(const scene::Bounds& bounds) {
    bounds_ = bounds;
}

glm::vec3 OrbitCamera::direction() const {
    return std::cos(pitch_) * (std::cos(yaw_) * a_ + std::sin(yaw_) * b_) + std::sin(pitch_) * up_;
}

glm::vec3 OrbitCamera::eye() const {
    return target_ + direction() * distance_;
}

void OrbitCamera::orbit(glm::vec2 pixels) {
    // Dragging right turns the model right (the eye goes left); dragging down shows the top.
    yaw_ = std::remainder(yaw_ - pixels.x * radiansPerPixel, 2.0f * glm::pi<float>());
    pitch_ = std::clamp(pitch_ + pixels.y * radiansPerPixel, -maxPitch, maxPitch);
}

void OrbitCamera::pan(glm::vec2 pixels, float viewportHeight) {
    // World units per pixel at the target's depth, so the target follows the cursor.
    const float scale = 2.0f * distance_ * std::tan(0.5f * fovY_) / std::max(viewportHeight, 1.0f);
    const glm::vec3 forward = -direction();
    const glm::vec3 right = glm::normalize(glm::cross(forward, up_));
    const glm::vec3 viewUp = glm::cross(right, forward);
    target_ += (-right * pixels.x + viewUp * pixels.y) * scale;
}

void OrbitCamera::zoom(float steps) {
    // Multiplying keeps the distance positive whatever the steps; the bounds keep it from
    // vanishing (float underflow) or running away.
    const float radius = usableRadius(bounds_);
    distance_ = std::clamp(distance_ * std::pow(zoomPerStep, steps), radius * 1e-5f, radius * 1e4f);
}

void OrbitCamera::fit(float aspect) {
    const float radius = usableRadius(bounds_);
    // The narrower of the two fields of view decides, as in scene::fitCamera.
    const float halfFov =
        0.5f * std::min(fovY_, 2.0f * std::atan(std::tan(0.5f * fovY_) * std::max(aspect, 1e-3f)));
    target_ = bounds_.center();
    distance_ = radius / std::sin(halfFov);
}

void OrbitCamera::resetView() {
    setFrom(initial_);
}

scene::Camera OrbitCamera::camera(float reach) const {
    scene::Camera camera;
    camera.eye = eye();
    camera.target = target_;
    camera.up = up_;
    camera.fovY = fovY_;
    scene::fitPlanes(camera, bounds_, reach);
    return camera;
}

} // namespace app
