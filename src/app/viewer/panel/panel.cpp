// panel.cpp - the panel: the open field, view toggles, renderer settings, scene, statistics,
// timing and help; its layout, the part a newcomer needs first at the top.
#include "app/viewer/panel/panel.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <type_traits>
#include <utility>

#include <imgui.h>

#include "app/viewer/commands/commands.h"
#include "app/viewer/panel/panel_browser.h"
#include "app/viewer/panel/panel_census.h"
#include "app/viewer/panel/panel_commands.h"
#include "app/viewer/panel/panel_layout.h"
#include "app/viewer/panel/panel_rendering.h"
#include "app/viewer/panel/panel_section.h"
#include "app/viewer/panel/panel_selection.h"
#include "app/viewer/panel/panel_tools.h"
#include "app/viewer/panel/panel_tree.h"
#include "app/viewer/panel/panel_widgets.h"
#include "scene/formats.h"

namespace app {
namespace {

// When to choose which technique, from the H100 figures in docs/benchmarks.md.
const char* const techniqueHelp =
    "On an H100 at 1440p, against drawing with no part IDs:\n"
    "vertex-fs: 1.00-1.02x with and without MSAA, one draw per object, no mesh shaders. "
    "Start here.\n"
    "mesh-vertex-fs: 1.00-1.01x without MSAA (and the faster pipeline there), 1.04x with "
    "4x MSAA in the mdi modes (1.00x with push).\n"
    "tri-fs, search-fs, bsearch-fs, nsearch-fs: 1.03x with 4x MSAA, 1.24x without "
    "(gl_PrimitiveID).\n"
    "gs techniques and mesh-fs (per-primitive output): 1.3-1.6x, avoid.\n"
    "per-draw: one draw per part, 1.1-1.3x and CPU-bound with push constants.\n"
    "Numbers and method: docs/benchmarks.md.";

// On a CPU device (lavapipe) the timestamps measure the CPU rendering, not a GPU.
void timing(const PanelInfo& info) {
    if (info.cpuDevice)
        textWrappedAtSpacesf("Render [ms]  %.3f (CPU device: %s renders on the CPU)", info.gpuMs,
                             info.device.c_str());
    else
        textWrappedAtSpacesf("Render GPU [ms]  %.3f", info.gpuMs);
    textWrappedAtSpacesf("ID passes  [ms]  %.3f", info.idPassMs);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("edges and outlines, the visible part count and box selection: "
                          "compute passes over the ID image after the scene pass");
    textWrappedAtSpacesf("cull, pyramid [ms] %.3f, %.3f", info.cullMs, info.pyramidMs);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("time of the cull passes and of the depth pyramid; included in "
                          "Render");
    textWrappedAtSpacesf("CPU record [ms]  %.3f", info.cpuRecordMs);
    if (!info.gpuHistory.empty())
        ImGui::PlotLines("##gpu", info.gpuHistory.data(), int(info.gpuHistory.size()), 0,
                         "scene pass ms", 0.0f, FLT_MAX, ImVec2(-FLT_MIN, 60));
}

// The recent files' list: a file no longer there is greyed out (it may come back: a
// network drive, a USB stick), and the last entry empties the list.
void recentFiles(const ViewSettings& view, const PanelInfo& info, PanelActions& actions) {
    ImGui::BeginDisabled(view.recentFiles.empty());
    if (ImGui::BeginCombo("##recent", nullptr, ImGuiComboFlags_NoPreview)) {
        for (const std::string& path : view.recentFiles) {
            std::error_code error;
            const bool there = std::filesystem::exists(path, error); // only while open
            if (ImGui::Selectable(path.c_str(), false,
                                  there ? ImGuiSelectableFlags_None
                                        : ImGuiSelectableFlags_Disabled))
                actions.ask({CommandId::Open, path});
        }
        ImGui::Separator();
        if (ImGui::Selectable("clear list", false,
                              info.can(CommandId::ClearRecent) ? ImGuiSelectableFlags_None
                                                               : ImGuiSelectableFlags_Disabled))
            actions.ask({CommandId::ClearRecent});
        ImGui::EndCombo();
    }
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s",
                          view.recentFiles.empty() ? "recent files: none yet" : "recent files");
}

// The model path field, the width of the panel so its hint shows whole, with the recent
// files beside it. Clicking it, or Ctrl+O, selects what it holds: typing replaces it.
void openField(ViewSettings& view, const PanelInfo& info, PanelActions& actions) {
    const float spacing = ImGui::GetStyle().ItemInnerSpacing.x;
    const char* chooseLabel = "Open...";
    const float chooseWidth =
        ImGui::CalcTextSize(chooseLabel).x + 2.0f * ImGui::GetStyle().FramePadding.x;
    const float recentWidth = ImGui::GetFrameHeight();
    if (std::exchange(view.focusOpen, false)) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - recentWidth - chooseWidth -
                            2.0f * spacing);
    static const std::string hint = std::string("open ").append(scene::extensionList());
    if (ImGui::InputTextWithHint("##open", hint.c_str(), view.openPath.data(), view.openPath.size(),
                                 ImGuiInputTextFlags_EnterReturnsTrue |
                                     ImGuiInputTextFlags_AutoSelectAll) &&
        view.openPath[0])
        actions.ask({CommandId::Open, std::string(view.openPath.data())});
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("type or paste a model's path, Enter opens it; or drop the file on "
                          "the window");
    ImGui::SameLine(0.0f, spacing);
    if (ImGui::Button(chooseLabel)) actions.ask({CommandId::Open});
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s", withKeys("choose a model file", CommandId::Open).c_str());
    ImGui::SameLine(0.0f, spacing);
    recentFiles(view, info, actions);
}

