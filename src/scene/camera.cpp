// camera.cpp - view and projection matrices (perspective and orthographic, reversed depth),
// view fitting and pixel rays, all in double.
#include "scene/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

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

glm::dmat4 reversedInfinitePerspective(double fovY, double aspect, double nearPlane) {
    // Clip z is the constant nearPlane and clip w the view distance (-z in view space, which
    // looks down -z), so depth = nearPlane / distance: 1 at the near plane, 0 at infinity.
    const double focal = 1.0 / std::tan(0.5 * fovY);
    glm::dmat4 proj(0.0);
    proj[0][0] = focal / aspect;
    proj[1][1] = -focal; // Vulkan's framebuffer y points down
    proj[2][3] = -1.0;
    proj[3][2] = nearPlane;
    return proj;
}

glm::dmat4 reversedOrthographic(double halfWidth, double halfHeight, double nearPlane,
                                double farPlane) {
    // depth = (farPlane + z) / (farPlane - nearPlane): 1 at z = -nearPlane, 0 at -farPlane.
    glm::dmat4 proj(1.0);
    proj[0][0] = 1.0 / halfWidth;
    proj[1][1] = -1.0 / halfHeight; // Vulkan's framebuffer y points down
    proj[2][2] = 1.0 / (farPlane - nearPlane);
    proj[3][2] = farPlane / (farPlane - nearPlane);
    return proj;
}

glm::dmat4 Camera::projection(double aspect) const {
    if (!ortho) return reversedInfinitePerspective(fovY, aspect, nearPlane);
    const double halfHeight = 0.5 * orthoHeight();
    return reversedOrthographic(halfHeight * aspect, halfHeight, nearPlane, farPlane);
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
    fitPlanes(camera, bounds);
    return camera;
}

// The nearest view depth (distance along `forward` from `eye`) of any point of the box.
static double nearestViewDepth(glm::dvec3 eye, glm::dvec3 forward, const Bounds& box) {
    // A linear function is least over a box at the corner its gradient points away from.
    const glm::dvec3 corner =
        glm::mix(box.max, box.min, glm::dvec3(glm::greaterThan(forward, glm::dvec3(0.0))));
    return glm::dot(corner - eye, forward);
}

void fitPlanes(Camera& camera, const Bounds& bounds, double reach) {
    // The near plane's least distance, as a fraction of the sphere's radius: for an eye among
    // the parts. Reversed float depth keeps its relative precision down to it.
    constexpr double nearFloor = 1e-5;
    // Rounding room between the scene's nearest point and the near plane.
    constexpr double nearMargin = 1.0 / 256.0;
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
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    // The sphere holds the scene exploded too; at rest the box holds it more tightly.
    double nearest = glm::dot(bounds.center() - camera.eye, forward) - radius;
    if (reach <= 1.0 && bounds.min.x <= bounds.max.x) // not an empty box
        nearest = std::max(nearest, nearestViewDepth(camera.eye, forward, bounds));
    // The floor stays in front of the target too, so what the user zooms to is not cut.
    const double floor =
        std::min(radius * nearFloor, 0.5 * glm::length(camera.target - camera.eye));
    camera.nearPlane = std::max(nearest * (1.0 - nearMargin), floor);
}

// Whether `viewProj` projects in perspective: its w row depends on the position then, while
// an orthographic one's w row is exactly (0, 0, 0, 1).
static bool isPerspective(const glm::dmat4& viewProj) {
    return viewProj[0][3] != 0.0 || viewProj[1][3] != 0.0 || viewProj[2][3] != 0.0;
}

// The world point under normalised device position `ndc` at framebuffer depth `depth`.
static glm::dvec3 unproject(const glm::dmat4& inverse, glm::dvec2 ndc, double depth) {
    const glm::dvec4 p = inverse * glm::dvec4(ndc, depth, 1.0);
    return glm::dvec3(p) / p.w;
}

Ray pixelRay(const glm::dmat4& viewProj, glm::dvec2 size, glm::dvec2 pixel) {
    const glm::dmat4 inverse = glm::inverse(viewProj);
    const glm::dvec2 ndc = pixel / size * 2.0 - 1.0;
    const glm::dvec3 origin = unproject(inverse, ndc, 1.0);
    if (!isPerspective(viewProj)) return {origin, unproject(inverse, ndc, 0.0) - origin, 1.0};
    // Depth 0 lies at infinity: the point at depth 1/2, twice as far from the eye, gives the
    // direction, and the ray goes on.
    return {origin, unproject(inverse, ndc, 0.5) - origin, std::numeric_limits<double>::infinity()};
}

double rayParameterAtDepth(const glm::dmat4& viewProj, double depth) {
    // Perspective: the distance from the eye is the near plane's over depth, and the ray
    // starts at the near plane (t = 0) and passes twice its distance at t = 1.
    if (isPerspective(viewProj)) return 1.0 / depth - 1.0;
    return 1.0 - depth;
}

glm::dvec3 unprojectPixel(const glm::dmat4& viewProj, glm::dvec2 size, glm::dvec2 pixel,
                          double depth) {
    const Ray ray = pixelRay(viewProj, size, pixel);
    return ray.origin + rayParameterAtDepth(viewProj, depth) * ray.direction;
}

} // namespace scene
