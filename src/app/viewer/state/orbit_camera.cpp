// orbit_camera.cpp - orbit, pan, zoom, fit and the standard views, and the near/far planes
// that follow the eye.
#include "app/viewer/state/orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

namespace app {
namespace {

// Orbiting stops just short of the poles, so that dragging keeps turning about the model's
// up axis; only the top and bottom views stand on them.
constexpr double maxPitch = 1.5607963; // pi/2 - 0.01

// Scenes of a single point (or none) still get a usable camera.
double usableRadius(const scene::Bounds& bounds) {
    const double radius = bounds.radius();
    return std::isfinite(radius) && radius > 0.0 ? radius : 1.0;
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
    const glm::dvec3 helper = std::abs(up_.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    a_ = glm::normalize(helper - glm::dot(helper, up_) * up_);
    b_ = glm::cross(up_, a_);
    target_ = camera.target;
    fovY_ = camera.fovY;
    shift_ = 0.0;
    const glm::dvec3 offset = camera.eye - camera.target;
    distance_ = glm::length(offset);
    if (!(distance_ > 0.0)) {
        distance_ = usableRadius(bounds_);
        yaw_ = pitch_ = 0.0;
        return;
    }
    const glm::dvec3 d = offset / distance_;
    pitch_ = std::clamp(std::asin(std::clamp(glm::dot(d, up_), -1.0, 1.0)), -maxPitch, maxPitch);
    yaw_ = std::atan2(glm::dot(d, b_), glm::dot(d, a_));
}

void OrbitCamera::setBounds(const scene::Bounds& bounds) {
    bounds_ = bounds;
}

glm::dvec3 OrbitCamera::direction() const {
    return std::cos(pitch_) * (std::cos(yaw_) * a_ + std::sin(yaw_) * b_) + std::sin(pitch_) * up_;
}

glm::dvec3 OrbitCamera::viewUp() const {
    return -std::sin(pitch_) * (std::cos(yaw_) * a_ + std::sin(yaw_) * b_) + std::cos(pitch_) * up_;
}

glm::dvec3 OrbitCamera::eye() const {
    return target_ + direction() * distance_;
}

void OrbitCamera::orbit(glm::vec2 pixels) {
    // Dragging right turns the model right (the eye goes left); dragging down shows the top.
    yaw_ = std::remainder(yaw_ - pixels.x * radiansPerPixel, 2.0 * glm::pi<double>());
    pitch_ = std::clamp(pitch_ + pixels.y * radiansPerPixel, -maxPitch, maxPitch);
}

void OrbitCamera::pan(glm::vec2 pixels, double viewportHeight) {
    // World units per pixel at the target's depth, so the target follows the cursor.
    const double scale = 2.0 * distance_ * std::tan(0.5 * fovY_) / std::max(viewportHeight, 1.0);
    const glm::dvec3 forward = -direction();
    const glm::dvec3 right = glm::normalize(glm::cross(forward, viewUp()));
    const glm::dvec3 viewUp = glm::cross(right, forward);
    target_ += (-right * double(pixels.x) + viewUp * double(pixels.y)) * scale;
}

void OrbitCamera::zoom(double steps) {
    distance_ *= zoomFactor(steps);
}

double OrbitCamera::zoomFactor(double steps) const {
    // Multiplying keeps the distance positive whatever the steps; the bounds keep it from
    // vanishing (double underflow) or running away.
    const double radius = usableRadius(bounds_);
    const double distance =
        std::clamp(distance_ * std::pow(zoomPerStep, steps), radius * 1e-5, radius * 1e4);
    return distance / distance_;
}

void OrbitCamera::zoomToward(glm::dvec3 point, double steps) {
    const double factor = zoomFactor(steps);
    target_ = point + (target_ - point) * factor;
    distance_ *= factor;
}

void OrbitCamera::fit(double aspect, FreeSpan span) {
    fit(bounds_, aspect, span);
}

void OrbitCamera::fit(const scene::Bounds& what, double aspect, FreeSpan span) {
    const double radius = usableRadius(what);
    const double width = std::clamp(double(span.right) - double(span.left), 1e-3, 1.0);
    aspect *= width; // the span's own aspect decides the distance
    shift_ =
        double(span.left) + double(span.right) - 1.0; // the span's middle, in device coordinates
    // The narrower of the two fields of view decides, as in scene::fitCamera; the
    // orthographic view of that distance is taller than the sphere (Camera::orthoHeight).
    const double halfFov =
        0.5 * std::min(fovY_, 2.0 * std::atan(std::tan(0.5 * fovY_) * std::max(aspect, 1e-3)));
    target_ = what.center();
    distance_ = radius / std::sin(halfFov);
}

glm::dmat4 OrbitCamera::shiftMatrix() const {
    // x' = x + shift * w: in clip space, so perspective and ortho both move by `shift`.
    glm::dmat4 m(1.0);
    m[3][0] = shift_;
    return m;
}

void OrbitCamera::turnTo(const scene::StandardView& view) {
    const glm::dmat3 frame = scene::modelFrame(up_);
    const glm::dvec3 d = glm::normalize(frame * view.toEye);
    const double along = glm::dot(d, up_);
    if (std::abs(along) > 0.9999) {
        // Top or bottom: on the pole, where the yaw only says which way the screen's up
        // points (viewUp): away from the horizontal direction at the top, towards it below.
        pitch_ = std::copysign(0.5 * glm::pi<double>(), along);
        const glm::dvec3 h = -std::copysign(1.0, along) * glm::normalize(frame * view.screenUp);
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

scene::Camera OrbitCamera::camera(double reach, bool ortho) const {
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
