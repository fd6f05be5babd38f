// test_document.cpp - the one owner of what the person has done (app/viewer/state/document.h):
// every change undo covers records its own step as it is made (a held slider one step when
// it lets go), undo and redo give back exactly the hidden parts and planes of each step, a
// new scene forgets everything, and the versions the renderer follows move on each change
// of what it draws and on nothing else.
#include <gtest/gtest.h>

#include "app/viewer/state/document.h"

namespace {

constexpr uint32_t partCount = 64;

scene::PartSet parts(std::initializer_list<uint32_t> ids) {
    scene::PartSet set(partCount);
    for (uint32_t id : ids) set.insert(id);
    return set;
}

scene::Section plane(float offset) {
    scene::Section section;
    section.add(scene::axisPlane(1, offset));
    return section;
}

// A click on `part` at the face level: the part alone becomes thing A and the selection.
app::ClickedThing faceClick(uint32_t part) {
    return {scene::Thing{{part}, std::nullopt, "part " + std::to_string(part)}, parts({part}),
            false, true};
}

app::Document started() {
    app::Document d;
    d.newScene(partCount, {});
    return d;
}

TEST(Document, EachHideIsItsOwnStepAndUndoRestoresExactly) {
    app::Document d = started();
    d.select(parts({1, 2, 3}), app::SelectMode::Replace);
    d.hideSelected();
    EXPECT_TRUE(d.selection().selected().empty()); // hidden parts leave the selection
    d.select(parts({7}), app::SelectMode::Replace);
    d.isolateSelected();
    const std::vector<app::ShownState> steps = d.takeSteps();
    ASSERT_EQ(steps.size(), 2u);
    EXPECT_EQ(steps[0].hidden, parts({1, 2, 3}));
    scene::PartSet allBut7 = parts({7});
    allBut7.invert();
    EXPECT_EQ(steps[1].hidden, allBut7);
    EXPECT_TRUE(d.takeSteps().empty()); // told once
    EXPECT_EQ(d.history().undoSteps(), 2u);

    EXPECT_EQ(d.undo()->hidden, parts({1, 2, 3}));
    EXPECT_EQ(d.selection().hidden(), parts({1, 2, 3}));
    EXPECT_EQ(d.undo()->hidden, parts({}));
    EXPECT_FALSE(d.undo());
    EXPECT_EQ(d.redo()->hidden, parts({1, 2, 3}));
    EXPECT_EQ(d.redo()->hidden, allBut7);
    EXPECT_FALSE(d.redo());
    EXPECT_TRUE(d.takeSteps().empty()); // undo and redo are no new steps
}

TEST(Document, AChangeToNothingNewIsNoStep) {
    app::Document d = started();
    d.showAll(); // nothing hidden
    d.hide(parts({}));
    d.isolateSelected(); // nothing selected: nothing isolated
    EXPECT_TRUE(d.takeSteps().empty());
    EXPECT_EQ(d.history().undoSteps(), 0u);
}

TEST(Document, AHeldSliderIsOneStepWhenItLetsGo) {
    app::Document d = started();
    for (float offset : {0.1f, 0.2f, 0.3f}) d.setSection(plane(offset), true);
    EXPECT_TRUE(d.takeSteps().empty());  // nothing while the slider is held
    EXPECT_EQ(d.section(), plane(0.3f)); // yet drawn as it moves
    d.settle();
    ASSERT_EQ(d.takeSteps().size(), 1u);
    d.settle(); // nothing held: nothing more
    EXPECT_TRUE(d.takeSteps().empty());
    EXPECT_EQ(d.undo()->section, scene::Section{});
    EXPECT_EQ(d.section(), scene::Section{});
    EXPECT_EQ(d.redo()->section, plane(0.3f));

    d.setSection(plane(0.5f), false); // a script's or a button's plane: a step at once
    EXPECT_EQ(d.takeSteps().size(), 1u);
    d.setSection(plane(0.5f), false); // the same again: none
    EXPECT_TRUE(d.takeSteps().empty());
}

TEST(Document, UndoWhileHeldSettlesFirst) {
    app::Document d = started();
    d.setSection(plane(0.2f), true);
    EXPECT_EQ(d.undo()->section, scene::Section{}); // the held change became its step
    EXPECT_EQ(d.redo()->section, plane(0.2f));
}

TEST(Document, ANewStepForgetsRedo) {
    app::Document d = started();
    d.hide(parts({4}));
    d.undo();
    EXPECT_EQ(d.history().redoSteps(), 1u);
    d.hide(parts({5}));
    EXPECT_EQ(d.history().redoSteps(), 0u);
    EXPECT_FALSE(d.redo());
}

TEST(Document, ClicksMakeThingsAAndBAndEscapeForgetsBoth) {
    app::Document d = started();
    d.hover(9);
    d.click(faceClick(9));
    EXPECT_EQ(d.selection().selected(), parts({9}));
    EXPECT_EQ(d.selection().primary(), 9u);
    ASSERT_TRUE(d.things().a());
    EXPECT_EQ(d.things().a()->parts, std::vector<uint32_t>{9});
    d.hover(12);
    app::ClickedThing ctrl = faceClick(12);
    ctrl.add = true;
    d.click(ctrl);
    ASSERT_TRUE(d.things().b());
    EXPECT_EQ(d.selection().selected(), parts({9, 12})); // A's and B's parts
    app::ClickedThing empty{std::nullopt, parts({}), true, true};
    d.click(empty); // a Ctrl+click on empty space adds nothing
    EXPECT_EQ(d.things().b()->parts, std::vector<uint32_t>{12});
    EXPECT_TRUE(d.escape());
    EXPECT_FALSE(d.things().a());
    EXPECT_TRUE(d.selection().selected().empty());
    EXPECT_FALSE(d.escape());           // nothing left
    EXPECT_TRUE(d.takeSteps().empty()); // selections are no undo steps
}

TEST(Document, VersionsMoveOnWhatTheRendererDraws) {
    app::Document d = started();
    const uint64_t v0 = d.version(), s0 = d.selectionVersion(), h0 = d.shownVersion();
    d.hover(3); // the GPU's own highlight: nothing to hand over
    d.setExplode(0.5f);
    d.toggleMeasure();
    EXPECT_EQ(d.version(), v0);
    d.select(parts({3}), app::SelectMode::Replace);
    EXPECT_GT(d.selectionVersion(), s0);
    EXPECT_EQ(d.shownVersion(), h0); // the hidden parts and planes did not change
    const uint64_t v1 = d.version(), s1 = d.selectionVersion();
    d.setXray(true);
    EXPECT_GT(d.version(), v1);
    EXPECT_EQ(d.selectionVersion(), s1);
    d.setSection(plane(1.0f), false);
    EXPECT_GT(d.shownVersion(), h0);
    EXPECT_EQ(d.selectionVersion(), s1);
}

TEST(Document, ANewSceneForgetsEverythingButThePlanesItIsGiven) {
    app::Document d = started();
    d.select(parts({1}), app::SelectMode::Replace);
    d.click(faceClick(1));
    d.hide(parts({2}));
    d.toggleMeasure();
    d.addMeasurePoint({glm::dvec3(1.0), 1});
    d.newScene(8, plane(2.0f));
    EXPECT_EQ(d.selection().selected().partCount(), 8u);
    EXPECT_TRUE(d.selection().selected().empty());
    EXPECT_TRUE(d.selection().hidden().empty());
    EXPECT_FALSE(d.things().a());
    EXPECT_TRUE(d.measure().points().empty());
    EXPECT_EQ(d.section(), plane(2.0f));
    EXPECT_FALSE(d.undo()); // the history starts again
    EXPECT_TRUE(d.takeSteps().empty());
}

TEST(Document, BringBackIsNoStep) {
    app::Document d = started();
    app::Selection kept;
    kept.reset(partCount);
    kept.hide(parts({5, 6}));
    d.bringBack(kept, plane(0.7f));
    EXPECT_EQ(d.selection().hidden(), parts({5, 6}));
    EXPECT_EQ(d.section(), plane(0.7f));
    EXPECT_FALSE(d.undo());
    EXPECT_TRUE(d.takeSteps().empty());
}

} // namespace
