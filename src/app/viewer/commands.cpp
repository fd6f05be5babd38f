// commands.cpp - the viewer's command table and what reads it: the key dispatch, the help
// overlay's lines and Esc's order of cancelling.
#include "app/viewer/commands.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/viewer/viewer.h"

namespace app {
namespace {

constexpr int shift = GLFW_MOD_SHIFT, ctrl = GLFW_MOD_CONTROL;

// The number row's key and the keypad's, so both keyboards' habits work.
std::vector<Chord> digit(int n, int mods = 0) {
    return {{GLFW_KEY_0 + n, mods}, {GLFW_KEY_KP_0 + n, mods}};
}
std::vector<Chord> join(std::vector<Chord> a, const std::vector<Chord>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

void hide(Viewer& viewer, Input& input) {
    input.selection().hideSelected();
    viewer.selectionChanged(); // hidden parts are not selected
    viewer.partsChanged();
}

void isolate(Viewer& viewer, Input& input) {
    input.selection().isolateSelected();
    viewer.partsChanged();
}

void showAll(Viewer& viewer, Input& input) {
    input.selection().showAll();
    viewer.partsChanged();
}

void cancel(Viewer& viewer, Input& input) {
    if (const auto what = cancelOne(viewer, input)) viewer.say("cancel: " + *what);
}

std::vector<Command> table() {
    // The views follow the numpad habit Blender made common (1 front, 3 right, 7 top, with
    // Ctrl the opposite side, 0 isometric) and FreeCAD's own 2 top, 4 back, 5 bottom, 6 left.
    return {
        {"help",
         {{GLFW_KEY_F1, 0}, {GLFW_KEY_SLASH, shift}},
         nullptr,
         "show or hide this list of keys and mouse actions",
         [](Viewer& v, Input&) { v.toggleHelp(); }},
        {"cancel",
         {{GLFW_KEY_ESCAPE, 0}},
         nullptr,
         "cancel: the help, a box drag, measure mode, then the selection and things A and B "
         "(never quits)",
         cancel},
        {"quit",
         {{GLFW_KEY_Q, ctrl}},
         nullptr,
         "quit idview (or close the window)",
         [](Viewer& v, Input&) { v.quit(); }},
        {"open",
         {{GLFW_KEY_O, ctrl}},
         nullptr,
         "Open...: choose a model file in the desktop's file chooser",
         [](Viewer& v, Input&) { v.chooseFile(); }},
        {"type-path",
         {{GLFW_KEY_L, ctrl}},
         nullptr,
         "type a model's path in the panel's open field",
         [](Viewer& v, Input&) { v.focusOpenField(); }},
        {"screenshot",
         {{GLFW_KEY_F12, 0}},
         nullptr,
         "save a PNG of the window in the Pictures folder (idview-DATE-TIME.png)",
         [](Viewer& v, Input&) { v.screenshotToPictures(); }},
        {"toggle-panel",
         {{GLFW_KEY_F9, 0}},
         nullptr,
         "show or hide the panel",
         [](Viewer& v, Input&) {
             v.view().panelVisible = !v.view().panelVisible;
             v.say(v.view().panelVisible ? "panel: shown" : "panel: hidden");
         }},
        {"fit",
         {{GLFW_KEY_F, 0}},
         nullptr,
         "fit the selection, else the shown parts, in view",
         [](Viewer& v, Input&) { v.fitView(); }},
        {"reset-view",
         {{GLFW_KEY_HOME, 0}},
         nullptr,
         "back to the model's opening view",
         [](Viewer& v, Input&) { v.camera().resetView(); }},
        {"projection",
         {{GLFW_KEY_O, 0}},
         nullptr,
         "switch orthographic / perspective",
         [](Viewer& v, Input&) { v.setOrtho(!v.settings().camera.ortho); }},
        {"view-front", digit(1), nullptr, "front view",
         [](Viewer& v, Input&) { v.turnTo(*scene::findStandardView("front")); }},
        {"view-back", join(digit(1, ctrl), digit(4)), nullptr, "back view",
         [](Viewer& v, Input&) { v.turnTo(*scene::findStandardView("back")); }},
        {"view-right", digit(3), nullptr, "right view",
         [](Viewer& v, Input&) { v.turnTo(*scene::findStandardView("right")); }},
        {"view-left", join(digit(3, ctrl), digit(6)), nullptr, "left view",
         [](Viewer& v, Input&) { v.turnTo(*scene::findStandardView("left")); }},
        {"view-top", join(digit(7), digit(2)), nullptr, "top view",
         [](Viewer& v, Input&) { v.turnTo(*scene::findStandardView("top")); }},
        {"view-bottom", join(digit(7, ctrl), digit(5)), nullptr, "bottom view",
         [](Viewer& v, Input&) { v.turnTo(*scene::findStandardView("bottom")); }},
        {"view-isometric", digit(0), nullptr, "isometric view",
         [](Viewer& v, Input&) { v.turnTo(*scene::findStandardView("isometric")); }},
        {"hide", {{GLFW_KEY_H, 0}}, nullptr, "hide the selected parts", hide},
        {"show-all", {{GLFW_KEY_H, shift}}, nullptr, "show every hidden part", showAll},
        {"isolate", {{GLFW_KEY_I, 0}}, nullptr, "show only the selected parts", isolate},
        {"undo",
         {{GLFW_KEY_Z, ctrl}},
         nullptr,
         "undo a hide, show or section change",
         [](Viewer& v, Input&) { v.undo(); }},
        {"redo",
         {{GLFW_KEY_Z, ctrl | shift}, {GLFW_KEY_Y, ctrl}},
         nullptr,
         "redo what undo took back",
         [](Viewer& v, Input&) { v.redo(); }},
        {"xray",
         {{GLFW_KEY_X, 0}},
         nullptr,
         "X-ray: the parts outside the selection translucent, not picked (nothing selected: "
         "no change)",
         [](Viewer& v, Input&) { v.setXray(!v.settings().xray); }},
        {"measure",
         {{GLFW_KEY_M, 0}},
         nullptr,
         "measure mode: clicks place points (distance, angle) instead of selecting",
         [](Viewer& v, Input&) { v.toggleMeasure(); }},
        {"edges",
         {{GLFW_KEY_E, 0}},
         nullptr,
         "edges on or off",
         [](Viewer& v, Input&) { v.settings().render.edges.on = !v.settings().render.edges.on; }},
        {"vsync",
         {{GLFW_KEY_V, 0}},
         nullptr,
         "vsync on or off (off: frames as fast as they go)",
         [](Viewer& v, Input&) { v.view().vsync = !v.view().vsync; }},
        {"reload-shaders",
         {{GLFW_KEY_R, 0}},
         nullptr,
         "reload the shaders from their folder",
         [](Viewer& v, Input&) { v.reloadShaders(); }},
        // The mouse: handled by Input::onButton, onCursor and onScroll; listed for the help.
        {"orbit", {}, "Left drag", "orbit around the target", nullptr},
        {"pan", {}, "Right or middle drag", "pan", nullptr},
        {"zoom", {}, "Wheel", "zoom toward the point under the cursor", nullptr},
        {"select",
         {},
         "Left click",
         "select the part under the cursor (empty space: none)",
         nullptr},
        {"select-solid", {}, "Double-click", "select the solid (object) under the cursor", nullptr},
        {"inspect-b",
         {},
         "Ctrl+click",
         "add a second thing (B) to the clicked one (A): the Inspect panel gives their distance",
         nullptr},
        {"box-select",
         {},
         "Shift / Ctrl / Alt + left drag",
         "box selection: replace / add to / remove from the selection",
         nullptr},
        {"drop-file",
         {},
         "Drop a file",
         "open it (.gltf .glb .step .stp .iges .igs .brep)",
         nullptr},
    };
}

const char* keyName(int key) {
    static const std::pair<int, const char*> names[] = {
        {GLFW_KEY_ESCAPE, "Esc"}, {GLFW_KEY_HOME, "Home"},   {GLFW_KEY_SLASH, "/"},
        {GLFW_KEY_TAB, "Tab"},    {GLFW_KEY_SPACE, "Space"}, {GLFW_KEY_ENTER, "Enter"}};
    for (const auto& [code, name] : names)
        if (code == key) return name;
    return nullptr;
}

} // namespace

const std::vector<Command>& commands() {
    static const std::vector<Command> rows = table();
    return rows;
}

const Command* findCommand(std::string_view name) {
    for (const Command& command : commands())
        if (name == command.name) return &command;
    return nullptr;
}

const Command* commandOfKey(int key, int mods) {
    const Chord pressed{key, mods & (GLFW_MOD_SHIFT | GLFW_MOD_CONTROL | GLFW_MOD_ALT)};
    for (const Command& command : commands())
        for (const Chord& chord : command.keys)
            if (chord == pressed) return &command;
    return nullptr;
}

std::string chordText(const Chord& chord) {
    if (chord.key == GLFW_KEY_SLASH && chord.mods == GLFW_MOD_SHIFT) return "?";
    std::string text;
    if (chord.mods & GLFW_MOD_CONTROL) text += "Ctrl+";
    if (chord.mods & GLFW_MOD_SHIFT) text += "Shift+";
    if (chord.mods & GLFW_MOD_ALT) text += "Alt+";
    const int key = chord.key;
    if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) return text + char('A' + key - GLFW_KEY_A);
    if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) return text + char('0' + key - GLFW_KEY_0);
    if (key >= GLFW_KEY_KP_0 && key <= GLFW_KEY_KP_9)
        return text + "Num " + char('0' + key - GLFW_KEY_KP_0);
    if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F25)
        return text + "F" + std::to_string(key - GLFW_KEY_F1 + 1);
    if (const char* name = keyName(key)) return text + name;
    return text + "key " + std::to_string(key);
}

std::vector<HelpLine> helpLines() {
    std::vector<HelpLine> lines;
    for (const Command& command : commands()) {
        HelpLine line{command.mouse ? command.mouse : "", command.description};
        for (const Chord& chord : command.keys)
            line.keys += (line.keys.empty() ? "" : ", ") + chordText(chord);
        lines.push_back(std::move(line));
    }
    return lines;
}

std::optional<std::string> cancelOne(Viewer& viewer, Input& input) {
    if (viewer.helpOpen()) {
        viewer.toggleHelp();
        return "help";
    }
    if (input.cancelBox()) return "box";
    if (viewer.measuring()) {
        viewer.toggleMeasure();
        return "measure";
    }
    // The selection and things A and B (things.h) go together: A's and B's parts are selected.
    const bool hadThings = input.things().forget();
    if (input.selection().escape() || hadThings) {
        viewer.selectionChanged();
        return "selection";
    }
    return std::nullopt;
}

} // namespace app
