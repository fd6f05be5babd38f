// panel_rendering.h - the panel's Rendering and Scene sections.
#pragma once

#include "app/viewer/panel/panel.h"

namespace app {

// The renderer, its mode and settings, culling, levels of detail; Reset to defaults.
void rendering(LiveSettings& settings, const PanelInfo& info, PanelActions& actions);
// Model copies, the parts mode, and what the scene and the renderer hold.
void sceneSection(SceneSettings& s, const PanelInfo& info, PanelActions& actions);

} // namespace app
