// panel_census.cpp - the Visibility section (panel_census.h).
#include "app/viewer/panel/panel_census.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

#include <imgui.h>

#include "app/cli.h"
#include "app/viewer/panel/panel_widgets.h"

namespace app {
namespace {

// The most rows "visible from here" lists; the event record has them all.
constexpr size_t hereRows = 40;

void ask(PanelActions& actions, CensusAction action, uint32_t part = 0, bool on = false) {
    actions.ask({CommandId::Census, CensusAsk{action, 0, 0, part, on}});
}

// The fields and Run, or the running census's progress and Cancel.
void runRow(ViewSettings& view, const PanelInfo& info, PanelActions& actions) {
    if (const auto progress = info.censusProgress) {
        const auto [drawn, views] = *progress;
        const std::string text = "view " + std::to_string(drawn) + " of " + std::to_string(views);
        ImGui::ProgressBar(views ? float(drawn) / float(views) : 0.0f, ImVec2(-1.0f, 0.0f),
                           text.c_str());
        if (ImGui::Button("Cancel (Esc)")) ask(actions, CensusAction::Cancel);
        return;
    }
    const ImU32 step = 1;
    ImGui::SetNextItemWidth(110.0f);
    ImGui::InputScalar("views", ImGuiDataType_U32, &view.censusViews, &step);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(110.0f);
    ImGui::InputScalar("size", ImGuiDataType_U32, &view.censusSize, &step);
    view.censusViews = std::clamp(view.censusViews, 1u, 100000u);
    view.censusSize = std::clamp(view.censusSize, 16u, 8192u);
    ImGui::TextWrapped("%u orthographic views spread over a sphere, each %u x %u pixels, one ID "
                       "per pixel at full detail; hidden parts, the section and explode apply.",
                       view.censusViews, view.censusSize, view.censusSize);
    if (ImGui::Button("Run census"))
        actions.ask({CommandId::Census,
                     CensusAsk{CensusAction::Run, view.censusViews, view.censusSize, 0}});
}

float buttonWidth(const char* label) {
    return ImGui::CalcTextSize(label).x + 2.0f * ImGui::GetStyle().FramePadding.x;
}

double percent(uint64_t part, uint64_t whole) {
    return whole ? 100.0 * double(part) / double(whole) : 0.0;
}

// The toggle and, while on, what its colours mean (visibility_tint.h).
void tintRow(const PanelInfo& info, PanelActions& actions) {
    bool on = info.censusTint;
    if (ImGui::Checkbox("Tint by visibility", &on)) ask(actions, CensusAction::Tint, 0, on);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("each part's colour by the pixels the census saw of it (log scale)");
    if (!on) return;
    ImGui::TextColored(ImVec4(0.3f, 0.5f, 1.0f, 1.0f), "barely seen");
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(0.0f, 1.0f, 0.0f, 1.0f), "->");
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.0f, 0.2f, 0.2f, 1.0f), "most seen");
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.0f, 0.0f, 1.0f, 1.0f), " never seen");
}

void summary(const CensusFound& found, PanelActions& actions) {
    const scene::CensusSummary& s = found.summary;
    ImGui::TextWrapped("%u views of %u x %u: %u of %u parts seen", found.census.views,
                       found.census.width, found.census.height, s.partsSeen, s.parts);
    ImGui::TextWrapped("never seen: %u parts (%.1f%% of the triangles), %u solids",
                       s.partsNeverSeen, percent(s.trianglesNeverSeen, s.triangles),
                       s.objectsNeverSeen);
    if (s.partsHidden || s.partsEmpty)
        ImGui::TextWrapped("not counted: %u hidden, %u without triangles", s.partsHidden,
                           s.partsEmpty);
    ImGui::BeginDisabled(s.partsNeverSeen == 0);
    if (ImGui::Button("Select never seen")) ask(actions, CensusAction::Select);
    sameLineIfFits(buttonWidth("Hide never seen"));
    if (ImGui::Button("Hide never seen")) ask(actions, CensusAction::Hide);
    sameLineIfFits(buttonWidth("Isolate never seen"));
    if (ImGui::Button("Isolate never seen")) ask(actions, CensusAction::Isolate);
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("show only the parts no view saw (hide everything else); Ctrl+Z undoes");
}

