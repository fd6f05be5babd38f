// selection.h - hover and click selection of parts, independent of any technique or mode so
// that switching renderers keeps what the user selected. Fed by the pick of each frame.
#pragma once

#include <cstdint>
#include <optional>

namespace app {

class Selection {
  public:
    // The part under the cursor from the newest completed pick; nullopt over background.
    void hover(std::optional<uint32_t> part) { hovered_ = part; }
    // A click selects the hovered part; a click on empty space clears the selection.
    void click() { selected_ = hovered_; }
    // Esc clears the selection. Returns false when nothing was selected, so the caller may
    // give Esc its other meaning (closing the viewer).
    bool escape() {
        const bool had = selected_.has_value();
        selected_.reset();
        return had;
    }
    // A new scene invalidates part IDs.
    void clear() {
        hovered_.reset();
        selected_.reset();
    }

    std::optional<uint32_t> hovered() const { return hovered_; }
    std::optional<uint32_t> selected() const { return selected_; }

  private:
    std::optional<uint32_t> hovered_;
    std::optional<uint32_t> selected_;
};

} // namespace app
