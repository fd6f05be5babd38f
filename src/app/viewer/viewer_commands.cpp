// viewer_commands.cpp - what the command table asks of the viewer as a whole: the help, undo
// and redo's event lines, the screenshot key, and each frame's overlays (help, the empty
// view's reason, a notice).
#include <ctime>

#include <imgui.h>

#include "app/viewer/commands/commands.h"
#include "app/viewer/viewer.h"
#include "app/viewer/window/screenshot_path.h"

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
    travel(false);
}

void Viewer::redo() {
    travel(true);
}

// The document comes back to the hidden parts and planes of the step before (or after); the
// selection loses what they hide.
void Viewer::travel(bool forward) {
    const char* what = forward ? "redo" : "undo";
    const scene::PartSet before = document_.selection().selected();
    const auto state = forward ? document_.redo() : document_.undo();
    if (!state) {
        events_.say(what, [](util::JsonWriter& j) { j.member("done", false); });
        return;
    }
    if (document_.selection().selected() != before) selectionChanged();
    partsChanged();
    events_.say(what, [&](util::JsonWriter& j) { shownMembers(j.member("done", true), *state); });
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

// A new model starts clean: its selection, hidden parts, measurements, section planes and
// undo history (Document::newScene) belong to the model they were made on. New copies keep the
// section: its planes are in world space and cut the copies as they cut the model; hidden parts and
// measurements go (copies renumber the parts they name), and with them the history.
void Viewer::startClean(SceneState::Change change) {
    const bool newModel = change == SceneState::Change::Model;
    scene::Section section = document_.section();
    if (newModel && !shell_.firstModel && section.any()) {
        section = {};
        events_.say("section", [](util::JsonWriter& j) { j.member("on", false); });
    }
    if (newModel) shell_.firstModel = false; // the command line's --section is for its model
    document_.newScene(scene_.scene().uniquePartCount(), section);
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

// After the panel, inside the ImGui frame.
void Viewer::drawOverlays() {
    const Selection& selection = document_.selection();
    const scene::Section& section = document_.section();
    if (document_.shownVersion() != shell_.shownVersion) {
        shell_.shownVersion = document_.shownVersion();
        shell_.changedAt = frameNumber_;
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
    if (!settings_.render.pipeline.technique->isFloor() && picking_.partSetsFrame() > 0 &&
        picking_.partSetsFrame() >= shell_.changedAt) {
        visible = picking_.visibleParts();
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
