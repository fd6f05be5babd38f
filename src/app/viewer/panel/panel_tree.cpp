// panel_tree.cpp - the assembly tree in the panel. Rows are drawn through ImGui's list
// clipper, so a tree of tens of thousands of nodes costs the rows on screen; what the rows
// are (open nodes, the filter) is worked out from the flat rows by skipping closed subtrees.
#include "app/viewer/panel/panel_tree.h"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <string>

#include <imgui.h>

#include "app/viewer/commands/commands.h"
#include "app/viewer/panel/panel_widgets.h"
#include "scene/cad/cad_loader.h" // kObjectWaiting, kObjectLost

namespace app {

std::vector<uint8_t> rowsMatching(const std::vector<scene::TreeRow>& rows, const char* filter) {
    std::vector<uint8_t> kept(rows.size(), *filter ? 0 : 1);
    if (!*filter) return kept;
    auto lower = [](std::string text) {
        std::transform(text.begin(), text.end(), text.begin(),
                       [](unsigned char c) { return char(std::tolower(c)); });
        return text;
    };
    const std::string wanted = lower(filter);
    // Backwards: a row is kept when it matches or any row of its subtree was kept.
    for (size_t i = rows.size(); i-- > 0;) {
        bool keep = lower(rows[i].name).find(wanted) != std::string::npos;
        for (size_t r = i + 1; r < rows[i].end && !keep; r = rows[r].end) keep = kept[r];
        kept[i] = keep;
    }
    return kept;
}

namespace {

// Whether none, some or all of the ranges' parts are hidden.
enum class Shown { All, Some, None };
bool allIn(const scene::PartRanges& parts, const scene::PartSet& set) {
    bool any = false;
    for (const auto& [first, count] : parts) {
        if (!set.allIn(first, count)) return false;
        any = any || count > 0;
    }
    return any;
}
Shown shownOf(const scene::PartRanges& parts, const scene::PartSet& hidden) {
    bool anyHidden = false, anyShown = false;
    for (const auto& [first, count] : parts) {
        const uint32_t n = hidden.countIn(first, count);
        anyHidden = anyHidden || n > 0;
        anyShown = anyShown || n < count;
    }
    return anyHidden ? (anyShown ? Shown::Some : Shown::None) : Shown::All;
}

// An object's row while its model loads, and after Stop: " (loading)" or " (missing)" until
// its solid is meshed, " (lost)" where its worker died; "" once it is drawn.
std::string stateSuffix(const PanelInfo& info, const scene::TreeRow& row, bool loading) {
    if (!info.objectStates || !row.object || *row.object >= info.objectStates->size()) return "";
    switch ((*info.objectStates)[*row.object]) {
    case scene::kObjectWaiting:
        return loading ? " (loading)" : " (missing)";
    case scene::kObjectLost:
        return " (lost)";
    default:
        return "";
    }
}

// One row: its arrow (a branch, not the root, while not filtering), its checkbox and its
// name. Checked: every part under the node shows; a click hides them all, or shows them all
// when some are hidden. Highlighted: every part under it is selected (a row click, a solid, a
// box); a long name is cut to the row, whole in the tooltip with its path.
void treeRow(ViewSettings& view, const PanelInfo& info, uint32_t i, bool filtering,
             PanelActions& actions) {
    const std::vector<scene::TreeRow>& rows = *info.tree;
    const scene::TreeRow& row = rows[i];
    ImGui::PushID(int(i));
    const float indent = float(row.depth) * 12.0f;
    if (indent > 0.0f) ImGui::Indent(indent); // 0 would mean ImGui's default width
    const bool branch = row.end > i + 1;
    if (branch && i > 0 && !filtering) {
        if (ImGui::ArrowButton("##open", view.treeOpen[i] ? ImGuiDir_Down : ImGuiDir_Right))
            view.treeOpen[i] = !view.treeOpen[i];
    } else {
        ImGui::Dummy(ImVec2(ImGui::GetFrameHeight(), ImGui::GetFrameHeight()));
    }
    ImGui::SameLine();
    const Shown state = shownOf(row.parts, *info.hidden);
    bool visible = state == Shown::All;
    if (state == Shown::Some) ImGui::PushStyleVar(ImGuiStyleVar_Alpha, 0.5f);
    if (ImGui::Checkbox("##visible", &visible))
        actions.ask(
            {CommandId::Node,
             nodeOfRow(rows, i, state == Shown::All ? NodeAction::Hide : NodeAction::Show)});
    if (state == Shown::Some) ImGui::PopStyleVar();
    ImGui::SameLine();
    const bool selected = info.selectedParts && allIn(row.parts, *info.selectedParts);
    const std::string suffix = stateSuffix(info, row, info.loading.has_value());
    const std::string label = (row.label.empty() ? row.name : row.label) + suffix;
    const std::string shown = elided(label, ImGui::GetContentRegionAvail().x);
    const bool drawn = suffix.empty(); // greyed until its solid is
    if (!drawn)
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    if (ImGui::Selectable((shown + "###row").c_str(), selected))
        actions.ask(
            {CommandId::Node,
             nodeOfRow(rows, i, ImGui::GetIO().KeyCtrl ? NodeAction::Add : NodeAction::Select)});
    if (!drawn) ImGui::PopStyleColor();
    if (ImGui::IsItemHovered() && (!row.path.empty() || shown != label))
        ImGui::SetTooltip("%s", row.path.empty() ? label.c_str() : row.path.c_str());
    if (indent > 0.0f) ImGui::Unindent(indent);
    ImGui::PopID();
}

// A bar the pointer drags up and down to resize the tree's pane, in rows.
void splitter(float& rows, float rowHeight) {
    const float thickness = ImGui::GetStyle().ItemSpacing.y + 4.0f;
    ImGui::InvisibleButton("##tree height", ImVec2(-1, thickness));
    const bool hot = ImGui::IsItemHovered() || ImGui::IsItemActive();
    if (hot) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeNS);
    if (ImGui::IsItemActive())
        rows = std::clamp(rows + ImGui::GetIO().MouseDelta.y / rowHeight, minTreeRows, maxTreeRows);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("drag to make the tree taller or shorter");
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    const float y = 0.5f * (a.y + b.y);
    ImGui::GetWindowDrawList()->AddLine(
        ImVec2(a.x, y), ImVec2(b.x, y),
        ImGui::GetColorU32(hot ? ImGuiCol_SeparatorActive : ImGuiCol_Separator), hot ? 3.0f : 1.0f);
}

} // namespace