// The export's path field filled with `path`, cut to fit.
void fillExportPath(ViewSettings& view, const std::string& path) {
    view.exportPath.fill('\0');
    path.copy(view.exportPath.data(), view.exportPath.size() - 1);
}

// Export seen...: the path (.glb, or .step for a CAD model: the radio buttons switch the
// extension), Export, and the last export's line.
void exportRow(ViewSettings& view, const PanelInfo& info, PanelActions& actions) {
    if (view.exportPathFor != info.exportDefault) { // a new model: its own proposal
        fillExportPath(view, info.exportDefault);
        view.exportPathFor = info.exportDefault;
    }
    ImGui::TextUnformatted("Export seen...");
    if (info.exportStep) {
        const std::filesystem::path path(view.exportPath.data());
        int step = censusExportsStep(path.string()) ? 1 : 0;
        const int was = step;
        ImGui::SameLine();
        ImGui::RadioButton("glb", &step, 0);
        ImGui::SameLine();
        ImGui::RadioButton("step", &step, 1);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("the solids with a seen face, from the CAD file read again");
        if (step != was)
            fillExportPath(
                view,
                std::filesystem::path(path).replace_extension(step ? ".step" : ".glb").string());
    }
    const char* label = "Export";
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - buttonWidth(label) -
                            ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::InputText("##export", view.exportPath.data(), view.exportPath.size(),
                     ImGuiInputTextFlags_AutoSelectAll);
    ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::BeginDisabled(info.exporting || !view.exportPath[0]);
    if (ImGui::Button(label))
        actions.ask({CommandId::Census, CensusAsk{CensusAction::Export, 0, 0, 0, false,
                                                  std::string(view.exportPath.data())}});
    ImGui::EndDisabled();
    if (info.exportLine && !info.exportLine->empty()) wrappedLine(*info.exportLine);
}

// The window's parts by pixel area, largest first; a click on a row selects its part.
void hereList(const PanelInfo& info, PanelActions& actions) {
    if (ImGui::Button("Visible from here")) ask(actions, CensusAction::Here);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the parts of the window's picture now, by pixels (its ID image)");
    if (!info.here || info.here->empty() || !info.scene) return;
    const std::vector<HerePart>& here = *info.here;
    ImGui::Text("%zu parts in the picture", here.size());
    if (!ImGui::BeginTable("here", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp))
        return;
    for (size_t i = 0; i < here.size() && i < hereRows; ++i) {
        const HerePart& row = here[i];
        const auto part = scene::describePart(*info.scene, row.part);
        char label[320]; // "#ID name", and the row's own ImGui ID after ##
        std::snprintf(label, sizeof label, "#%u %s##here%zu", row.part,
                      part ? part->name.c_str() : "", i);
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        const bool selected = info.selectedParts && info.selectedParts->contains(row.part);
        if (ImGui::Selectable(label, selected, ImGuiSelectableFlags_SpanAllColumns))
            ask(actions, CensusAction::Part, row.part);
        ImGui::TableNextColumn();
        ImGui::Text("%llu px", static_cast<unsigned long long>(row.pixels));
        ImGui::TableNextColumn();
        ImGui::Text("%.2f%%", 100.0 * row.share);
    }
    ImGui::EndTable();
    if (here.size() > hereRows) ImGui::TextDisabled("and %zu more", here.size() - hereRows);
}

} // namespace

void visibilitySection(ViewSettings& view, const PanelInfo& info, PanelActions& actions) {
    runRow(view, info, actions);
    if (info.census) {
        summary(*info.census, actions);
        tintRow(info, actions);
        exportRow(view, info, actions);
    }
    ImGui::Separator();
    hereList(info, actions);
}

} // namespace app
