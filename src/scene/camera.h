// camera.h - a look-at camera, perspective or orthographic, with Vulkan conventions (depth
// 0..1, y down in framebuffer space), and the ray through a pixel that the CPU ray cast uses.
// Everything here is double, in world coordinates: a model placed kilometres from the origin
// keeps its millimetres. What the GPU gets is relative to the eye (render::eyeRelative).
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
    // since nothing diverges at the eye.
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

// A camera looking at the whole of `bounds` from `direction` (target to eye), with near and
// far planes hugging the bounding sphere so depth precision follows the model's size. The
// distance fits the sphere in the narrower field of view; the orthographic view of that
// distance (orthoHeight) then holds the sphere too, with a little more room.
Camera fitCamera(const Bounds& bounds, glm::dvec3 direction, glm::dvec3 up, float fovY,
                 double aspect);

// Near and far planes that hug the bounding sphere of `bounds` (5% margin, `reach` radii:
// an exploded view reaches 2) as seen from the camera's eye. In perspective, from inside the
// sphere the near plane stays in front of the target and at most a thousandth of the far
// plane, which keeps both the close-up part and the far end of a large plant; in ortho the
// planes always take in the whole sphere, behind the eye too.
void fitPlanes(Camera& camera, const Bounds& bounds, double reach = 1.0);

struct Ray {
    glm::dvec3 origin;
    glm::dvec3 direction; // not normalised: origin + direction reaches the far plane
};

// The ray through framebuffer position `pixel` (pixel centres at +0.5) of a width x height
// image rendered with `viewProj`: from the near plane under the pixel to the far plane under
// it, so rays converge at the eye in perspective and run parallel in ortho.
Ray pixelRay(const glm::dmat4& viewProj, glm::dvec2 size, glm::dvec2 pixel);

// The world point at framebuffer depth `depth` (0 near, 1 far) under framebuffer position
// `pixel` of that image: what a pick's depth says of where the surface is (either projection).
glm::dvec3 unprojectPixel(const glm::dmat4& viewProj, glm::dvec2 size, glm::dvec2 pixel,
                          double depth);

} // namespace scene