// A model loading: its stage and bar; a big CAD file shown as it loads says what is shown
// and what is left, and offers Stop here beside Cancel.
void loadingLines(const PanelInfo::Loading& loading, PanelActions& actions) {
    // CAD loads report their stage and how far it is; glTF loads report nothing, and the
    // bar sweeps once a second while they run.
    const double t = loading.seconds;
    char label[96];
    std::snprintf(label, sizeof label, "%s %.0f%%, %.1f s",
                  loading.stage.empty() ? "loading" : loading.stage.c_str(),
                  100.0 * loading.fraction, t);
    ImGui::TextWrapped("%s", loading.path.c_str());
    if (!loading.shown.empty()) ImGui::TextWrapped("%s", loading.shown.c_str());
    const double shown = loading.stage.empty() ? t - std::floor(t) : loading.fraction;
    ImGui::ProgressBar(float(shown), ImVec2(-1, 0), label);
    if (loading.stopping) {
        textDisabledWrapped("stopping: the workers are killed");
        return;
    }
    // CAD loads stop at their next face or progress step; glTF loads run to their end. Esc
    // does Cancel where there was a model before, else Stop (commands.h).
    const std::string esc = " (" + keysOf(CommandId::Escape) + ")";
    if (!loading.shown.empty()) {
        if (ImGui::Button("Stop here")) actions.ask({CommandId::Stop});
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("stop loading: what is shown stays, marked incomplete%s",
                              loading.modelBefore ? "" : esc.c_str());
        ImGui::SameLine();
    }
    if (ImGui::Button("Cancel")) actions.ask({CommandId::Cancel});
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s", loading.modelBefore
                                    ? ("stop loading, back to the model shown before" + esc).c_str()
                                    : "stop loading: nothing stays open");
}

// The device and how the frames are drawn: in Rendering, with the GPU's other settings.
void device(const PanelInfo& info) {
    // The frame rate on the device's line where the widest rate would fit there too, else on
    // a line of its own: a rate gaining a digit never wraps the line and moves what follows.
    // Drawing on change, a frame rate would count changes: the panel says so instead.
    char fps[32];
    if (info.continuous)
        std::snprintf(fps, sizeof fps, "%.0f fps", info.fps);
    else
        std::snprintf(fps, sizeof fps, "draws on change");
    const std::string widest = info.device + ", draws on change"; // wider than 99999 fps
    if (ImGui::CalcTextSize(widest.c_str()).x <= ImGui::GetContentRegionAvail().x) {
        textDisabledWrapped((info.device + ", " + fps).c_str());
    } else {
        textDisabledWrapped(info.device.c_str());
        textDisabledWrapped(fps);
    }
}

// What needs the person now: the last error, a pipeline being built, a model loading.
void status(const PanelInfo& info, PanelActions& actions) {
    if (!info.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", info.error.c_str());
        ImGui::PopStyleColor();
    }
    if (const auto& building = info.building)
        textWrappedAtSpacesf("building pipeline %s, %.1f s: what is drawn stays until it is "
                             "ready, then %s",
                             building->pipeline.c_str(), building->seconds, building->then.c_str());
    if (const auto& loading = info.loading) loadingLines(*loading, actions);
}

