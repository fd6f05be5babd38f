// panel_tools.cpp - the Tools section (panel_tools.h).
#include "app/viewer/panel/panel_tools.h"

#include <imgui.h>

#include "app/viewer/panel/panel_commands.h"
#include "app/viewer/panel/panel_widgets.h"
#include "scene/standard_view.h"

namespace app {
namespace {

// Edges, projection, vsync and the standard views.
void viewRow(const LiveSettings& settings, const ViewSettings& view, PanelActions& actions) {
    switchCheckbox("edges", CommandId::Edges, settings.render.edges.on, actions);
    switchCheckbox("ortho", CommandId::Ortho, settings.camera.ortho, actions, true);
    switchCheckbox("vsync", CommandId::Vsync, view.vsync, actions, true);
    // The standard views, as their keys turn to them (1, 3, 7, Ctrl, 0), wrapped to the
    // panel's width.
    const ImGuiStyle& style = ImGui::GetStyle();
    for (const scene::StandardView& standard : scene::standardViews()) {
        const float width = ImGui::CalcTextSize(standard.name).x + 2.0f * style.FramePadding.x;
        if (&standard != scene::standardViews().data()) {
            ImGui::SameLine();
            if (ImGui::GetContentRegionAvail().x < width) ImGui::NewLine();
        }
        if (ImGui::SmallButton(standard.name)) actions.ask({CommandId::View, &standard});
    }
}

void selectLevel(const ViewSettings& view, PanelActions& actions) {
    ImGui::TextUnformatted("click selects");
    const char* levels[] = {"face", "solid", "assembly"};
    for (uint32_t level = 0; level < 3; ++level) {
        sameLineIfFits(checkboxWidth(levels[level]));
        if (ImGui::RadioButton(levels[level], view.selectLevel == level))
            actions.ask({CommandId::Level, level});
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("face: the part (a CAD face); solid: its object; assembly: the "
                          "node above it. A double-click selects the solid at least.");
}

void hideRow(const PanelInfo& info, PanelActions& actions) {
    commandButton("hide", CommandId::Hide, info, actions);
    commandButton("isolate", CommandId::Isolate, info, actions, true);
    commandButton("show all", CommandId::ShowAll, info, actions, true);
    switchCheckbox("X-ray", CommandId::Xray, info.xray, actions);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the parts outside the selection drawn translucent: not in the ID "
                          "image, not picked, not hiding the selection, so selected parts "
                          "inside show and can be picked and measured in place. With nothing "
                          "selected it changes nothing.");
    switchCheckbox("measure", CommandId::Measure, info.measuring, actions, true);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("clicks place points on surfaces: a face's data, then the distance "
                          "and angle of two (Properties shows them)");
}

// The exploded view, by assembly level (scene/explode.h); --animate's loop, for the
// benchmark, has no place here.
void explodeSlider(const PanelInfo& info, PanelActions& actions) {
    float explode = info.explode;
    ImGui::SliderFloat(fitLabel("explode").c_str(), &explode, 0.0f, 1.0f, "%.2f",
                       ImGuiSliderFlags_AlwaysClamp);
    if (explode != info.explode) actions.ask({CommandId::Explode, explode});
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("move the parts apart, assembly level by level: sub-assemblies from "
                          "their assembly's centre, their parts within them (--explode F)");
}

} // namespace

void toolsSection(const LiveSettings& settings, const ViewSettings& view, const PanelInfo& info,
                  PanelActions& actions, PanelLayout& layout) {
    layout.mark("view");
    viewRow(settings, view, actions);
    layout.mark("click selects");
    selectLevel(view, actions);
    layout.mark("hide buttons");
    hideRow(info, actions);
    layout.mark("explode");
    explodeSlider(info, actions);
}

} // namespace app
