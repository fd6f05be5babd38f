// things.h - the two things the Inspect panel compares (scene::Thing, inspect.h): a plain
// click makes thing A (at the select level: a face, a solid, an assembly node), a Ctrl+click
// thing B; a further Ctrl+click replaces B, a plain click starts again. Kept beside
// app::Selection, which holds A's and B's parts; a new scene and Esc forget both.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scene/assembly_tree.h"
#include "scene/inspect.h"
#include "scene/part_set.h"

namespace app {

class Things {
  public:
    // A plain click: `thing` becomes A and B goes; nullopt (a click on empty space) leaves
    // neither.
    void click(std::optional<scene::Thing> thing) {
        a_ = std::move(thing);
        b_.reset();
        ++version_;
    }
    // A Ctrl+click: `thing` becomes B, replacing an earlier B; with no A yet it is A, as a
    // plain click would make it (there is nothing to compare it with).
    void add(scene::Thing thing) {
        if (a_)
            b_ = std::move(thing);
        else
            a_ = std::move(thing);
        ++version_;
    }
    // Esc and a new scene. Returns false when there was nothing to forget.
    bool forget() {
        const bool had = a_ || b_;
        a_.reset();
        b_.reset();
        if (had) ++version_;
        return had;
    }

    const std::optional<scene::Thing>& a() const { return a_; }
    const std::optional<scene::Thing>& b() const { return b_; }
    // A's and B's parts (an edge's: its face), what the selection holds after a click.
    scene::PartSet parts(uint32_t partCount) const;
    // Counts the changes, so what is worked out from A and B is worked out once per change.
    uint64_t version() const { return version_; }

  private:
    std::optional<scene::Thing> a_, b_;
    uint64_t version_ = 0;
};

// The thing a click makes: `parts`, clicked on `part`, named by the assembly node they make
// up (`tree`'s deepest row of exactly these parts, else the clicked part's object path) and,
// for a single part, its CAD face ("board/U3 · face 12") or local part. With `edge` set (the
// edge under the cursor, edge_info.h) the thing is that edge alone ("... · edge 4").
scene::Thing makeThing(const scene::Scene& scene, const std::vector<scene::TreeRow>& tree,
                       const scene::PartSet& parts, uint32_t part,
                       std::optional<scene::EdgeRef> edge = std::nullopt);

// "board/U3 · face 12|board/U4": the event line's form, "none" for a thing not there.
std::string thingsLine(const Things& things);

} // namespace app
