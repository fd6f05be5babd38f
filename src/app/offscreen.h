// offscreen.h - everything one offscreen rendering needs on a device: the device, shader
// compiler, scene pass (with the options' MSAA), targets, frames in flight and the renderer.
// Members are built in order and destroyed in reverse; the Instance outlives it, so the
// validation count read after destruction includes teardown.
#pragma once

#include "app/cli.h"
#include "render/frame_slots.h"
#include "render/renderer.h"
#include "render/targets.h"
#include "vk/context.h"
#include "vk/shader_compiler.h"

namespace app {

struct Offscreen {
    Offscreen(vk::Instance& instance, const Options& options)
        : device(instance, vk::chooseDevice(instance.devices(), options.device)),
          compiler(vk::ShaderCompiler::locate(options.shaderDir)),
          pass(device, render::checkedSampleCount(device, options.msaa)), extent{options.width,
                                                                                 options.height},
          targets(device, pass, extent), slots(device), renderer(device, compiler, pass) {}

    vk::Device device;
    vk::ShaderCompiler compiler;
    render::ScenePass pass;
    VkExtent2D extent;
    render::SceneTargets targets;
    render::FrameSlots slots;
    render::Renderer renderer;
};

} // namespace app