void assemblyTree(ViewSettings& view, const PanelInfo& info, PanelActions& actions,
                  PanelLayout& layout) {
    if (!info.tree || info.tree->empty() || !info.hidden) return;
    const std::vector<scene::TreeRow>& rows = *info.tree;
    if (view.treeOpen.size() != rows.size()) view.treeOpen.assign(rows.size(), 0);
    ImGui::SetNextItemWidth(-FLT_MIN);
    ImGui::InputTextWithHint("##filter", "filter by name", view.objectFilter.data(),
                             view.objectFilter.size());
    if (view.treeFilterFor != view.objectFilter.data() || view.treeShown.size() != rows.size()) {
        view.treeFilterFor = view.objectFilter.data();
        view.treeShown = rowsMatching(rows, view.objectFilter.data());
    }
    const bool filtering = !view.treeFilterFor.empty();
    // The rows to draw: kept by the filter, under open nodes (all open while filtering).
    std::vector<uint32_t> shown;
    for (uint32_t i = 0; i < rows.size();) {
        if (!view.treeShown[i]) {
            i = rows[i].end;
            continue;
        }
        shown.push_back(i);
        i = (filtering || view.treeOpen[i] || i == 0) ? i + 1 : rows[i].end;
    }
    ImGui::TextWrapped("%zu rows of %zu nodes", shown.size(), rows.size());
    layout.mark("tree rows");
    // A pane of its own height, whatever the filter keeps: the rows below never move with it.
    // The bar under it drags that height.
    view.treeRows = std::clamp(view.treeRows, minTreeRows, maxTreeRows);
    const float rowHeight = ImGui::GetFrameHeightWithSpacing();
    const float height = view.treeRows * rowHeight + 2.0f * ImGui::GetStyle().WindowPadding.y;
    if (ImGui::BeginChild("##tree", ImVec2(-1, height), true)) {
        ImGuiListClipper clipper;
        clipper.Begin(int(shown.size()));
        while (clipper.Step())
            for (int line = clipper.DisplayStart; line < clipper.DisplayEnd; ++line)
                treeRow(view, info, shown[size_t(line)], filtering, actions);
    }
    layout.checkChild();
    ImGui::EndChild();
    splitter(view.treeRows, rowHeight);
}

} // namespace app
