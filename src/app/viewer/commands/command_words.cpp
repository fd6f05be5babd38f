// command_words.cpp - commands as people and scripts write them: a row's arguments parsed
// from a script line and written back, key chords named, and the help overlay's lines.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/cli_values.h" // parseCensus: the same VIEWSxSIZE as --census
#include "app/viewer/commands/commands.h"
#include "app/viewer/commands/script.h" // parseNumber
#include "render/culling.h"
#include "render/technique.h"
#include "scene/formats.h"
#include "scene/standard_view.h"

namespace app {
namespace {

using Kind = ArgumentKind;

// What follows the name in the script's form of each kind.
const char* kindUsage(Kind kind) {
    switch (kind) {
    case Kind::None:
        return "";
    case Kind::Switch:
        return "[on|off]";
    case Kind::OptionalText:
        return "[FILE]";
    case Kind::Text:
        return "NAME";
    case Kind::View:
    case Kind::Technique:
    case Kind::DrawMode:
        return "NAME";
    case Kind::CullMode:
        return "off|frustum|occlusion";
    case Kind::ClearPath:
        return "auto|pass|compute";
    case Kind::Msaa:
        return "1|2|4|8";
    case Kind::Copies:
        return "N";
    case Kind::Level:
        return "face|solid|assembly";
    case Kind::Explode:
        return "F (0 to 1)";
    case Kind::Section:
        return "AXIS,VALUE[,flip] | off";
    case Kind::Node:
        return "select|add|hide|show [PATH]";
    case Kind::Census:
        return "VIEWSxSIZE|cancel|select|hide|isolate|here|part ID|tint on|off|export PATH";
    }
    return "";
}

// The words of the kinds that take one of a few.
const char* const switchWords[] = {"on", "off"};
const char* const clearWords[] = {"auto", "pass", "compute"};
const char* const levelNames[] = {"face", "solid", "assembly"};
const char* const nodeActions[] = {"select", "add", "hide", "show"};
// CensusAction's words after Run (which is VIEWSxSIZE).
const char* const censusWords[] = {"cancel", "select", "hide", "isolate",
                                   "here",   "part",   "tint", "export"};

[[noreturn]] void fail(const std::string& message) {
    throw std::invalid_argument(message);
}

double number(const CommandDef& def, const std::string& word) {
    double value = 0.0;
    if (!parseNumber(word, value))
        fail("'" + word + "' is not a number (" + commandUsage(def) + ")");
    return value;
}

// A registry entry by name, or "unknown WHAT 'x' (known: ...)".
template <typename Entry>
Entry found(Entry entry, const char* what, const std::string& word, const std::string& known) {
    if (!entry) fail(std::string("unknown ") + what + " '" + word + "' (known: " + known + ")");
    return entry;
}

std::optional<scene::SectionPlane> sectionPlane(const std::string& word) {
    if (word == "off") return std::nullopt;
    try {
        return scene::parseSectionPlane(word);
    } catch (const std::invalid_argument& e) {
        fail(std::string("'section' ") + e.what() + ", or off");
    }
}

// VIEWSxSIZE (as --census reads it) or one of censusWords.
CensusAsk censusAsk(const CommandDef& def, const std::string& word) {
    if (word.empty() || !std::isdigit(static_cast<unsigned char>(word[0]))) {
        const auto action = CensusAction(1 + oneOfWords(def.name, word, censusWords));
        if (action == CensusAction::Part) fail("'census part' takes a part ID");
        if (action == CensusAction::Tint) fail("'census tint' takes on or off");
        if (action == CensusAction::Export) fail("'census export' takes a path");
        return {action};
    }
    try {
        const scene::CensusSpec spec = parseCensus(word);
        return {CensusAction::Run, spec.views, spec.size};
    } catch (const std::exception& e) {
        fail(std::string("'census' ") + e.what());
    }
}

// The kinds written as one word.
Argument parseWord(const CommandDef& def, const std::string& word) {
    switch (def.argument) {
    case Kind::Switch:
        return oneOfWords(def.name, word, switchWords) == 0 ? Switch::On : Switch::Off;
    case Kind::View:
        return found(scene::findStandardView(word), "view", word, scene::standardViewNames());
    case Kind::Technique:
        return found(render::findTechnique(word), "renderer", word, render::techniqueNames());
    case Kind::DrawMode:
        return found(render::findDrawMode(word), "mode", word, render::drawModeNames());
    case Kind::CullMode:
        return found(render::findCullMode(word), "culling", word, render::cullModeNames())->mode;
    case Kind::ClearPath:
        oneOfWords(def.name, word, clearWords);
        return *render::findClearPath(word);
    case Kind::Level:
        return uint32_t(oneOfWords(def.name, word, levelNames));
    case Kind::Section:
        return sectionPlane(word);
    case Kind::Census:
        return censusAsk(def, word);
    default:
        break;
    }
    const double n = number(def, word);
    if (def.argument == Kind::Msaa && n != 1.0 && n != 2.0 && n != 4.0 && n != 8.0)
        fail("msaa takes 1, 2, 4 or 8");
    if (def.argument == Kind::Copies && (n < 1.0 || n > 1e6 || n != std::floor(n)))
        fail("copies takes a whole number from 1 to 1000000");
    if (def.argument == Kind::Explode) {
        if (n < 0.0 || n > 1.0) fail("explode takes a number from 0 to 1");
        return float(n);
    }
    return uint32_t(n);
}

// select|add|hide|show, then the path: the rest of the line after that word.
NodeTarget parseNode(const CommandDef& def, const std::vector<std::string>& words,
                     const std::string& rest) {
    NodeTarget node;
    size_t i = 0;
    while (i < 4 && words[0] != nodeActions[i]) ++i;
    if (i == 4)
        fail("a node is selected, added, hidden or shown, not '" + words[0] + "' (" +
             commandUsage(def) + ")");
    node.action = NodeAction(i);
    const size_t start = rest.find_first_not_of(" \t", words[0].size());
    node.path = start == std::string::npos ? "" : rest.substr(start);
    return node;
}

std::string sectionText(const std::optional<scene::SectionPlane>& plane) {
    if (!plane) return "off";
    for (int axis = 0; axis < 3; ++axis)
        if (plane->normal == glm::dvec3(axis == 0, axis == 1, axis == 2)) {
            char text[64];
            std::snprintf(text, sizeof text, "%c,%.9g%s", "xyz"[axis], plane -> offset,
                          plane -> flip ? ",flip" : "");
            return text;
        }
    char text[128];
    std::snprintf(text, sizeof text, "normal %.6g %.6g %.6g, offset %.9g", plane->normal.x,
                  plane->normal.y, plane->normal.z, plane->offset);
    return text;
}

// The argument as the script writes it ("" for none and for a toggle).
std::string argumentText(Kind kind, const Argument& argument) {
    struct Words {
        Kind kind;
        std::string operator()(std::monostate) const { return ""; }
        std::string operator()(Switch s) const {
            return s == Switch::On ? "on" : s == Switch::Off ? "off" : "";
        }
        std::string operator()(uint32_t n) const {
            return kind == Kind::Level && n < 3 ? levelNames[n] : std::to_string(n);
        }
        std::string operator()(float f) const {
            char text[32];
            std::snprintf(text, sizeof text, "%g", double(f));
            return text;
        }
        std::string operator()(const std::string& text) const { return text; }
        std::string operator()(const scene::StandardView* v) const { return v->name; }
        std::string operator()(const render::Technique* t) const { return t->name; }
        std::string operator()(const render::DrawMode* m) const { return m->name; }
        std::string operator()(render::CullMode m) const { return render::cullModeName(m); }
        std::string operator()(render::ClearPath p) const { return render::clearPathName(p); }
        std::string operator()(const std::optional<scene::SectionPlane>& p) const {
            return sectionText(p);
        }
        std::string operator()(const CensusAsk& c) const {
            if (c.action == CensusAction::Part) return "part " + std::to_string(c.part);
            if (c.action == CensusAction::Tint) return c.on ? "tint on" : "tint off";
            if (c.action == CensusAction::Export) return "export " + c.path;
            if (c.action != CensusAction::Run) return censusWords[size_t(c.action) - 1];
            return std::to_string(c.views) + "x" + std::to_string(c.size);
        }
        std::string operator()(const NodeTarget& n) const {
            std::string text = nodeActions[size_t(n.action)];
            if (!n.path.empty()) text += " " + n.path;
            if (n.occurrence) text += " (row " + std::to_string(n.occurrence + 1) + " of the path)";
            return text;
        }
    };
    return std::visit(Words{kind}, argument);
}

const char* keyName(int key) {
    static const std::pair<int, const char*> names[] = {
        {GLFW_KEY_ESCAPE, "Esc"}, {GLFW_KEY_HOME, "Home"},   {GLFW_KEY_SLASH, "/"},
        {GLFW_KEY_TAB, "Tab"},    {GLFW_KEY_SPACE, "Space"}, {GLFW_KEY_ENTER, "Enter"}};
    for (const auto& [code, name] : names)
        if (code == key) return name;
    return nullptr;
}

std::string chordsText(const std::vector<Chord>& chords) {
    std::string text;
    for (const Chord& chord : chords) text += (text.empty() ? "" : ", ") + chordText(chord);
    return text;
}

// The mouse: handled by Input::onButton, onCursor and onScroll, and by the window's drop;
// listed for the help.
const std::pair<std::string, std::string> gestures[] = {
    {"Left drag", "orbit around the target"},
    {"Right or middle drag", "pan"},
    {"Wheel", "zoom toward the point under the cursor"},
    {"Left click", "select the part under the cursor (empty space: none)"},
    {"Double-click", "select the solid (object) under the cursor"},
    {"Ctrl+click",
     "add a second thing (B) to the clicked one (A): the Inspect panel gives their distance"},
    {"Shift / Ctrl / Alt + left drag",
     "box selection: replace / add to / remove from the selection"},
    {"Drop a file", std::string("open it (").append(scene::extensionList()).append(")")},
};

} // namespace

Argument parseArgument(const CommandDef& def, const std::vector<std::string>& words,
                       const std::string& rest) {
    const std::string usage = std::string("'") + def.name + "' takes: " + commandUsage(def);
    switch (def.argument) {
    case Kind::None:
        if (!words.empty()) fail(usage);
        return {};
    case Kind::OptionalText:
        return rest.empty() ? Argument{} : Argument{rest};
    case Kind::Text:
        if (rest.empty()) fail(usage);
        return rest;
    case Kind::Node:
        if (words.empty()) fail(usage);
        return parseNode(def, words, rest);
    case Kind::Census: // `part ID`, `tint on|off` and `export PATH`, the forms of more words
        if (words.size() >= 2 && words[0] == "export") // the path: the rest of the line
            return CensusAsk{CensusAction::Export,
                             0,
                             0,
                             0,
                             false,
                             rest.substr(rest.find_first_not_of(" \t", words[0].size()))};
        if (words.size() == 2 && words[0] == "part")
            return CensusAsk{CensusAction::Part, 0, 0, uint32_t(number(def, words[1]))};
        if (words.size() == 2 && words[0] == "tint")
            return CensusAsk{CensusAction::Tint, 0, 0, 0,
                             oneOfWords("census tint", words[1], switchWords) == 0};
        break;
    case Kind::Switch:
        if (words.empty()) return Switch::Toggle;
        break;
    default:
        break;
    }
    if (words.size() != 1) fail(usage);
    return parseWord(def, words[0]);
}

std::string commandUsage(const CommandDef& def) {
    const std::string args = kindUsage(def.argument);
    return args.empty() ? def.name : def.name + (" " + args);
}

std::string commandWords(const Command& command) {
    const CommandDef& def = definition(command.id);
    const std::string args = argumentText(def.argument, command.argument);
    return args.empty() ? def.name : def.name + (" " + args);
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

std::string keysOf(CommandId id) {
    const CommandDef& def = definition(id);
    return def.keys.empty() ? "" : chordsText(def.keys.front().chords);
}

std::string withKeys(const char* label, CommandId id) {
    const std::string keys = keysOf(id);
    return keys.empty() ? label : label + (" (" + keys + ")");
}

// A line per key binding (a view per digit), a line for a command without keys; a switch's
// or an optional file's keys show the script's whole form, "xray [on|off]".
std::vector<HelpLine> helpLines() {
    std::vector<HelpLine> lines;
    for (const CommandDef& def : commands()) {
        if (def.keys.empty()) lines.push_back({"", def.description, commandUsage(def)});
        for (const KeyBinding& binding : def.keys) {
            const Command command{def.id, binding.argument};
            const bool whole = std::holds_alternative<std::monostate>(binding.argument) ||
                               binding.argument == Argument(Switch::Toggle);
            lines.push_back({chordsText(binding.chords),
                             binding.description ? binding.description : def.description,
                             whole ? commandUsage(def) : commandWords(command)});
        }
    }
    for (const auto& [gesture, description] : gestures) lines.push_back({gesture, description, ""});
    return lines;
}

size_t bindingCount() {
    size_t count = std::size(gestures);
    for (const CommandDef& def : commands())
        for (const KeyBinding& binding : def.keys) count += binding.chords.size();
    return count;
}

} // namespace app
