// script.cpp - the viewer script parser (input lines here, command lines by the command
// table's rows) and the player that hands out lines as they come due.
#include "app/viewer/commands/script.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <tuple>

#include "app/viewer/commands/commands.h"

// Only the key code constants are used; no GLFW function is called here.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace app {
namespace {

// The lines that are input or a wait, not a command (commands.h has those).
struct InputSpec {
    const char* name;
    ScriptOp op;
    size_t numbers;    // numeric arguments
    const char* usage; // for the error message
    bool points;       // the numbers are points in the window (never negative)
};

const InputSpec inputSpecs[] = {
    {"key", ScriptOp::Key, 0, "key NAME", false},
    {"type", ScriptOp::Type, 0, "type TEXT", false},
    {"move", ScriptOp::Move, 2, "move X Y", true},
    {"click", ScriptOp::Click, 2, "click X Y [ctrl]", true},
    {"dblclick", ScriptOp::DoubleClick, 2, "dblclick X Y", true},
    {"drag", ScriptOp::Drag, 4, "drag X0 Y0 X1 Y1", true},
    {"box", ScriptOp::Box, 4, "box X0 Y0 X1 Y1 [add|remove]", true},
    {"scroll", ScriptOp::Scroll, 1, "scroll DY", false},
    {"leave", ScriptOp::Leave, 0, "leave", false},
    {"unfocus", ScriptOp::Unfocus, 0, "unfocus", false},
    {"resize", ScriptOp::Resize, 2, "resize WIDTH HEIGHT", false},
    {"drop", ScriptOp::Drop, 0, "drop FILE", false},
    {"loaded", ScriptOp::Loaded, 0, "loaded", false},
    {"solids", ScriptOp::Solids, 1, "solids N", false},
    {"frames", ScriptOp::Frames, 1, "frames N", false},
    {"redraw", ScriptOp::Redraw, 0, "redraw", false},
    {"blink", ScriptOp::Blink, 0, "blink strong|weak|clock", false},
    {"rest", ScriptOp::Rest, 1, "rest SECONDS", false},
    {"pipeline", ScriptOp::Pipeline, 0, "pipeline hold|release|ready", false},
    {"inspect", ScriptOp::Inspect, 0, "inspect hold|release|ready", false},
    {"census-done", ScriptOp::CensusDone, 0, "census-done", false},
};

[[noreturn]] void fail(const std::string& message) {
    throw std::invalid_argument(message);
}

std::string upper(std::string text) {
    for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

std::string trimmed(const std::string& text) {
    const size_t first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t\r") + 1 - first);
}

const char* const holdWords[] = {"hold", "release", "ready"}; // pipeline, inspect
const char* const blinkWords[] = {"strong", "weak", "clock"};

bool whole(double value, double low, double high) {
    return value >= low && value <= high && value == std::floor(value);
}

// How many words a line takes, and the modifiers a box or a click names after its points.
void readInputWords(const InputSpec& spec, const std::vector<std::string>& args,
                    const std::string& rest, ScriptLine& line) {
    const ScriptOp op = spec.op;
    const bool oneWord = op == ScriptOp::Key || op == ScriptOp::Drop || op == ScriptOp::Blink ||
                         op == ScriptOp::Pipeline || op == ScriptOp::Inspect;
    const bool fits = op == ScriptOp::Type    ? !rest.empty()
                      : op == ScriptOp::Box   ? args.size() == 4 || args.size() == 5
                      : op == ScriptOp::Click ? args.size() == 2 || args.size() == 3
                      : oneWord               ? args.size() == 1
                                              : args.size() == spec.numbers;
    if (!fits) fail(std::string("'") + spec.name + "' takes: " + spec.usage);
    if (op == ScriptOp::Type) line.text = rest;
    if (oneWord) line.text = args[0];
    if (op == ScriptOp::Box && args.size() == 5) {
        if (args[4] != "add" && args[4] != "remove")
            fail("a box adds or removes, not '" + args[4] + "' (" + spec.usage + ")");
        line.mods = args[4] == "add" ? GLFW_MOD_CONTROL : GLFW_MOD_ALT;
    } else if (op == ScriptOp::Box) {
        line.mods = GLFW_MOD_SHIFT;
    }
    if (op == ScriptOp::Click && args.size() == 3) {
        if (args[2] != "ctrl") fail("a click holds ctrl or nothing, not '" + args[2] + "'");
        line.mods = GLFW_MOD_CONTROL;
    }
    for (size_t i = 0; i < spec.numbers; ++i)
        if (!parseNumber(args[i], line.values[i]))
            fail("'" + args[i] + "' is not a number (" + spec.usage + ")");
}

// What each line's words may be.
void checkInput(const InputSpec& spec, ScriptLine& line) {
    const auto& v = line.values;
    if (spec.points)
        for (size_t i = 0; i < spec.numbers; ++i)
            if (v[i] < 0.0) fail("window coordinates cannot be negative");
    switch (spec.op) {
    case ScriptOp::Key:
        if (auto chord = scriptKeyChord(line.text))
            std::tie(line.key, line.mods) = *chord;
        else
            fail("unknown key '" + line.text +
                 "' (A-Z, 0-9, F1-F12, ESC, SPACE, ENTER, TAB, HOME, /; shift+, ctrl+, alt+)");
        break;
    case ScriptOp::Resize:
        if (!whole(v[0], 1.0, 16384.0) || !whole(v[1], 1.0, 16384.0))
            fail("window size must be whole numbers from 1 to 16384");
        break;
    case ScriptOp::Frames:
        if (!whole(v[0], 1.0, 1000.0)) fail("frames takes a whole number from 1 to 1000");
        break;
    case ScriptOp::Solids:
        if (!whole(v[0], 1.0, 1e9)) fail("solids takes a whole number from 1");
        break;
    case ScriptOp::Rest:
        if (v[0] <= 0.0 || v[0] > 60.0) fail("rest takes seconds, more than 0 and at most 60");
        break;
    case ScriptOp::Pipeline:
    case ScriptOp::Inspect:
        oneOfWords(spec.name, line.text, holdWords);
        break;
    case ScriptOp::Blink:
        oneOfWords(spec.name, line.text, blinkWords);
        break;
    default:
        break;
    }
}

std::string knownWords() {
    std::string known;
    for (const InputSpec& spec : inputSpecs)
        known += (known.empty() ? "" : ", ") + std::string(spec.name);
    for (const CommandDef& def : commands()) known += ", " + std::string(def.name);
    return known;
}

// One line; `where` is "file:line" and prefixes every message.
ScriptLine parseLine(const std::string& text, const std::string& where) {
    std::istringstream in(text);
    std::string time, name;
    in >> time >> name;
    const std::streamoff end = in.tellg(); // -1 when the name ends the line
    const std::string rest = end < 0 ? "" : trimmed(text.substr(size_t(end)));
    std::vector<std::string> args;
    for (std::string word; in >> word;) args.push_back(word);
    ScriptLine line;
    line.where = where;
    try {
        if (!parseNumber(time, line.seconds) || line.seconds < 0.0)
            fail("expected '<seconds> <command> [args]', and '" + time +
                 "' is not a time in seconds (0 or more)");
        if (name.empty()) fail("a command must follow the time");
        if (const CommandDef* def = findCommand(name)) {
            line.op = ScriptOp::Command;
            line.command = Command{def->id, parseArgument(*def, args, rest)};
            return line;
        }
        const auto spec = std::find_if(std::begin(inputSpecs), std::end(inputSpecs),
                                       [&](const InputSpec& s) { return name == s.name; });
        if (spec == std::end(inputSpecs))
            fail("unknown command '" + name + "' (known: " + knownWords() + ")");
        line.op = spec->op;
        readInputWords(*spec, args, rest, line);
        checkInput(*spec, line);
    } catch (const std::invalid_argument& e) {
        throw ScriptError(where + ": " + e.what());
    }
    return line;
}

} // namespace

size_t oneOfWords(const char* name, const std::string& word, std::span<const char* const> words) {
    for (size_t i = 0; i < words.size(); ++i)
        if (word == words[i]) return i;
    std::string said;
    for (size_t i = 0; i < words.size(); ++i)
        said += std::string(i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
    throw std::invalid_argument(std::string("'") + name + "' takes " + said + ", not '" + word +
                                "'");
}

bool parseNumber(const std::string& text, double& value) {
    std::istringstream in(text);
    in >> value;
    return in && in.peek() == std::char_traits<char>::eof() && std::isfinite(value);
}

std::optional<int> scriptKeyCode(const std::string& name) {
    const std::string key = upper(name);
    if (key.size() == 1 && key[0] >= 'A' && key[0] <= 'Z') return GLFW_KEY_A + (key[0] - 'A');
    if (key.size() == 1 && key[0] >= '0' && key[0] <= '9') return GLFW_KEY_0 + (key[0] - '0');
    if (key.size() >= 2 && key.size() <= 3 && key[0] == 'F') {
        double number = 0.0;
        if (parseNumber(key.substr(1), number) && number >= 1 && number <= 12 &&
            std::isdigit(static_cast<unsigned char>(key[1])))
            return GLFW_KEY_F1 + int(number) - 1;
    }
    if (key == "ESC" || key == "ESCAPE") return GLFW_KEY_ESCAPE;
    if (key == "SPACE") return GLFW_KEY_SPACE;
    if (key == "ENTER") return GLFW_KEY_ENTER;
    if (key == "TAB") return GLFW_KEY_TAB;
    if (key == "HOME") return GLFW_KEY_HOME;
    if (key == "/" || key == "SLASH") return GLFW_KEY_SLASH; // shift+/ is ?, the help
    return std::nullopt;
}

std::optional<std::pair<int, int>> scriptKeyChord(const std::string& name) {
    int mods = 0;
    std::string rest = name;
    for (size_t plus; (plus = rest.find('+')) != std::string::npos && plus + 1 < rest.size();) {
        const std::string modifier = upper(rest.substr(0, plus));
        if (modifier == "SHIFT")
            mods |= GLFW_MOD_SHIFT;
        else if (modifier == "CTRL")
            mods |= GLFW_MOD_CONTROL;
        else if (modifier == "ALT")
            mods |= GLFW_MOD_ALT;
        else
            return std::nullopt;
        rest = rest.substr(plus + 1);
    }
    const auto code = scriptKeyCode(rest);
    if (!code) return std::nullopt;
    return std::pair{*code, mods};
}

std::vector<ScriptLine> parseScript(const std::string& text, const std::string& name) {
    std::vector<ScriptLine> lines;
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (!line.empty() && line.back() == '\r') line.pop_back(); // files written on Windows
        const auto first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line[first] == '#') continue;
        lines.push_back(parseLine(line, name + ":" + std::to_string(number)));
    }
    return lines;
}

std::vector<ScriptLine> loadScript(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw ScriptError("cannot read script '" + path + "'");
    std::ostringstream text;
    text << file.rdbuf();
    return parseScript(text.str(), path);
}

ScriptPlayer::ScriptPlayer(std::vector<ScriptLine> lines) : lines_(std::move(lines)) {
    std::stable_sort(lines_.begin(), lines_.end(),
                     [](const auto& a, const auto& b) { return a.seconds < b.seconds; });
}

std::vector<ScriptLine> ScriptPlayer::due(double seconds) {
    std::vector<ScriptLine> ready;
    while (next_ < lines_.size() && lines_[next_].seconds <= seconds)
        ready.push_back(lines_[next_++]);
    return ready;
}

std::optional<double> ScriptPlayer::nextTime() const {
    if (finished()) return std::nullopt;
    return lines_[next_].seconds;
}

} // namespace app
