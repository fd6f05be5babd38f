// camera.cpp - view and projection matrices (perspective and orthographic, reversed depth),
// view fitting and pixel rays.
#include "scene/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

namespace scene {

glm::mat4 Camera::view() const {
    return glm::lookAt(eye, target, up);
}

float Camera::orthoHeight() const {
    return 2.0f * glm::length(target - eye) * std::tan(0.5f * fovY);
}

glm::mat4 reversedInfinitePerspective(float fovY, float aspect, float nearPlane) {
    // Clip z is the constant nearPlane and clip w the view distance (-z in view space, which
    // looks down -z), so depth = nearPlane / distance: 1 at the near plane, 0 at infinity.
    const float focal = 1.0f / std::tan(0.5f * fovY);
    glm::mat4 proj(0.0f);
    proj[0][0] = focal / aspect;
    proj[1][1] = -focal; // Vulkan's framebuffer y points down
    proj[2][3] = -1.0f;
    proj[3][2] = nearPlane;
    return proj;
}

glm::mat4 reversedOrthographic(float halfWidth, float halfHeight, float nearPlane, float farPlane) {
    // depth = (farPlane + z) / (farPlane - nearPlane): 1 at z = -nearPlane, 0 at -farPlane.
    glm::mat4 proj(1.0f);
    proj[0][0] = 1.0f / halfWidth;
    proj[1][1] = -1.0f / halfHeight; // Vulkan's framebuffer y points down
    proj[2][2] = 1.0f / (farPlane - nearPlane);
    proj[3][2] = farPlane / (farPlane - nearPlane);
    return proj;
}

glm::mat4 Camera::projection(float aspect) const {
    if (!ortho) return reversedInfinitePerspective(fovY, aspect, nearPlane);
    const float halfHeight = 0.5f * orthoHeight();
    return reversedOrthographic(halfHeight * aspect, halfHeight, nearPlane, farPlane);
}

Camera fitCamera(const Bounds& bounds, glm::vec3 direction, glm::vec3 up, float fovY,
                 float aspect) {
    const float radius = std::max(bounds.radius(), 1e-3f);
    const float halfFov = 0.5f * std::min(fovY, 2.0f * std::atan(std::tan(0.5f * fovY) * aspect));
    const float distance = radius / std::sin(halfFov);
    Camera camera;
    camera.target = bounds.center();
    camera.eye = camera.target + glm::normalize(direction) * distance;
    camera.up = up;
    camera.fovY = fovY;
    fitPlanes(camera, bounds);
    return camera;
}

// The nearest view depth (distance along `forward` from `eye`) of any point of the box.
static float nearestViewDepth(glm::vec3 eye, glm::vec3 forward, const Bounds& box) {
    // A linear function is least over a box at the corner its gradient points away from.
    const glm::vec3 corner =
        glm::mix(box.max, box.min, glm::vec3(glm::greaterThan(forward, glm::vec3(0.0f))));
    return glm::dot(corner - eye, forward);
}

void fitPlanes(Camera& camera, const Bounds& bounds, float reach) {
    // The near plane's least distance, as a fraction of the sphere's radius: for an eye among
    // the parts. Reversed float depth keeps its relative precision down to it.
    constexpr float nearFloor = 1e-5f;
    // Rounding room between the scene's nearest point and the near plane.
    constexpr float nearMargin = 1.0f / 256.0f;
    float radius = bounds.radius();
    if (!std::isfinite(radius) || !(radius > 0.0f)) radius = 1.0f; // a point, or nothing
    radius *= 1.05f * std::max(reach, 1.0f);
    const float centre = glm::length(camera.eye - bounds.center());
    camera.farPlane = centre + radius;
    if (camera.ortho) {
        // Depth is linear and no ray starts at the eye: the slab through the whole sphere.
        camera.nearPlane = centre - radius;
        return;
    }
    const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    // The sphere holds the scene exploded too; at rest the box holds it more tightly.
    float nearest = glm::dot(bounds.center() - camera.eye, forward) - radius;
    if (reach <= 1.0f && bounds.min.x <= bounds.max.x) // not an empty box
        nearest = std::max(nearest, nearestViewDepth(camera.eye, forward, bounds));
    // The floor stays in front of the target too, so what the user zooms to is not cut.
    const float floor =
        std::min(radius * nearFloor, 0.5f * glm::length(camera.target - camera.eye));
    camera.nearPlane = std::max(nearest * (1.0f - nearMargin), floor);
}

// Whether `viewProj` projects in perspective: its w row depends on the position then, while
// an orthographic one's w row is exactly (0, 0, 0, 1).
static bool isPerspective(const glm::mat4& viewProj) {
    return viewProj[0][3] != 0.0f || viewProj[1][3] != 0.0f || viewProj[2][3] != 0.0f;
}

// The world point under normalised device position `ndc` at framebuffer depth `depth`.
static glm::vec3 unproject(const glm::mat4& inverse, glm::vec2 ndc, float depth) {
    const glm::vec4 p = inverse * glm::vec4(ndc, depth, 1.0f);
    return glm::vec3(p) / p.w;
}

Ray pixelRay(const glm::mat4& viewProj, glm::vec2 size, glm::vec2 pixel) {
    const glm::mat4 inverse = glm::inverse(viewProj);
    const glm::vec2 ndc = pixel / size * 2.0f - 1.0f;
    const glm::vec3 origin = unproject(inverse, ndc, 1.0f);
    if (!isPerspective(viewProj)) return {origin, unproject(inverse, ndc, 0.0f) - origin, 1.0f};
    // Depth 0 lies at infinity: the point at depth 1/2, twice as far from the eye, gives the
    // direction, and the ray goes on.
    return {origin, unproject(inverse, ndc, 0.5f) - origin, std::numeric_limits<float>::infinity()};
}

float rayParameterAtDepth(const glm::mat4& viewProj, float depth) {
    // Perspective: the distance from the eye is the near plane's over depth, and the ray
    // starts at the near plane (t = 0) and passes twice its distance at t = 1.
    if (isPerspective(viewProj)) return 1.0f / depth - 1.0f;
    return 1.0f - depth;
}

glm::vec3 unprojectPixel(const glm::mat4& viewProj, glm::vec2 size, glm::vec2 pixel, float depth) {
    const Ray ray = pixelRay(viewProj, size, pixel);
    return ray.origin + rayParameterAtDepth(viewProj, depth) * ray.direction;
}

} // namespace scene
