// selection.h - what the user picked and hid, independent of any technique or mode so that
// switching renderers keeps it: the hovered part (from each frame's pick), the selected
// parts (a click, a box, the object list) and the hidden ones (H, I, Shift+H). Sets of
// unique part IDs over the current scene; a new scene empties them.
#pragma once

#include <cstdint>
#include <optional>

#include "scene/inspect.h" // EdgeRef
#include "scene/part_set.h"

namespace app {

// How a box or a list choice combines with the selection: Shift replaces, Ctrl adds, Alt
// removes.
enum class SelectMode { Replace, Add, Remove };

class Selection {
  public:
    // A new scene of `partCount` parts: nothing hovered, selected or hidden.
    void reset(uint32_t partCount) {
        hovered_.reset();
        primary_.reset();
        hoveredEdge_.reset();
        selectedEdge_.reset();
        selected_ = hidden_ = scene::PartSet(partCount);
    }

    // The part under the cursor from the newest completed pick; nullopt over background.
    void hover(std::optional<uint32_t> part) { hovered_ = part; }
    // The B-rep edge of the hovered part's face near the cursor (app/viewer/panel/edge_hover.h).
    void hoverEdge(std::optional<scene::EdgeRef> edge) { hoveredEdge_ = edge; }
    // A click selects the hovered part alone, and the hovered edge if one is (a click away
    // from every edge leaves none selected); a click on empty space clears the selection.
    void click() {
        selected_.clear();
        if (hovered_) selected_.insert(*hovered_);
        primary_ = hovered_;
        selectedEdge_ = hoveredEdge_;
    }
    // A click at a coarser level (solid, assembly): `parts` around the hovered part become
    // the selection, the hovered part its primary one (the panel details the face).
    void clickAround(const scene::PartSet& parts) {
        selected_ = parts;
        primary_ = hovered_;
        selectedEdge_.reset(); // a solid or an assembly, not an edge
    }
    // A box or the object list: `parts` replace, join or leave the selection.
    void select(const scene::PartSet& parts, SelectMode mode) {
        if (mode == SelectMode::Replace) selected_.clear();
        if (mode == SelectMode::Remove)
            selected_.eraseAll(parts);
        else
            selected_.insertAll(parts);
        primary_.reset();
        if (selected_.size() == 1) primary_ = selected_.ids().front();
        selectedEdge_.reset();
    }
    // Esc clears the selection (after what else it cancels, commands.h). Returns false when
    // nothing was selected.
    bool escape() {
        const bool had = !selected_.empty() || selectedEdge_;
        selected_.clear();
        primary_.reset();
        selectedEdge_.reset();
        return had;
    }

    // H: the selected parts are hidden, and so no longer selected.
    void hideSelected() {
        hidden_.insertAll(selected_);
        selected_.clear();
        primary_.reset();
        selectedEdge_.reset();
    }
    // I: everything but the selection is hidden (the selection stays).
    void isolateSelected() {
        if (selected_.empty()) return; // isolating nothing would leave an empty screen
        hidden_ = selected_;
        hidden_.invert();
    }
    // Shift+H.
    void showAll() { hidden_.clear(); }
    // A tree row's checkbox: its parts hidden (and so no longer selected), or shown again.
    void hide(const scene::PartSet& parts) {
        hidden_.insertAll(parts);
        selected_.eraseAll(parts);
        if (primary_ && !selected_.contains(*primary_)) primary_.reset();
        if (selectedEdge_ && parts.contains(selectedEdge_->part)) selectedEdge_.reset();
    }
    void show(const scene::PartSet& parts) { hidden_.eraseAll(parts); }

    std::optional<uint32_t> hovered() const { return hovered_; }
    // The part the panel details: the one clicked, or the only one selected.
    std::optional<uint32_t> primary() const { return primary_; }
    std::optional<scene::EdgeRef> hoveredEdge() const { return hoveredEdge_; }
    std::optional<scene::EdgeRef> selectedEdge() const { return selectedEdge_; }
    const scene::PartSet& selected() const { return selected_; }
    const scene::PartSet& hidden() const { return hidden_; }

  private:
    std::optional<uint32_t> hovered_, primary_;
    std::optional<scene::EdgeRef> hoveredEdge_, selectedEdge_;
    scene::PartSet selected_, hidden_;
};

} // namespace app
