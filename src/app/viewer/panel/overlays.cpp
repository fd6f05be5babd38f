// overlays.cpp - the help overlay, the empty view's explanation and the notice, drawn with
// ImGui over the view.
#include "app/viewer/panel/overlays.h"

#include <algorithm>
#include <array>

#include <imgui.h>

#include "app/viewer/commands/commands.h"
#include "scene/bounds.h"

namespace app {

// Each reason names the keys that mend it, as the command table binds them.
std::optional<EmptyReason> whyEmpty(uint32_t partCount, uint32_t hiddenCount, bool sectionOn,
                                    std::optional<uint32_t> visible) {
    if (partCount == 0)
        return EmptyReason{"no parts", "This model has no parts to draw - " +
                                           keysOf(CommandId::Open) + " opens another"};
    if (hiddenCount >= partCount)
        return EmptyReason{"all hidden", "All " + std::to_string(partCount) +
                                             " parts are hidden - " + keysOf(CommandId::ShowAll) +
                                             " shows them"};
    if (!visible || *visible > 0) return std::nullopt;
    if (sectionOn)
        return EmptyReason{"section", "The section planes cut everything away - move or turn "
                                      "them off in the panel's Section, or " +
                                          keysOf(CommandId::Undo)};
    return EmptyReason{"out of view", "Nothing is in view - " + keysOf(CommandId::Fit) +
                                          " fits the model, " + keysOf(CommandId::ResetView) +
                                          " goes back to its first view"};
}

// The command table (commands.h): each command's keys, what it does and its script words;
// the mouse gestures after them.
void drawHelp(bool& open) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(0.5f * display.x, 0.5f * display.y), ImGuiCond_Appearing,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(860.0f, 0.95f * display.x), 0.9f * display.y),
                             ImGuiCond_Appearing);
    ImGui::SetNextWindowBgAlpha(0.94f);
    const std::string title = "Keys, mouse and commands (" + keysOf(CommandId::Help) + " or " +
                              keysOf(CommandId::Escape) + " closes)###help";
    if (!ImGui::Begin(title.c_str(), &open,
                      ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings)) {
        ImGui::End();
        return;
    }
    if (ImGui::BeginTable("keys", 3, ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableSetupColumn("does", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("script", ImGuiTableColumnFlags_WidthFixed);
        for (const HelpLine& line : helpLines()) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(line.keys.c_str());
            ImGui::TableNextColumn();
            ImGui::TextWrapped("%s", line.description.c_str());
            ImGui::TableNextColumn();
            ImGui::TextDisabled("%s", line.script.c_str());
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

// Behind ImGui's windows (the background draw list), so the panel and help stay on top.
void drawCentred(const std::string& text, FreeSpan span, float heightFraction) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float left = span.left * display.x, right = span.right * display.x;
    const float wrap = std::max(80.0f, std::min(520.0f, right - left - 40.0f));
    const ImVec2 size = ImGui::CalcTextSize(text.c_str(), nullptr, false, wrap);
    const ImVec2 at(0.5f * (left + right - size.x), heightFraction * display.y - 0.5f * size.y);
    const float pad = 10.0f;
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    draw->AddRectFilled(ImVec2(at.x - pad, at.y - pad),
                        ImVec2(at.x + size.x + pad, at.y + size.y + pad), IM_COL32(0, 0, 0, 150),
                        6.0f);
    draw->AddText(nullptr, 0.0f, at, IM_COL32(220, 220, 220, 255), text.c_str(), nullptr, wrap);
}

namespace {

// A world segment from clip-space ends, cut where it passes behind the eye (w near 0 would
// project to infinity), drawn in window coordinates.
void clippedLine(ImDrawList* draw, glm::dvec4 a, glm::dvec4 b, glm::vec2 size, ImU32 colour) {
    const double nearW = 1e-4 * std::max(a.w, b.w);
    if (a.w < nearW && b.w < nearW) return;
    if (a.w < nearW) a = glm::mix(a, b, (nearW - a.w) / (b.w - a.w));
    if (b.w < nearW) b = glm::mix(b, a, (nearW - b.w) / (a.w - b.w));
    auto window = [&](const glm::dvec4& clip) {
        const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
        return ImVec2(float((ndc.x * 0.5 + 0.5) * size.x), float((ndc.y * 0.5 + 0.5) * size.y));
    };
    draw->AddLine(window(a), window(b), colour, 1.0f);
}

} // namespace

void drawWaitingBoxes(const scene::Scene& scene, const scene::CadPartial& partial,
                      const scene::PartSet& hidden, const glm::dmat4& viewProj, glm::vec2 size) {
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const size_t count =
        std::min({partial.boxes.size(), partial.state.size(), scene.objects.size()});
    for (size_t i = 0; i < count; ++i) {
        const scene::Bounds& box = partial.boxes[i];
        if (partial.state[i] == scene::kObjectReady || scene::isEmpty(box)) continue;
        const scene::Object& object = scene.objects[i];
        if (hidden.allIn(object.uniquePartOffset, scene.geometries[object.geometry].partCount))
            continue;
        const ImU32 colour = partial.state[i] == scene::kObjectLost ? IM_COL32(255, 90, 80, 170)
                                                                    : IM_COL32(200, 205, 215, 110);
        std::array<glm::dvec4, 8> corner;
        for (int c = 0; c < 8; ++c)
            corner[c] = viewProj * glm::dvec4((c & 1) ? box.max.x : box.min.x,
                                              (c & 2) ? box.max.y : box.min.y,
                                              (c & 4) ? box.max.z : box.min.z, 1.0);
        // The twelve edges: corners one bit apart.
        for (int c = 0; c < 8; ++c)
            for (int bit = 1; bit < 8; bit <<= 1)
                if (!(c & bit)) clippedLine(draw, corner[c], corner[c | bit], size, colour);
    }
}

} // namespace app
