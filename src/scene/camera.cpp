// camera.cpp - view and projection matrices (perspective and orthographic), view fitting and
// pixel rays.
#include "scene/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace scene {

glm::mat4 Camera::view() const {
    return glm::lookAt(eye, target, up);
}

float Camera::orthoHeight() const {
    return 2.0f * glm::length(target - eye) * std::tan(0.5f * fovY);
}

glm::mat4 Camera::projection(float aspect) const {
    glm::mat4 proj;
    if (ortho) {
        const float halfHeight = 0.5f * orthoHeight();
        const float halfWidth = halfHeight * aspect;
        proj = glm::ortho(-halfWidth, halfWidth, -halfHeight, halfHeight, nearPlane, farPlane);
    } else {
        proj = glm::perspective(fovY, aspect, nearPlane, farPlane);
    }
    proj[1][1] *= -1.0f; // Vulkan's framebuffer y points down
    return proj;
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
    camera.nearPlane = std::max(distance - radius * 1.05f, distance * 1e-3f);
    camera.farPlane = distance + radius * 1.05f;
    return camera;
}

void fitPlanes(Camera& camera, const Bounds& bounds, float reach) {
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
    const float floor =
        std::min(0.5f * glm::length(camera.target - camera.eye), camera.farPlane * 1e-3f);
    camera.nearPlane = std::max(centre - radius, floor);
}

glm::vec3 unprojectPixel(const glm::mat4& viewProj, glm::vec2 size, glm::vec2 pixel, float depth) {
    const glm::vec4 p = glm::inverse(viewProj) * glm::vec4(pixel / size * 2.0f - 1.0f, depth, 1.0f);
    return glm::vec3(p) / p.w;
}

Ray pixelRay(const glm::mat4& viewProj, glm::vec2 size, glm::vec2 pixel) {
    const glm::mat4 inverse = glm::inverse(viewProj);
    const glm::vec2 ndc = pixel / size * 2.0f - 1.0f;
    glm::vec4 nearPoint = inverse * glm::vec4(ndc, 0.0f, 1.0f);
    glm::vec4 farPoint = inverse * glm::vec4(ndc, 1.0f, 1.0f);
    glm::vec3 origin = glm::vec3(nearPoint) / nearPoint.w;
    return {origin, glm::vec3(farPoint) / farPoint.w - origin};
}

} // namespace scene
