// history.h - undo and redo of what the viewer shows of a model: its hidden parts and its
// section planes. A step is a snapshot of both taken when they settle (a slider's drag is
// one step, not one per frame); a new model or copy count starts an empty history, since
// part IDs then name other parts. Plain C++, unit-tested.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scene/part_set.h"
#include "scene/section.h"
#include "util/json_writer.h"

namespace app {

struct ShownState {
    scene::PartSet hidden;
    scene::Section section;
    bool operator==(const ShownState&) const = default;
};

// "hidden":3,"hidden_hash":"8a4f0c21e3d56b70","section":false: what the event records say of
// a state; the hash names the exact set of hidden parts, so tests compare sets without
// listing them.
void shownMembers(util::JsonWriter& json, const ShownState& state);

class History {
  public:
    // A new scene: no steps; `now` is the state undo comes back to.
    void reset(const ShownState& now);
    // The state as it stands. When it differs from the last one seen and `settled` (no
    // widget is being dragged), the last one becomes an undo step and redo is forgotten.
    // True when a step was taken.
    bool observe(const ShownState& now, bool settled);
    // The state before the newest step (the current one goes to redo), or nullopt.
    std::optional<ShownState> undo();
    std::optional<ShownState> redo();
    size_t undoSteps() const { return undo_.size(); }
    size_t redoSteps() const { return redo_.size(); }

    // Steps kept: a hidden set is a bit per part, so even a million-part model keeps a
    // hundred steps in about 12 MB.
    static constexpr size_t limit = 100;

  private:
    std::optional<ShownState> step(std::vector<ShownState>& from, std::vector<ShownState>& to);

    std::vector<ShownState> undo_, redo_;
    ShownState current_;
};

} // namespace app
