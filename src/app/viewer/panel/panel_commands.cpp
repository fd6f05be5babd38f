// panel_commands.cpp - the panel's widgets for commands (panel_commands.h).
#include "app/viewer/panel/panel_commands.h"

#include <string>

#include <imgui.h>

#include "app/viewer/commands/commands.h"
#include "app/viewer/panel/panel_widgets.h"

namespace app {

void switchCheckbox(const char* label, CommandId id, bool on, PanelActions& actions,
                    bool sameLine) {
    const std::string text = withKeys(label, id);
    if (sameLine) sameLineIfFits(checkboxWidth(text.c_str()));
    if (ImGui::Checkbox(text.c_str(), &on)) actions.ask({id, on ? Switch::On : Switch::Off});
}

void commandButton(const char* label, CommandId id, const PanelInfo& info, PanelActions& actions,
                   bool sameLine) {
    const std::string text = withKeys(label, id);
    if (sameLine)
        sameLineIfFits(ImGui::CalcTextSize(text.c_str()).x +
                       2.0f * ImGui::GetStyle().FramePadding.x);
    ImGui::BeginDisabled(!info.can(id));
    if (ImGui::Button(text.c_str())) actions.ask({id});
    ImGui::EndDisabled();
}

} // namespace app
