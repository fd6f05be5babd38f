// camera_frame.cpp - a camera's frame parameters and the exploded view's place in time.
#include "app/camera_frame.h"

#include "scene/explode.h"

namespace app {

render::FrameParams cameraFrame(const scene::Camera& camera, VkExtent2D extent) {
    render::FrameParams params;
    const double aspect = double(extent.width) / double(extent.height);
    // The GPU works relative to the eye: the view from there has no translation, so the
    // float matrix it gets is as exact wherever the model sits (docs/models.md).
    params.origin = camera.eye;
    params.worldViewProj = camera.viewProjection(aspect);
    params.viewProj = glm::mat4(camera.projection(aspect) * camera.viewFromEye());
    params.eye = glm::vec3(0.0f);
    if (camera.ortho) params.orthoToViewer = glm::normalize(camera.eye - camera.target);
    return params;
}

float explodeAt(const Animation& animation, uint64_t frame) {
    return animation.animate ? scene::explodeLoop(animation.time.value_or(float(frame) / 60))
                             : animation.explode;
}

} // namespace app
