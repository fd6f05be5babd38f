// document.h - what the person has done to the model shown, in one place: the hovered and
// selected parts, the hidden ones, things A and B of the Inspect section, measure mode and its
// points, the section planes, the explode fraction, X-ray and the undo history of the hidden
// parts and planes. Commands change it through its functions alone, and each change that undo
// covers records its own step here; the viewer hands the renderer what it draws from it when
// version() moves. Plain C++ without Vulkan or ImGui, unit-tested (test_document.cpp).
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "app/viewer/state/history.h"
#include "app/viewer/state/measure.h"
#include "app/viewer/state/selection.h"
#include "app/viewer/state/things.h"
#include "scene/section.h"

namespace app {

// What a click asks for once its pick has come: the thing it hit (nullopt: empty space), the
// parts around it at the click's level, and whether it was a Ctrl+click (thing B).
struct ClickedThing {
    std::optional<scene::Thing> thing;
    scene::PartSet around;
    bool add = false;
    bool faceLevel = true; // a plain click at the face level selects the part alone
};

class Document {
  public:
    // A new scene of `partCount` parts: nothing hovered, selected, hidden or measured, things
    // A and B forgotten, and an empty history that comes back to `section` (the caller keeps
    // or clears the planes: copies keep them, a new model does not).
    void newScene(uint32_t partCount, const scene::Section& section);
    // Cancel's model before: its selection and planes as they were, with no undo step.
    void bringBack(const Selection& selection, const scene::Section& section);

    const Selection& selection() const { return selection_; }
    const Things& things() const { return things_; }
    const Measure& measure() const { return measure_; }
    const scene::Section& section() const { return section_; }
    float explode() const { return explode_; }
    bool xray() const { return xray_; }
    ShownState shown() const { return {selection_.hidden(), section_}; }
    const History& history() const { return history_; }
    // Counts the changes of what the renderer draws from here (selection, hidden parts,
    // X-ray, planes); the hover is the GPU's own.
    uint64_t version() const { return version_; }
    // The same for the selected parts alone (the renderer's highlight), and for the hidden
    // parts and planes alone (visible counts of older frames are stale).
    uint64_t selectionVersion() const { return selectionVersion_; }
    uint64_t shownVersion() const { return shownVersion_; }
    // The undo steps recorded since the last call, oldest first (the event lines tell them).
    std::vector<ShownState> takeSteps() { return std::exchange(newSteps_, {}); }

    // The newest pick's part and the B-rep edge near the cursor.
    void hover(std::optional<uint32_t> part) { selection_.hover(part); }
    void hoverEdge(std::optional<scene::EdgeRef> edge) { selection_.hoverEdge(edge); }

    // A click's pick came (measure mode excepted): its thing becomes A (or B), and the
    // selection the hovered part alone or A's and B's parts.
    void click(ClickedThing clicked);
    // A box, the object list or a tree row: `parts` replace, join or leave the selection.
    void select(const scene::PartSet& parts, SelectMode mode);
    // Esc: the selection and things A and B go. False when there were none.
    bool escape();

    // The hidden parts; each change is an undo step.
    void hideSelected();
    void isolateSelected();
    void showAll();
    void hide(const scene::PartSet& parts);
    void show(const scene::PartSet& parts);

    // The planes. A widget held (a slider dragged) makes one undo step when it lets go
    // (settle, each frame no widget is held), not one per frame; a script's or a button's
    // change is a step at once.
    void setSection(const scene::Section& section, bool held);
    void settle(); // no widget is held now

    void setExplode(float fraction) { explode_ = fraction; }
    void setXray(bool on);

    void toggleMeasure() { measure_.toggle(); }
    void addMeasurePoint(const MeasurePoint& point) { measure_.add(point); }
    void forgetMeasurePoints() { measure_.forget(); } // the parts moved (explode)

    // Ctrl+Z and Ctrl+Shift+Z: the hidden parts and planes of the step before or after (the
    // hidden parts leave the selection), or nullopt when there is none.
    std::optional<ShownState> undo();
    std::optional<ShownState> redo();

  private:
    void record(bool held); // after a change of the hidden parts or planes
    void restore(const ShownState& state);

    Selection selection_;
    Things things_;
    Measure measure_;
    scene::Section section_;
    float explode_ = 0.0f;
    bool xray_ = false;
    History history_;
    bool holding_ = false; // a widget holds a change that is no undo step yet
    std::vector<ShownState> newSteps_;
    uint64_t version_ = 0, selectionVersion_ = 0, shownVersion_ = 0;
    void selectionChanged() {
        ++version_;
        ++selectionVersion_;
    }
};

} // namespace app
