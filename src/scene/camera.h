// camera.h - a look-at camera, perspective or orthographic, with Vulkan conventions (depth
// 0..1, y down in framebuffer space), and the ray through a pixel that the CPU ray cast uses.
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
    // since nothing diverges at the eye.
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

// A camera looking at the whole of `bounds` from `direction` (target to eye), with near and
// far planes hugging the bounding sphere so depth precision follows the model's size. The
// distance fits the sphere in the narrower field of view; the orthographic view of that
// distance (orthoHeight) then holds the sphere too, with a little more room.
Camera fitCamera(const Bounds& bounds, glm::vec3 direction, glm::vec3 up, float fovY, float aspect);

// Near and far planes that hug the bounding sphere of `bounds` (5% margin, `reach` radii:
// an exploded view reaches 2) as seen from the camera's eye. In perspective, from inside the
// sphere the near plane stays in front of the target and at most a thousandth of the far
// plane, which keeps both the close-up part and the far end of a large plant; in ortho the
// planes always take in the whole sphere, behind the eye too.
void fitPlanes(Camera& camera, const Bounds& bounds, float reach = 1.0f);

struct Ray {
    glm::vec3 origin;
    glm::vec3 direction; // not normalised: origin + direction reaches the far plane
};

// The ray through framebuffer position `pixel` (pixel centres at +0.5) of a width x height
// image rendered with `viewProj`: from the near plane under the pixel to the far plane under
// it, so rays converge at the eye in perspective and run parallel in ortho.
Ray pixelRay(const glm::mat4& viewProj, glm::vec2 size, glm::vec2 pixel);

// The world point at framebuffer depth `depth` (0 near, 1 far) under framebuffer position
// `pixel` of that image: what a pick's depth says of where the surface is (either projection).
glm::vec3 unprojectPixel(const glm::mat4& viewProj, glm::vec2 size, glm::vec2 pixel, float depth);

} // namespace scene
