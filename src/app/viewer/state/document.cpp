// document.cpp - the changes of what the person has done, each with its undo step.
#include "app/viewer/state/document.h"

#include <utility>

namespace app {

void Document::newScene(uint32_t partCount, const scene::Section& section) {
    selection_.reset(partCount);
    things_.forget();
    measure_.forget();
    section_ = section;
    holding_ = false;
    newSteps_.clear();
    history_.reset(shown());
    selectionChanged();
    ++shownVersion_;
}

void Document::bringBack(const Selection& selection, const scene::Section& section) {
    selection_ = selection;
    section_ = section;
    history_.reset(shown());
    selectionChanged();
    ++shownVersion_;
}

void Document::click(ClickedThing clicked) {
    if (clicked.add && !clicked.thing) return; // a Ctrl+click on empty space adds nothing
    const uint32_t partCount = selection_.selected().partCount();
    if (clicked.add)
        things_.add(std::move(*clicked.thing));
    else
        things_.click(std::move(clicked.thing));
    // At the face level the part alone (and its edge, Selection::click); at coarser levels,
    // and with Ctrl, A's and B's parts. The clicked part is the primary one either way.
    if (!clicked.add && clicked.faceLevel)
        selection_.click();
    else
        selection_.clickAround(things_.parts(partCount));
    selectionChanged();
}

void Document::select(const scene::PartSet& parts, SelectMode mode) {
    selection_.select(parts, mode);
    selectionChanged();
}

bool Document::escape() {
    const bool hadThings = things_.forget();
    const bool hadSelection = selection_.escape();
    if (hadThings || hadSelection) selectionChanged();
    return hadThings || hadSelection;
}

void Document::hideSelected() {
    selection_.hideSelected();
    selectionChanged(); // hidden parts leave the selection
    record(false);
}

void Document::isolateSelected() {
    selection_.isolateSelected();
    record(false);
}

void Document::showAll() {
    selection_.showAll();
    record(false);
}

void Document::hide(const scene::PartSet& parts) {
    selection_.hide(parts);
    selectionChanged();
    record(false);
}

void Document::show(const scene::PartSet& parts) {
    selection_.show(parts);
    record(false);
}

void Document::setSection(const scene::Section& section, bool held) {
    if (section == section_) return;
    section_ = section;
    record(held);
}

void Document::settle() {
    if (!holding_) return;
    holding_ = false; // a drag that ends where it began makes no step
    if (history_.observe(shown(), true)) newSteps_.push_back(shown());
}

void Document::setXray(bool on) {
    xray_ = on;
    ++version_;
}

// History::observe takes a step only when the state differs from the last step's, so a hide
// of nothing new or a plane set to where it was makes none.
void Document::record(bool held) {
    ++version_;
    ++shownVersion_;
    holding_ = held;
    if (!held && history_.observe(shown(), true)) newSteps_.push_back(shown());
}

std::optional<ShownState> Document::undo() {
    settle(); // a held change first becomes its own step
    const auto state = history_.undo();
    if (state) restore(*state);
    return state;
}

std::optional<ShownState> Document::redo() {
    settle();
    const auto state = history_.redo();
    if (state) restore(*state);
    return state;
}

void Document::restore(const ShownState& state) {
    selection_.showAll();
    selection_.hide(state.hidden); // hidden parts leave the selection
    section_ = state.section;
    selectionChanged();
    ++shownVersion_;
}

} // namespace app