// The scene's source and the unit its lengths are in (where the unit comes from in a
// tooltip).
void source(const PanelInfo& info) {
    textDisabledWrapped(info.source.c_str());
    if (!info.incomplete.empty()) { // stopped while it loaded
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.72f, 0.1f, 1.0f));
        ImGui::TextWrapped("incomplete: %s (stopped while loading)", info.incomplete.c_str());
        ImGui::PopStyleColor();
    }
    if (!info.scene || info.source.empty()) return; // nothing open: no unit either
    const scene::LengthUnit& unit = info.scene->unit;
    textDisabledWrapped(scene::unitHeading(unit).c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", unit.source.c_str());
}

// Docked at the window's left side, full height; its right edge drags its width, which
// stays between minPanelWidth and maxPanelShare of the window.
bool beginPanel(ViewSettings& view) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float widest = std::max(minPanelWidth, maxPanelShare * display.x);
    view.panelWidth = std::clamp(view.panelWidth, minPanelWidth, widest);
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(view.panelWidth, display.y), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(minPanelWidth, display.y),
                                        ImVec2(widest, display.y));
    ImGui::SetNextWindowBgAlpha(0.85f);
    // No move and no collapse: it stays docked, and F9 hides it.
    const std::string title = "idview (" + keysOf(CommandId::Panel) + " hides)";
    const bool open = ImGui::Begin(title.c_str(), nullptr,
                                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                                       ImGuiWindowFlags_NoSavedSettings);
    // A drag of its edge changed the size in Begin: that is the width from now on.
    if (open) view.panelWidth = ImGui::GetWindowWidth();
    return open;
}

} // namespace

PanelActions drawPanel(LiveSettings& settings, ViewSettings& view, const PanelInfo& info) {
    PanelActions actions;
    view.panelLeft = view.panelRight = 0.0f; // until it is drawn
    if (!beginPanel(view)) {
        ImGui::End();
        return actions;
    }
    // Where the panel lies, for F to fit the scene beside it.
    view.panelLeft = ImGui::GetWindowPos().x;
    view.panelRight = view.panelLeft + ImGui::GetWindowSize().x;
    PanelLayout layout(view.layout);
    layout.mark("status");
    status(info, actions);
    layout.mark("open");
    openField(view, info, actions);
    layout.mark("browser");
    drawFileBrowser(view.browser, actions, info.events);
    layout.mark("source");
    source(info);
    // Laid out for inspecting (FreeCAD's model tree and property view, Mayo's tree beside
    // the view): the tree, the tools, then what is selected and hovered with its measures;
    // the GPU's settings closed below. Every area above the closed headers keeps its
    // height, so a row stays under the pointer from one click to the next.
    layout.mark("Assembly tree");
    if (ImGui::CollapsingHeader("Assembly tree", ImGuiTreeNodeFlags_DefaultOpen))
        assemblyTree(view, info, actions, layout);
    layout.mark("Tools");
    if (ImGui::CollapsingHeader("Tools", ImGuiTreeNodeFlags_DefaultOpen))
        toolsSection(settings, view, info, actions, layout);
    layout.mark("Properties");
    if (ImGui::CollapsingHeader("Properties", ImGuiTreeNodeFlags_DefaultOpen))
        propertiesSection(info, layout);
    layout.mark("Visibility");
    if (ImGui::CollapsingHeader("Visibility")) visibilitySection(view, info, actions);
    layout.mark("Section");
    if (ImGui::CollapsingHeader("Section")) {
        // The document's planes, edited as a copy: a change goes back as the actions' section.
        scene::Section section = info.section;
        sectionPlanes(section, info.bounds, info.selectedPlane,
                      info.scene ? info.scene->unit : scene::generatedUnit(), layout);
        if (section != info.section) actions.section = section;
    }
    layout.mark("Rendering");
    if (ImGui::CollapsingHeader("Rendering")) {
        device(info);
        rendering(settings, info, actions);
    }
    layout.mark("Scene");
    if (ImGui::CollapsingHeader("Scene")) sceneSection(settings.scene, info, actions);
    layout.mark("Timing");
    if (ImGui::CollapsingHeader("Timing")) timing(info);
    layout.mark("Controls");
    if (ImGui::CollapsingHeader("Controls")) // the help overlay lists the command table
        ImGui::TextWrapped("%s lists every key, mouse action and command.",
                           keysOf(CommandId::Help).c_str());
    layout.mark("Which technique?");
    if (ImGui::CollapsingHeader("Which technique?")) ImGui::TextWrapped("%s", techniqueHelp);
    layout.finish(info.events);
    ImGui::End();
    actions.held = ImGui::IsAnyItemActive();
    return actions;
}

} // namespace app
