// panel.h - the viewer's ImGui panel. It edits the viewer's settings structs in place (the
// same ones the command line filled) and reads a snapshot of the viewer's state; the viewer
// then applies whatever differs from what is drawn. The panel holds no state of its own.
#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "app/live_settings.h"
#include "app/viewer/commands/command.h"
#include "app/viewer/panel/panel_layout.h"
#include "app/viewer/state/census_state.h"
#include "app/viewer/state/events.h"
#include "app/viewer/state/selection.h"
#include "app/viewer/state/view_settings.h"
#include "render/draw_list.h"
#include "render/renderer.h"
#include "scene/assembly_tree.h"
#include "scene/face_info.h"
#include "scene/part_data.h"
#include "scene/scene.h"
#include "scene/standard_view.h"
#include "scene/surface_info.h"

namespace app {

struct InspectReport; // inspect_report.h

// The panel's distance from the window's top left corner, where it opens.
constexpr float panelMargin = 8.0f;

// The panel's narrowest width (every label fits, panel_widgets.h) and widest share of the
// window.
inline constexpr float minPanelWidth = 320.0f, maxPanelShare = 0.6f;
// The tree pane's height, in rows.
inline constexpr float minTreeRows = 3.0f, maxTreeRows = 40.0f;

// What the user asked for through the panel's buttons and widgets: the commands a key or a
// script line would give (commands.h), for the viewer to run once the panel is drawn.
struct PanelActions {
    std::vector<Command> commands;
    // The section planes as the panel's widgets left them.
    std::optional<scene::Section> section;
    // A widget is held (a slider being dragged): its change is one undo step once let go.
    bool held = false;
    void ask(Command command) { commands.push_back(std::move(command)); }
};

// A part under the cursor or selected, as the pick reported it.
struct PartLine {
    std::optional<scene::PartInfo> part;
    float depth = 1.0f;
    std::optional<scene::FaceReport> face; // CAD parts: the B-rep face (part_details.h)
    std::string edge; // the B-rep edge near the cursor or selected (edge_hover.h), or ""
};

struct PanelInfo {
    std::string device;
    bool cpuDevice = false;         // VK_PHYSICAL_DEVICE_TYPE_CPU (lavapipe): times are CPU's
    const Events* events = nullptr; // for the panel's own event lines (panel_layout.h)
    // Per entry of render::techniques(): why the device cannot run it, or "".
    std::vector<std::string> unavailable;
    std::string source; // model file or scene spec
    bool gltf = false;  // the parts mode applies
    std::string error;  // the last failed action's message, shown until the next success
    struct Loading {
        std::string path;
        double seconds = 0.0;
        std::string stage; // "" when the loader reports no stages
        double fraction = 0.0;
        std::string shown;        // a model shown as it loads: "3 of 8 solids shown, ..."
        bool modelBefore = false; // Cancel goes back to a model
        bool stopping = false;    // Stop or Cancel asked, the load not ended yet
    };
    std::optional<Loading> loading; // a model still loading
    // A model stopped while it loaded: what it lacks ("5 of 8 solids missing"), else "".
    std::string incomplete;
    // A model shown as it loads (and after Stop): each object's scene::kObjectWaiting,
    // kObjectReady or kObjectLost, for the tree's rows; nullptr once whole.
    const std::vector<uint8_t>* objectStates = nullptr;
    struct Building {
        std::string pipeline;
        double seconds = 0.0;
        std::string then; // what changes once it is ready
    };
    std::optional<Building> building; // a pipeline the settings wait for, built on a worker
    const scene::Scene* scene = nullptr;
    const std::vector<scene::TreeRow>* tree = nullptr; // the scene's assembly tree
    const scene::PartSet* hidden = nullptr;
    scene::Bounds bounds;   // the scene's, for the section planes' sliders
    scene::Section section; // the document's planes
    float explode = 0.0f;   // the document's explode fraction
    // The selected part's surface when it is a planar B-rep face (world), for a section plane.
    std::optional<scene::SurfaceInfo> selectedPlane;
    bool measuring = false;                // measure mode (M)
    std::vector<std::string> measureLines; // its points, faces, distance and angle
    render::RenderStats stats;
    render::SwitchReport lastSwitch;
    size_t cachedPipelines = 0;
    scene::IdDataBytes idBytes;
    VkSampleCountFlags sampleCounts = VK_SAMPLE_COUNT_1_BIT; // offered by the device
    render::ClearPath clearPath = render::ClearPath::Pass;   // the one drawing (never Auto)
    std::optional<render::ClearTiming> clearTiming;          // Auto's, at the MSAA drawn
    double fps = 0.0, gpuMs = 0.0, cpuRecordMs = 0.0;
    bool continuous = false;       // vsync off: a scene pass every frame, so fps means something
    std::vector<float> gpuHistory; // the last ~200 scene pass times, oldest first
    PartLine hovered, selected;
    uint32_t selectedCount = 0, hiddenCount = 0;
    bool xray = false;                 // the document's X-ray
    std::bitset<commandCount> enabled; // by CommandId: what can do anything now (commands.h)
    bool can(CommandId id) const { return enabled[size_t(id)]; }
    const scene::PartSet* selectedParts = nullptr; // the tree highlights rows all selected
    // The deepest tree row whose parts are exactly the selection (scene::rowOfParts).
    std::optional<size_t> selectedRow;
    uint32_t visibleParts = 0; // counted on the GPU in the newest completed frame
    // The Inspect section's sizes, properties and distance, worked out when the selection or
    // things A and B changed (inspect_report.h).
    const InspectReport* inspect = nullptr;
    double idPassMs = 0.0; // GPU time of the edge and part set passes
    // Culling: what the technique and mode get of the mode chosen, what the newest completed
    // frame drew of the totals, and the GPU time of the cull passes and the depth pyramid.
    std::string cullingApplied;
    render::CullCounts drawn, totals;
    double cullMs = 0.0, pyramidMs = 0.0;
    // Levels of detail: whether the technique, mode and culling chosen have the cull pass
    // choose them (else full detail is drawn).
    bool lodChosen = false;
    // The Visibility section: the census running (views drawn, views), what the last one
    // found, and the window's parts by pixels (`census here`), largest first.
    std::optional<std::pair<uint32_t, uint32_t>> censusProgress;
    const CensusFound* census = nullptr;
    bool censusTint = false; // the tint by visibility is on
    const std::vector<HerePart>* here = nullptr;
    // Export seen...: where it proposes to write (a .glb; a CAD model offers .step too), and
    // the last export's line (writing, wrote, its error), "" before the first.
    std::string exportDefault;
    bool exportStep = false;
    bool exporting = false;
    const std::string* exportLine = nullptr;
};

// Draws the panel; the user's changes land in `settings` (scene, render, animation) and
// `view`, what it asks of the parts in the result.
PanelActions drawPanel(LiveSettings& settings, ViewSettings& view, const PanelInfo& info);

} // namespace app
