// commands.h - every user action of the viewer as one row of one table: a name, its key
// chords (or the mouse gesture it is), a line for people and what it does. Keys, the
// script's `key` and the help overlay (F1, ?) all read this table, so the help cannot list a
// key the input code does not dispatch, nor miss one it does (Mayo's Command, without Qt).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace app {

class Viewer;
class Input;

// A key with the modifiers held (GLFW key code and GLFW_MOD_* bits of Shift, Ctrl, Alt).
struct Chord {
    int key = 0;
    int mods = 0;
    bool operator==(const Chord&) const = default;
};

struct Command {
    const char* name;             // "hide", "view-front": a stable name for people and tests
    std::vector<Chord> keys;      // empty for a mouse gesture
    const char* mouse;            // the gesture ("Left drag"), nullptr for a key command
    const char* description;      // one line, as the help overlay shows it
    void (*run)(Viewer&, Input&); // nullptr for a mouse gesture: input.cpp's handlers do it
};

// The table, in the order the help lists it.
const std::vector<Command>& commands();

// The row of this name (panel buttons run their key's row), or nullptr.
const Command* findCommand(std::string_view name);

// The key command a key press runs (only Shift, Ctrl and Alt count; Caps Lock, Num Lock and
// Super do not), or nullptr.
const Command* commandOfKey(int key, int mods);

// "Ctrl+Shift+Z", "F1", "Num 7", "?" (Shift+/ on the keyboards GLFW names keys after).
std::string chordText(const Chord& chord);

// One line of the help overlay: the keys (or the gesture) and what they do.
struct HelpLine {
    std::string keys, description;
};
std::vector<HelpLine> helpLines();

// Esc: cancels the first thing in progress of the help overlay, a box drag, measure mode and
// the selection (typing in a panel field never gets here: ImGui takes the Esc and leaves the
// field). Says what it cancelled; nullopt when there was nothing, and nothing happens then.
std::optional<std::string> cancelOne(Viewer& viewer, Input& input);

} // namespace app
