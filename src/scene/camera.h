// camera.h - a look-at camera, perspective or orthographic, with Vulkan conventions (y down
// in framebuffer space) and reversed depth: 1 at the near plane, 0 at the far plane (at
// infinity in perspective); and the ray through a pixel that the CPU ray cast uses.
// Everything here is double, in world coordinates: a model placed kilometres from the origin
// keeps its millimetres. What the GPU gets is relative to the eye (app::cameraFrame).
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace scene {

struct Camera {
    glm::dvec3 eye{0, -10, 5};
    glm::dvec3 target{0, 0, 0};
    glm::dvec3 up{0, 0, 1};
    float fovY = glm::radians(45.0f);
    // Orthographic: a parallel projection whose view is orthoHeight() tall. The near plane
    // may then lie behind the eye (fitPlanes puts it there when the eye is among the parts),
    // since nothing diverges at the eye. Perspective has its far plane at infinity: farPlane
    // only bounds the orthographic slab (fitPlanes still sets it in both).
    bool ortho = false;
    double nearPlane = 0.1;
    double farPlane = 100.0;

    // The height the orthographic view spans: that of the perspective view at the target's
    // distance, so switching projections keeps the target's apparent size, and zooming (the
    // eye nearer the target) magnifies in both.
    double orthoHeight() const;
    glm::dmat4 view() const;
    // The view with the eye at the origin: for coordinates relative to the eye, the matrix
    // the GPU gets (render::FrameParams) holds no large translation to round.
    glm::dmat4 viewFromEye() const;
    glm::dmat4 projection(double aspect) const;
    glm::dmat4 viewProjection(double aspect) const { return projection(aspect) * view(); }
};

// A camera looking at the whole of `bounds` from `direction` (target to eye), with its near
// plane at the front of the scene (fitPlanes). The distance fits the bounding sphere in the
// narrower field of view; the orthographic view of that distance (orthoHeight) then holds the
// sphere too, with a little more room.
Camera fitCamera(const Bounds& bounds, glm::dvec3 direction, glm::dvec3 up, float fovY,
                 double aspect);

// Near and far planes for the scene in `bounds` (its box, and its bounding sphere with a 5%
// margin and `reach` radii: an exploded view reaches 2) as seen from the camera's eye. In
// perspective the near plane lies at the nearest view depth of the scene (of the box, or of
// the sphere when exploded), so nothing of it is cut; where the scene reaches beside or
// behind the eye, at a floor relative to the scene's size (at most half the distance to the
// target, which stays in view however close the user zooms). Reversed float depth keeps about
// the same relative precision at every distance, so a near plane close to the eye costs
// little. In ortho the planes take in the whole sphere, behind the eye too.
void fitPlanes(Camera& camera, const Bounds& bounds, double reach = 1.0);

// The projections written out: reversed depth, Vulkan's 0..1 depth range and y down.
// Perspective: depth = nearPlane / view distance, 1 at the near plane, 0 at infinity.
glm::dmat4 reversedInfinitePerspective(double fovY, double aspect, double nearPlane);
// Orthographic: depth linear, 1 at the near plane, 0 at the far plane.
glm::dmat4 reversedOrthographic(double halfWidth, double halfHeight, double nearPlane,
                                double farPlane);

struct Ray {
    glm::dvec3 origin;
    // Not normalised: in ortho origin + direction reaches the far plane; in perspective
    // (whose far plane is at infinity) origin + direction lies twice as far from the eye as
    // the origin, and the ray goes on without end.
    glm::dvec3 direction;
    double end = 1.0; // the ray's last t: 1 (ortho's far plane) or infinity (perspective)
};

// The ray through framebuffer position `pixel` (pixel centres at +0.5) of a width x height
// image rendered with `viewProj`: from the near plane under the pixel on to the far plane
// under it, so rays converge at the eye in perspective and run parallel in ortho.
Ray pixelRay(const glm::dmat4& viewProj, glm::dvec2 size, glm::dvec2 pixel);

// The ray parameter t at which pixelRay's ray reaches framebuffer depth `depth` (reversed:
// 1 near, 0 far), for a perspective or an orthographic `viewProj`.
double rayParameterAtDepth(const glm::dmat4& viewProj, double depth);

// The world point at framebuffer depth `depth` (1 near, 0 far) under framebuffer position
// `pixel` of that image: what a pick's depth says of where the surface is (either projection).
// Along pixelRay, not through the inverse at that depth: in perspective the depth of a far
// surface is small, and the inverse's rounding would swamp it.
glm::dvec3 unprojectPixel(const glm::dmat4& viewProj, glm::dvec2 size, glm::dvec2 pixel,
                          double depth);

} // namespace scene
