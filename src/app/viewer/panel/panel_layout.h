// panel_layout.h - keeps the panel's rows where the pointer is, and checks that nothing in it
// is clipped. The panel marks the start of each group of rows; while the pointer is over the
// panel, the mark above it is its anchor, and when the anchor's place in the panel moves
// (a section opened or closed above it, rows that came or went), the panel scrolls by as
// much, with blank room above or below where scrolling alone cannot, so the row under the
// pointer stays put. The room goes once the pointer leaves the panel. Each mark also checks
// whether the rows since the one before reached past the panel's right edge.
#pragma once

#include <string>
#include <vector>

#include "app/viewer/state/events.h"
#include "app/viewer/state/view_settings.h"

namespace app {

class PanelLayout {
  public:
    // Call right after ImGui::Begin of the panel; draws the blank room above.
    explicit PanelLayout(PanelLayoutState& state);
    // The start of a group of rows named `name` (unique in the panel).
    void mark(const char* name);
    // Call just before ImGui::End: the room below, the anchor for the next frame, and three
    // event lines, each when it changes: "panel: width W, clipped: none" (or the groups
    // clipped, "clipped: Rendering, Controls"); "panel: rows status 27, open 49, ..." (where
    // each group starts, window y); "panel: pointer row Timing at 612" (the anchor's group
    // and where it was drawn in this frame).
    void finish(const Events* events);
    // What a child window (the tree, the details boxes) reached past its own right edge: call
    // just before its EndChild; counted under the current group.
    void checkChild();

  private:
    void checkOverflow();
    struct Mark {
        std::string name;
        float y;
    };
    PanelLayoutState& state_;
    std::vector<Mark> marks_;
    std::vector<std::string> clipped_;
    bool hovered_ = false;
    void tell(const Events* events);
    float scroll_ = 0.0f, roomAbove_ = 0.0f; // as the frame started
    float shift_ = 0.0f;                     // how far the anchor moved since the last frame
};

} // namespace app
