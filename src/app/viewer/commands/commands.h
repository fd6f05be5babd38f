// commands.h - the viewer's command table: every action a user can ask for is one row with a
// name (the script's word for it), the argument it takes, its key chords, a line for people
// and what it does. Keys, the panel's buttons and widgets and the script's lines all make a
// Command (command.h) of a row, and execute() runs it: the help overlay (F1, ?) lists the
// table, so it cannot miss a key the input code dispatches (Mayo's Command, without Qt).
//
// The panel's tuning widgets that no key or script word asks for (sliders, colours, the
// section planes' slots) edit the settings in place, as the panel's settings do: they are
// settings, not actions.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "app/viewer/commands/command.h"

namespace scene {
struct TreeRow;
}

namespace app {

class CommandTarget; // command_target.h

// A key with the modifiers held (GLFW key code and GLFW_MOD_* bits of Shift, Ctrl, Alt).
struct Chord {
    int key = 0;
    int mods = 0;
    bool operator==(const Chord&) const = default;
};

// How a command's argument is written after its name in a script (and in the help).
enum class ArgumentKind : uint8_t {
    None,
    Switch,       // on or off; nothing toggles
    OptionalText, // the rest of the line, may be empty (open, screenshot: a file)
    Text,         // the rest of the line (object: a name)
    View,         // a standard view's name
    Technique,    // a renderer's name
    DrawMode,     // a per-draw mode's name
    CullMode,     // off, frustum or occlusion
    ClearPath,    // auto, pass or compute
    Msaa,         // 1, 2, 4 or 8
    Copies,       // 1 to 1000000
    Level,        // face, solid or assembly: 0, 1, 2
    Explode,      // 0 to 1
    Section,      // AXIS,VALUE[,flip] or off
    Node,         // select|add|hide|show, then the path
    Census,       // VIEWSxSIZE, cancel, select, hide, isolate, here or part ID
};

// Keys that ask for a command with one argument: the views' digits each give their view, a
// switch's key toggles.
struct KeyBinding {
    std::vector<Chord> chords;
    Argument argument{};
    const char* description = nullptr; // the help's line for these keys; nullptr: the row's
};

struct CommandDef {
    CommandId id;
    const char* name; // the script's word, and the name in the help and the event lines
    ArgumentKind argument;
    const char* description; // one line, as the help shows it
    std::vector<KeyBinding> keys;
    // Carries the command out; the argument is of the kind above, a switch settled to on
    // or off.
    void (*run)(CommandTarget&, const Argument&);
    // A switch: whether it is on now (what a toggle turns round). Others: nullptr.
    bool (*isOn)(const CommandTarget&) = nullptr;
    // Whether it can do anything now (the panel greys its widget); nullptr: always.
    bool (*enabled)(const CommandTarget&) = nullptr;
};

// The table, in the order the help lists it: one row per CommandId.
const std::vector<CommandDef>& commands();
const CommandDef& definition(CommandId id);
// The row whose script word is `name`, or nullptr.
const CommandDef* findCommand(std::string_view name);

// The command a key press asks for (only Shift, Ctrl and Alt count; Caps Lock, Num Lock and
// Super do not), or nullopt.
std::optional<Command> commandOfKey(int key, int mods);

// A command that names what is not there (a script's tree node); what() says what.
struct CommandError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The one place a command runs, whatever asked for it: a toggle is settled against the
// state, the event line "command: WORDS" is told (--print-events), then the row runs it.
// Throws CommandError.
void execute(Command command, CommandTarget& target);
bool enabled(CommandId id, const CommandTarget& target);

// The node of tree row `i` for a node command, as the panel's row asks for it (two objects of
// one path are two rows, told apart by which of them it is), and the row a node names
// (nullopt when no row has its path): rowOfNode(rows, nodeOfRow(rows, i, a)) is i.
NodeTarget nodeOfRow(const std::vector<scene::TreeRow>& rows, size_t i, NodeAction action);
std::optional<size_t> rowOfNode(const std::vector<scene::TreeRow>& rows, const NodeTarget& node);

// The script's words for a command, "view front", "xray on", "hide": a script line of them
// makes the same command again (a node's second row of one path excepted).
std::string commandWords(const Command& command);
// The script's form of a row: "view NAME", "xray [on|off]", "hide".
std::string commandUsage(const CommandDef& def);
// A script line's argument for `def`: `words` are the line after the name split at blanks,
// `rest` the line after the name, trimmed. Throws std::invalid_argument with a message for
// people that names the command.
Argument parseArgument(const CommandDef& def, const std::vector<std::string>& words,
                       const std::string& rest);

// "Ctrl+Shift+Z", "F1", "Num 7", "?" (Shift+/ on the keyboards GLFW names keys after).
std::string chordText(const Chord& chord);
// The keys of a command's first binding, as the help names them ("F1, ?"; "" for none), and
// a panel label with them: "hide (H)".
std::string keysOf(CommandId id);
std::string withKeys(const char* label, CommandId id);

// One line of the help overlay: the keys (or the mouse gesture), what they do and the
// script's words for it.
struct HelpLine {
    std::string keys, description, script;
};
std::vector<HelpLine> helpLines();
// Key chords and mouse gestures the help lists ("help: N bindings").
size_t bindingCount();

// Esc: cancels the first thing in progress of the help overlay, a box drag, a model loading
// (Cancel where a model was shown before it, else Stop), a census running, measure mode and the
// selection (typing in
// a panel field never gets here: ImGui takes the Esc and leaves the field). Says what it cancelled;
// nullopt when there was nothing, and nothing happens then.
std::optional<std::string> cancelOne(CommandTarget& target);

} // namespace app
