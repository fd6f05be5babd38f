// test_support.h - what the Vulkan tests share: headless options with validation on, render
// settings for one registry entry, and gtest-safe parameter names.
#pragma once

#include <cctype>
#include <ostream>
#include <string>

#include "app/cli.h"
#include "app/offscreen.h"
#include "render/settings.h"

namespace testing_support {

// Headless, validation on, `frames` frames of width x height.
inline app::Options headlessOptions(uint32_t width, uint32_t height, uint32_t frames = 1) {
    app::Options o;
    o.headless = true;
    o.validation = true;
    o.width = width;
    o.height = height;
    o.frames = frames;
    return o;
}

// The default settings with this technique and mode.
inline render::RenderSettings settingsFor(const render::Technique& technique,
                                          const render::DrawMode& mode) {
    render::RenderSettings settings;
    settings.pipeline.technique = &technique;
    settings.pipeline.mode = &mode;
    return settings;
}

// The tests' flat camera: x and y straight to the image, depth 1 - z, so that with reversed
// depth (scene/camera.h) a smaller z is still nearer and z = 0 lies on the near plane.
inline glm::mat4 flatViewProj() {
    glm::mat4 viewProj(1.0f);
    viewProj[2][2] = -1.0f;
    viewProj[3][2] = 1.0f;
    return viewProj;
}

// One frame of `rig` through the flat camera (frame number `frame`, then counted on),
// waited for, and its ID image.
inline std::vector<uint32_t> renderIds(app::Offscreen& rig, uint64_t& frame) {
    render::FrameParams params;
    params.viewProj = flatViewProj();
    render::FrameSlot& slot = rig.slots.begin(frame++);
    rig.renderer.record(slot, rig.targets, params);
    const app::Readback readback(rig.device, rig.extent);
    readback.record(slot.cmd, *rig.targets);
    rig.slots.submit(slot);
    rig.slots.finish();
    return readback.idValues();
}

// Letters, digits and underscores only, as gtest wants parameter names.
inline std::string testName(std::string name) {
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

} // namespace testing_support

namespace render {
// gtest prints a technique parameter by its name (found by argument-dependent lookup).
inline void PrintTo(const Technique* technique, std::ostream* os) {
    *os << technique->name;
}
} // namespace render
