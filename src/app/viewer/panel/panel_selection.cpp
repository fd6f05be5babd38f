// panel_selection.cpp - the Properties section: the selected and hovered parts' details, then
// the measure points and the Inspect report, each box of fixed height (panel_selection.h).
#include "app/viewer/panel/panel_selection.h"

#include <string>

#include <imgui.h>

#include "app/viewer/panel/inspect_panel.h"
#include "app/viewer/panel/panel_widgets.h"
#include "scene/precision.h"

namespace app {
namespace {

// Lines each details box holds: a part's name, path, face and its surface, its edge, object
// and triangles, with room for a long name to wrap once. Fixed, so what lies below never jumps as
// the hover changes (it scrolls where a narrow panel wraps more).
constexpr float detailLines = 8.0f;
// Lines of the measure and Inspect box: a solid's volume, area and centre, a sum, A and B and
// their distance; more scroll inside it.
constexpr float inspectLines = 10.0f;

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

// The measure mode's points and the Inspect report, in one box of fixed height: what they say
// grows and shrinks with the clicks, inside the box, never moving the rows below.
void inspectBox(const PanelInfo& info, PanelLayout& layout) {
    const float height = inspectLines * ImGui::GetTextLineHeightWithSpacing();
    if (ImGui::BeginChild("##inspect", ImVec2(-1, height), true)) {
        if (info.measuring) {
            ImGui::TextUnformatted("Measure (M to leave)");
            if (info.measureLines.empty())
                ImGui::TextWrapped("Click a part for its face; two clicks for their distance.");
            for (const std::string& line : info.measureLines) textWrappedAtSpaces(line);
            ImGui::Spacing();
        }
        if (info.inspect) inspectSection(*info.inspect);
    }
    layout.checkChild();
    ImGui::EndChild();
}

} // namespace

void propertiesSection(const PanelInfo& info, PanelLayout& layout) {
    if (info.hiddenCount)
        ImGui::TextWrapped("visible parts %u, hidden %u", info.visibleParts, info.hiddenCount);
    else
        ImGui::TextWrapped("visible parts %u", info.visibleParts);
    layout.mark("selected part");
    detailsBox("##selected", layout, [&] { selectionLine(info); });
    layout.mark("hovered part");
    detailsBox("##hovered", layout, [&] { partLine("hovered", info.hovered); });
    layout.mark("Inspect");
    inspectBox(info, layout);
}

} // namespace app
