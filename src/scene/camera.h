// camera.h - a look-at camera, perspective or orthographic, with Vulkan conventions (y down
// in framebuffer space) and reversed depth: 1 at the near plane, 0 at the far plane (at
// infinity in perspective); and the ray through a pixel that the CPU ray cast uses.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace scene {

struct Camera {
    glm::vec3 eye{0, -10, 5};
    glm::vec3 target{0, 0, 0};
    glm::vec3 up{0, 0, 1};
    float fovY = glm::radians(45.0f);
    // Orthographic: a parallel projection whose view is orthoHeight() tall. The near plane
    // may then lie behind the eye (fitPlanes puts it there when the eye is among the parts),
    // since nothing diverges at the eye. Perspective has its far plane at infinity: farPlane
    // only bounds the orthographic slab (fitPlanes still sets it in both).
    bool ortho = false;
    float nearPlane = 0.1f;
    float farPlane = 100.0f;

    // The height the orthographic view spans: that of the perspective view at the target's
    // distance, so switching projections keeps the target's apparent size, and zooming (the
    // eye nearer the target) magnifies in both.
    float orthoHeight() const;
    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;
    glm::mat4 viewProjection(float aspect) const { return projection(aspect) * view(); }
};

// A camera looking at the whole of `bounds` from `direction` (target to eye), with its near
// plane at the front of the bounding sphere and its far plane behind it. The
// distance fits the sphere in the narrower field of view; the orthographic view of that
// distance (orthoHeight) then holds the sphere too, with a little more room.
Camera fitCamera(const Bounds& bounds, glm::vec3 direction, glm::vec3 up, float fovY, float aspect);

// Near and far planes for the scene in `bounds` (its box, and its bounding sphere with a 5%
// margin and `reach` radii: an exploded view reaches 2) as seen from the camera's eye. In
// perspective the near plane lies at the nearest view depth of the scene (of the box, or of
// the sphere when exploded), so nothing of it is cut; where the scene reaches beside or
// behind the eye, at a floor relative to the scene's size (at most half the distance to the
// target, which stays in view however close the user zooms). Reversed float depth keeps about
// the same relative precision at every distance, so a near plane close to the eye costs
// little. In ortho the planes take in the whole sphere, behind the eye too.
void fitPlanes(Camera& camera, const Bounds& bounds, float reach = 1.0f);

// The projections written out: reversed depth, Vulkan's 0..1 depth range and y down.
// Perspective: depth = nearPlane / view distance, 1 at the near plane, 0 at infinity.
glm::mat4 reversedInfinitePerspective(float fovY, float aspect, float nearPlane);
// Orthographic: depth linear, 1 at the near plane, 0 at the far plane.
glm::mat4 reversedOrthographic(float halfWidth, float halfHeight, float nearPlane, float farPlane);

struct Ray {
    glm::vec3 origin;
    // Not normalised: in ortho origin + direction reaches the far plane; in perspective
    // (whose far plane is at infinity) origin + direction lies twice as far from the eye as
    // the origin, and the ray goes on without end.
    glm::vec3 direction;
    float end = 1.0f; // the ray's last t: 1 (ortho's far plane) or infinity (perspective)
};

// The ray through framebuffer position `pixel` (pixel centres at +0.5) of a width x height
// image rendered with `viewProj`: from the near plane under the pixel on to the far plane
// under it, so rays converge at the eye in perspective and run parallel in ortho.
Ray pixelRay(const glm::mat4& viewProj, glm::vec2 size, glm::vec2 pixel);

// The ray parameter t at which pixelRay's ray reaches framebuffer depth `depth` (reversed:
// 1 near, 0 far), for a perspective or an orthographic `viewProj`.
float rayParameterAtDepth(const glm::mat4& viewProj, float depth);

// The world point at framebuffer depth `depth` (1 near, 0 far) under framebuffer position
// `pixel` of that image: what a pick's depth says of where the surface is (either projection).
// Along pixelRay, not through the inverse at that depth: in perspective the depth of a far
// surface is small, and the inverse's rounding would swamp it.
glm::vec3 unprojectPixel(const glm::mat4& viewProj, glm::vec2 size, glm::vec2 pixel, float depth);

} // namespace scene
