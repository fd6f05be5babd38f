// camera_frame.h - the frame a camera and the animation give, as headless runs, the benchmark
// and the viewer draw it.
#pragma once

#include <cstdint>

#include <vulkan/vulkan.h>

#include "app/live_settings.h"
#include "render/renderer.h"
#include "scene/camera.h"

namespace app {

// The frame of `camera` for `extent`, as headless, the benchmark and the viewer draw it.
render::FrameParams cameraFrame(const scene::Camera& camera, VkExtent2D extent);
// --animate: the exploded view at --time, else at frame / 60 s; otherwise it stays put.
float explodeAt(const Animation& animation, uint64_t frame);

} // namespace app
