// viewer_ui.h - the viewer's ImGui panel. It reads a snapshot of the viewer's state and
// returns the settings the user asked for; the viewer applies the difference through the
// same functions that keys and scripts use, so the panel holds no state of its own.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "render/draw_list.h"
#include "scene/part_data.h"
#include "scene/scene.h"

namespace app {

// Everything the user can change at run time.
struct ViewerSettings {
    int technique = 0; // index into render::techniques()
    int mode = 0;      // index into render::drawModes()
    uint32_t searchBatch = 16;
    render::NarySearch nsearch{}; // the nsearch techniques' parameters
    float visible = 1.0f;         // fraction of the objects drawn, in scene order
    float partWeight = 0.5f;
    bool colorizeDraws = false;
    bool ignoreMaterials = false;
    uint32_t copies = 1;
    uint32_t copyAxes = 3;       // scene::CopyAxis bits the copies' grid spans (x and y)
    bool componentParts = false; // glTF parts mode: connected components, not primitives
    uint32_t msaa = 1;
    bool animate = false;
    bool vsync = true;
    bool operator==(const ViewerSettings&) const = default;
};

// A part under the cursor or selected, as the pick reported it.
struct PartLine {
    std::optional<scene::PartInfo> part;
    float depth = 1.0f;
};

struct PanelInfo {
    std::string device;
    std::string source; // model file or scene spec
    bool gltf = false;  // the parts mode applies
    std::string error;  // the last failed action's message, shown until the next success
    const scene::Scene* scene = nullptr;
    render::RenderStats stats;
    scene::IdDataBytes idBytes;
    VkSampleCountFlags sampleCounts = VK_SAMPLE_COUNT_1_BIT; // offered by the device
    double fps = 0.0, gpuMs = 0.0, cpuRecordMs = 0.0;
    std::vector<float> gpuHistory; // the last ~200 scene pass times, oldest first
    PartLine hovered, selected;
};

// Draws the panel and returns `current` with the user's changes.
ViewerSettings drawPanel(const ViewerSettings& current, const PanelInfo& info);

} // namespace app
