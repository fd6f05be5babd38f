// orbit_camera.cpp - orbit, pan, zoom, fit and the standard views, and the near/far planes
// that follow the eye.
#include "app/viewer/orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

namespace app {
namespace {

// Orbiting stops just short of the poles, so that dragging keeps turning about the model's
// up axis; only the top and bottom views stand on them.
constexpr float maxPitch = 1.5607963f; // pi/2 - 0.01

// Scenes of a single point (or none) still get a usable camera.
float usableRadius(const scene::Bounds& bounds) {
    const float radius = bounds.radius();
    return std::isfinite(radius) && radius > 0.0f ? radius : 1.0f;
}

// Less free than this (a fraction of the width) and F uses the whole window after all.
constexpr float narrowestSpan = 0.25f;

} // namespace

FreeSpan freeSpan(float windowWidth, float panelLeft, float panelRight) {
    if (!(windowWidth > 0.0f) || !(panelRight > panelLeft)) return {};
    const float left = std::clamp(panelLeft / windowWidth, 0.0f, 1.0f);
    const float right = std::clamp(panelRight / windowWidth, 0.0f, 1.0f);
    const FreeSpan span = 1.0f - right >= left ? FreeSpan{right, 1.0f} : FreeSpan{0.0f, left};
    return span.right - span.left < narrowestSpan ? FreeSpan{} : span;
}

OrbitCamera::OrbitCamera(const scene::Camera& initial, const scene::Bounds& bounds,
                         const scene::StandardView* opening)
    : bounds_(bounds), initial_(initial), opening_(opening) {
    resetView();
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
    shift_ = 0.0f;
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

glm::vec3 OrbitCamera::viewUp() const {
    return -std::sin(pitch_) * (std::cos(yaw_) * a_ + std::sin(yaw_) * b_) + std::cos(pitch_) * up_;
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
    const glm::vec3 right = glm::normalize(glm::cross(forward, viewUp()));
    const glm::vec3 viewUp = glm::cross(right, forward);
    target_ += (-right * pixels.x + viewUp * pixels.y) * scale;
}

void OrbitCamera::zoom(float steps) {
    distance_ *= zoomFactor(steps);
}

float OrbitCamera::zoomFactor(float steps) const {
    // Multiplying keeps the distance positive whatever the steps; the bounds keep it from
    // vanishing (float underflow) or running away.
    const float radius = usableRadius(bounds_);
    const float distance =
        std::clamp(distance_ * std::pow(zoomPerStep, steps), radius * 1e-5f, radius * 1e4f);
    return distance / distance_;
}

void OrbitCamera::zoomToward(glm::vec3 point, float steps) {
    const float factor = zoomFactor(steps);
    target_ = point + (target_ - point) * factor;
    distance_ *= factor;
}

void OrbitCamera::fit(float aspect, FreeSpan span) {
    fit(bounds_, aspect, span);
}

void OrbitCamera::fit(const scene::Bounds& what, float aspect, FreeSpan span) {
    const float radius = usableRadius(what);
    const float width = std::clamp(span.right - span.left, 1e-3f, 1.0f);
    aspect *= width;                        // the span's own aspect decides the distance
    shift_ = span.left + span.right - 1.0f; // the span's middle, in device coordinates
    // The narrower of the two fields of view decides, as in scene::fitCamera; the
    // orthographic view of that distance is taller than the sphere (Camera::orthoHeight).
    const float halfFov =
        0.5f * std::min(fovY_, 2.0f * std::atan(std::tan(0.5f * fovY_) * std::max(aspect, 1e-3f)));
    target_ = what.center();
    distance_ = radius / std::sin(halfFov);
}

glm::mat4 OrbitCamera::shiftMatrix() const {
    // x' = x + shift * w: in clip space, so perspective and ortho both move by `shift`.
    glm::mat4 m(1.0f);
    m[3][0] = shift_;
    return m;
}

void OrbitCamera::turnTo(const scene::StandardView& view) {
    const glm::mat3 frame = scene::modelFrame(up_);
    const glm::vec3 d = glm::normalize(frame * view.toEye);
    const float along = glm::dot(d, up_);
    if (std::abs(along) > 0.9999f) {
        // Top or bottom: on the pole, where the yaw only says which way the screen's up
        // points (viewUp): away from the horizontal direction at the top, towards it below.
        pitch_ = std::copysign(0.5f * glm::pi<float>(), along);
        const glm::vec3 h = -std::copysign(1.0f, along) * glm::normalize(frame * view.screenUp);
        yaw_ = std::atan2(glm::dot(h, b_), glm::dot(h, a_));
    } else {
        pitch_ = std::asin(along);
        yaw_ = std::atan2(glm::dot(d, b_), glm::dot(d, a_));
    }
}

void OrbitCamera::resetView() {
    if (home_) {
        target_ = home_->target;
        distance_ = home_->distance;
        yaw_ = home_->yaw;
        pitch_ = home_->pitch;
        shift_ = home_->shift;
        return;
    }
    setFrom(initial_);
    if (opening_) turnTo(*opening_);
}

void OrbitCamera::setHome() {
    home_ = Home{target_, distance_, yaw_, pitch_, shift_};
}

scene::Camera OrbitCamera::camera(float reach, bool ortho) const {
    scene::Camera camera;
    camera.eye = eye();
    camera.target = target_;
    // Off the poles lookAt takes the model's up as it always did; on them only viewUp works.
    camera.up = std::abs(pitch_) > maxPitch ? viewUp() : up_;
    camera.fovY = fovY_;
    camera.ortho = ortho;
    scene::fitPlanes(camera, bounds_, reach);
    return camera;
}

} // namespace app
