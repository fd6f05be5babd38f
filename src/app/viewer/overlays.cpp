// overlays.cpp - the help overlay, the empty view's explanation and the notice, drawn with
// ImGui over the view.
#include "app/viewer/overlays.h"

#include <algorithm>

#include <imgui.h>

#include "app/viewer/commands.h"

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

} // namespace app
