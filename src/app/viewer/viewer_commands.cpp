// viewer_commands.cpp - what the command table asks of the viewer as a whole: the help, undo
// and redo, the screenshot key, and each frame's overlays (help, the empty view's reason, a
// notice) with the watch on hidden parts and section that makes undo steps.
#include <ctime>

#include <imgui.h>

#include "app/viewer/commands.h"
#include "app/viewer/screenshot_path.h"
#include "app/viewer/viewer.h"

namespace app {

void Viewer::toggleHelp() {
    shell_.help = !shell_.help;
    if (!shell_.help) {
        events_.say("help", [](util::JsonWriter& j) { j.member("open", false); });
        return;
    }
    events_.say("help", [&](util::JsonWriter& j) {
        j.member("open", true).member("bindings", bindingCount());
    });
}

void Viewer::undo() {
    if (const auto state = shell_.history.undo())
        restore(*state, "undo");
    else
        events_.say("undo", [](util::JsonWriter& j) { j.member("done", false); });
}

void Viewer::redo() {
    if (const auto state = shell_.history.redo())
        restore(*state, "redo");
    else
        events_.say("redo", [](util::JsonWriter& j) { j.member("done", false); });
}

void Viewer::restore(const ShownState& state, const char* what) {
    Selection& selection = input_.selection();
    const scene::PartSet before = selection.selected();
    selection.showAll();
    selection.hide(state.hidden); // hidden parts leave the selection
    settings_.render.section = state.section;
    shell_.seen = state; // the history holds it already: no new step
    shell_.pending = false;
    shell_.changedAt = frameNumber_;
    if (selection.selected() != before) selectionChanged();
    partsChanged();
    events_.say(what, [&](util::JsonWriter& j) { shownMembers(j.member("done", true), state); });
}

// F12 rather than Ctrl+Shift+S: one key, as in the tools that have a screenshot key (Steam,
// GNOME's Print is the desktop's own), and Ctrl+Shift+S is "save as" nearly everywhere.
void Viewer::screenshotToPictures() {
    const std::string path =
        screenshotPath(picturesFolder(processEnvironment()), std::time(nullptr)).string();
    screenshot(path); // written after the next frame; its event line names the file
    shell_.notice = "Screenshot: " + path;
    shell_.noticeUntil = elapsed() + 4.0;
}

// A new model starts clean: its hidden parts (Input::forgetParts), measurements, section
// planes and undo history belong to the model they were made on. New copies keep the section:
// its planes are in world space and cut the copies as they cut the model; hidden parts and
// measurements go (copies renumber the parts they name), and with them the history.
void Viewer::startClean(SceneState::Change change) {
    const bool newModel = change == SceneState::Change::Model;
    if (newModel && !shell_.firstModel && settings_.render.section.any()) {
        settings_.render.section = {};
        events_.say("section", [](util::JsonWriter& j) { j.member("on", false); });
    }
    if (newModel) shell_.firstModel = false; // the command line's --section is for its model
    shell_.seen = {input_.selection().hidden(), settings_.render.section};
    shell_.history.reset(shell_.seen);
    shell_.pending = false;
    shell_.changedAt = frameNumber_;
}

// Why nothing shows (overlays.h's whyEmpty), or that a model is loading and none of its solids
// is meshed yet, or that nothing is open (the model given at start stopped or cancelled).
std::optional<EmptyReason> Viewer::emptyView(uint32_t partCount, uint32_t hidden, bool sectionOn,
                                             std::optional<uint32_t> visible) const {
    if (partCount > 0) return whyEmpty(partCount, hidden, sectionOn, visible);
    if (const auto loading = scene_.loading())
        return EmptyReason{"loading",
                           "Opening " + loading->path +
                               (scene_.partial() ? ": its solids show as they are meshed" : "")};
    if (scene_.loaded().source.empty())
        return EmptyReason{"nothing open",
                           "Nothing is open - " + keysOf(CommandId::Open) + " opens a model"};
    return whyEmpty(partCount, hidden, sectionOn, visible);
}

// After the panel, inside the ImGui frame. The hidden parts and section are compared with the
// last frame's, not copied, so a frame at rest costs two comparisons; a change becomes an undo
// step once no widget is held (a slider drag is one step).
void Viewer::drawOverlays() {
    const Selection& selection = input_.selection();
    const scene::Section& section = settings_.render.section;
    if (selection.hidden() != shell_.seen.hidden || section != shell_.seen.section) {
        shell_.seen = {selection.hidden(), section};
        shell_.pending = true;
        shell_.changedAt = frameNumber_;
    }
    if (shell_.pending && !ImGui::IsAnyItemActive()) {
        shell_.pending = false; // a drag that ends where it began makes no step
        if (shell_.history.observe(shell_.seen, true))
            events_.say("undo_step", [&](util::JsonWriter& j) { shownMembers(j, shell_.seen); });
    }

    if (shell_.help) {
        drawHelp(shell_.help);
        if (!shell_.help) events_.say("help", [](util::JsonWriter& j) { j.member("open", false); });
    }
    const float width = ImGui::GetIO().DisplaySize.x;
    const FreeSpan span =
        view_.panelVisible ? freeSpan(width, view_.panelLeft, view_.panelRight) : FreeSpan{};
    // The visible count of a frame that shows the current hidden parts and section. Until
    // one comes, planes that cut everything away still do (hiding parts or adding copies
    // uncuts nothing), so the line does not blink off for the frames a new count takes.
    std::optional<uint32_t> visible;
    if (!settings_.render.pipeline.technique->isFloor() && input_.partSetsFrame() > 0 &&
        input_.partSetsFrame() >= shell_.changedAt) {
        visible = input_.visibleParts();
        shell_.countedSection = section;
    } else if (shell_.empty == "section" && section == shell_.countedSection) {
        visible = 0;
    }
    // Empty parts never show, hidden or not: they count neither way.
    const scene::PartSet& neverShown = scene_.emptyParts();
    uint32_t hidden = selection.hidden().size();
    if (!neverShown.empty()) {
        scene::PartSet emptyShown = neverShown;
        emptyShown.eraseAll(selection.hidden());
        hidden -= neverShown.size() - emptyShown.size();
    }
    const auto empty = emptyView(scene_.scene().uniquePartCount() - neverShown.size(), hidden,
                                 section.any(), visible);
    const std::string reason = empty ? empty->event : "";
    // Until the model given at start shows, the view says what opens, without a line.
    if (reason != shell_.empty && !scene_.waitingForFirst()) {
        shell_.empty = reason;
        events_.say("empty", [&](util::JsonWriter& j) {
            j.member("reason", reason.empty() ? std::nullopt : std::optional(reason));
        });
    }
    if (empty) drawCentred(empty->message, span, 0.5f);
    if (!shell_.notice.empty() && elapsed() < shell_.noticeUntil)
        drawCentred(shell_.notice, span, 0.92f);
}

} // namespace app
