// camera.cpp - view and projection matrices (perspective and orthographic), view fitting and
// pixel rays.
#include "scene/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace scene {

glm::dmat4 Camera::view() const {
    return glm::lookAt(eye, target, up);
}

glm::dmat4 Camera::viewFromEye() const {
    return glm::lookAt(glm::dvec3(0.0), target - eye, up);
}

double Camera::orthoHeight() const {
    return 2.0 * glm::length(target - eye) * std::tan(0.5 * double(fovY));
}

glm::dmat4 Camera::projection(double aspect) const {
    glm::dmat4 proj;
    if (ortho) {
        const double halfHeight = 0.5 * orthoHeight();
        const double halfWidth = halfHeight * aspect;
        proj = glm::ortho(-halfWidth, halfWidth, -halfHeight, halfHeight, nearPlane, farPlane);
    } else {
        proj = glm::perspective(double(fovY), aspect, nearPlane, farPlane);
    }
    proj[1][1] *= -1.0; // Vulkan's framebuffer y points down
    return proj;
}

Camera fitCamera(const Bounds& bounds, glm::dvec3 direction, glm::dvec3 up, float fovY,
                 double aspect) {
    const double radius = std::max(bounds.radius(), 1e-3);
    const double fov = fovY;
    const double halfFov = 0.5 * std::min(fov, 2.0 * std::atan(std::tan(0.5 * fov) * aspect));
    const double distance = radius / std::sin(halfFov);
    Camera camera;
    camera.target = bounds.center();
    camera.eye = camera.target + glm::normalize(direction) * distance;
    camera.up = up;
    camera.fovY = fovY;
    camera.nearPlane = std::max(distance - radius * 1.05, distance * 1e-3);
    camera.farPlane = distance + radius * 1.05;
    return camera;
}

void fitPlanes(Camera& camera, const Bounds& bounds, double reach) {
    double radius = bounds.radius();
    if (!std::isfinite(radius) || !(radius > 0.0)) radius = 1.0; // a point, or nothing
    radius *= 1.05 * std::max(reach, 1.0);
    const double centre = glm::length(camera.eye - bounds.center());
    camera.farPlane = centre + radius;
    if (camera.ortho) {
        // Depth is linear and no ray starts at the eye: the slab through the whole sphere.
        camera.nearPlane = centre - radius;
        return;
    }
    const double floor =
        std::min(0.5 * glm::length(camera.target - camera.eye), camera.farPlane * 1e-3);
    camera.nearPlane = std::max(centre - radius, floor);
}

glm::dvec3 unprojectPixel(const glm::dmat4& viewProj, glm::dvec2 size, glm::dvec2 pixel,
                          double depth) {
    const glm::dvec4 p = glm::inverse(viewProj) * glm::dvec4(pixel / size * 2.0 - 1.0, depth, 1.0);
    return glm::dvec3(p) / p.w;
}

Ray pixelRay(const glm::dmat4& viewProj, glm::dvec2 size, glm::dvec2 pixel) {
    const glm::dmat4 inverse = glm::inverse(viewProj);
    const glm::dvec2 ndc = pixel / size * 2.0 - 1.0;
    const glm::dvec4 nearPoint = inverse * glm::dvec4(ndc, 0.0, 1.0);
    const glm::dvec4 farPoint = inverse * glm::dvec4(ndc, 1.0, 1.0);
    const glm::dvec3 origin = glm::dvec3(nearPoint) / nearPoint.w;
    return {origin, glm::dvec3(farPoint) / farPoint.w - origin};
}

} // namespace scene
