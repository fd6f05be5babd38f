// test_support.h - what the Vulkan tests share: headless options with validation on, render
// settings for one registry entry, and gtest-safe parameter names.
#pragma once

#include <cctype>
#include <ostream>
#include <string>
#include <vector>

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

// Background pixels no 4-connected path of background pixels joins to the image's border:
// where a closed model shows them, the background shows through a hole between its faces.
inline std::vector<size_t> enclosedBackground(const std::vector<uint32_t>& ids, uint32_t w,
                                              uint32_t h) {
    std::vector<uint8_t> outside(ids.size(), 0);
    std::vector<size_t> stack;
    auto visit = [&](uint32_t x, uint32_t y) {
        const size_t i = size_t(y) * w + x;
        if (ids[i] == gpu::BACKGROUND_ID && !outside[i]) {
            outside[i] = 1;
            stack.push_back(i);
        }
    };
    for (uint32_t x = 0; x < w; ++x) visit(x, 0), visit(x, h - 1);
    for (uint32_t y = 0; y < h; ++y) visit(0, y), visit(w - 1, y);
    while (!stack.empty()) {
        const size_t i = stack.back();
        stack.pop_back();
        const uint32_t x = uint32_t(i % w), y = uint32_t(i / w);
        if (x > 0) visit(x - 1, y);
        if (x + 1 < w) visit(x + 1, y);
        if (y > 0) visit(x, y - 1);
        if (y + 1 < h) visit(x, y + 1);
    }
    std::vector<size_t> enclosed;
    for (size_t i = 0; i < ids.size(); ++i)
        if (ids[i] == gpu::BACKGROUND_ID && !outside[i]) enclosed.push_back(i);
    return enclosed;
}

} // namespace testing_support

namespace render {
// gtest prints a technique parameter by its name (found by argument-dependent lookup).
inline void PrintTo(const Technique* technique, std::ostream* os) {
    *os << technique->name;
}
} // namespace render
