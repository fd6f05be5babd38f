// panel_commands.h - the panel's buttons and checkboxes for commands (commands.h): labelled
// with the keys of their command as the help names them, greyed when the command cannot do
// anything now, and asking for the same Command a key or a script line gives.
#pragma once

#include "app/viewer/panel/panel.h"

namespace app {

// A checkbox for the switch command `id`, showing `on`: a click asks for it on or off. With
// `sameLine`, on the row before it when it fits.
void switchCheckbox(const char* label, CommandId id, bool on, PanelActions& actions,
                    bool sameLine = false);

// A button for the command `id` (no argument); with `sameLine` as above.
void commandButton(const char* label, CommandId id, const PanelInfo& info, PanelActions& actions,
                   bool sameLine = false);

} // namespace app
