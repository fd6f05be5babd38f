// panel_selection.cpp - hovered and selected part details, wrapped to the panel's width.
#include "app/viewer/panel_selection.h"

#include <string>

#include <imgui.h>

#include "app/viewer/panel_commands.h"
#include "app/viewer/panel_widgets.h"
#include "scene/precision.h"

namespace app {
namespace {

// Lines each details box holds: a part's name, path, face and its surface, its edge, object
// and triangles, with room for a long name to wrap once. Fixed, so what lies below never jumps as
// the hover changes (it scrolls where a narrow panel wraps more).
constexpr float detailLines = 8.0f;

void partLine(const char* what, const PartLine& line) {
    if (!line.part) {
        ImGui::TextDisabled("%s: none", what);
        return;
    }
    const scene::PartInfo& p = *line.part;
    ImGui::TextWrapped("%s: part %u, %s", what, p.uniquePartId, p.name.c_str());
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", p.path.c_str());
    ImGui::PopStyleColor();
    if (p.face) {
        const std::string surface = line.face ? ": " + scene::describeSurface(*line.face) : "";
        textWrappedAtSpaces("face " + std::to_string(*p.face) + surface);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("the B-rep face's number in its shape (0-based, as --face-info "
                              "gives it); its exact area from Open CASCADE");
    }
    if (!line.edge.empty()) {
        textWrappedAtSpaces(line.edge);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("the B-rep edge's number in its shape (0-based, as --edge-info "
                              "gives it); its exact length, radius and axis from Open CASCADE");
    }
    ImGui::TextWrapped("object %u, local part %u, geometry %u", p.object, p.localPart, p.geometry);
    // The depth buffer's value (0 near, 1 far): a float, shown to a millionth.
    textWrappedAtSpaces(std::to_string(p.triangleCount) + " triangles, depth " +
                        scene::rounded(line.depth, 1e-6));
}

// More than one part: the tree node they make up, if they are exactly one node's parts.
void selectionLine(const PanelInfo& info) {
    if (info.selectedCount <= 1) {
        partLine("selected", info.selected);
        return;
    }
    const scene::TreeRow* row =
        info.tree && info.selectedRow && *info.selectedRow < info.tree->size()
            ? &(*info.tree)[*info.selectedRow]
            : nullptr;
    if (row) {
        ImGui::TextWrapped("selected: %s (%u parts)", row->label.c_str(), info.selectedCount);
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        if (!row->path.empty()) ImGui::TextWrapped("%s", row->path.c_str());
        ImGui::PopStyleColor();
    } else {
        ImGui::TextWrapped("selected: %u parts", info.selectedCount);
    }
    // The first selected part says where the selection starts (several nodes, a box).
    if (info.selected.part)
        ImGui::TextWrapped("first: part %u, %s", info.selected.part->uniquePartId,
                           info.selected.part->path.c_str());
}

void detailsBox(const char* id, PanelLayout& layout, auto&& draw) {
    const float height = detailLines * ImGui::GetTextLineHeightWithSpacing();
    if (ImGui::BeginChild(id, ImVec2(-1, height), true)) draw();
    layout.checkChild();
    ImGui::EndChild();
}

} // namespace

void selectionSection(const ViewSettings& view, const PanelInfo& info, PanelActions& actions,
                      PanelLayout& layout) {
    if (info.hiddenCount)
        ImGui::TextWrapped("visible parts %u, hidden %u", info.visibleParts, info.hiddenCount);
    else
        ImGui::TextWrapped("visible parts %u", info.visibleParts);
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
    layout.mark("selected part");
    detailsBox("##selected", layout, [&] { selectionLine(info); });
    layout.mark("hovered part");
    detailsBox("##hovered", layout, [&] { partLine("hovered", info.hovered); });
    layout.mark("hide buttons");
    commandButton("hide", CommandId::Hide, info, actions);
    commandButton("isolate", CommandId::Isolate, info, actions, true);
    commandButton("show all", CommandId::ShowAll, info, actions, true);
    switchCheckbox("X-ray", CommandId::Xray, info.xray, actions);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the parts outside the selection drawn translucent: not in the ID "
                          "image, not picked, not hiding the selection, so selected parts "
                          "inside show and can be picked and measured in place. With nothing "
                          "selected it changes nothing.");
}

} // namespace app
