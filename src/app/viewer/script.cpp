// script.cpp - the viewer script parser and the player that hands out due commands.
#include "app/viewer/script.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <tuple>

#include "render/culling.h"
#include "render/technique.h"
#include "scene/section.h"
#include "scene/standard_view.h"

// Only the key code constants are used; no GLFW function is called here.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace app {
namespace {

struct CommandSpec {
    const char* name;
    ScriptOp op;
    size_t numbers;    // numeric arguments
    const char* usage; // for the error message
};

const CommandSpec commandSpecs[] = {
    {"key", ScriptOp::Key, 0, "key NAME"},
    {"type", ScriptOp::Type, 0, "type TEXT"},
    {"move", ScriptOp::Move, 2, "move X Y"},
    {"click", ScriptOp::Click, 2, "click X Y [ctrl]"},
    {"dblclick", ScriptOp::DoubleClick, 2, "dblclick X Y"},
    {"level", ScriptOp::Level, 0, "level face|solid|assembly"},
    {"drag", ScriptOp::Drag, 4, "drag X0 Y0 X1 Y1"},
    {"box", ScriptOp::Box, 4, "box X0 Y0 X1 Y1 [add|remove]"},
    {"object", ScriptOp::Object, 0, "object NAME"},
    {"node", ScriptOp::Node, 0, "node select|add|hide|show [PATH]"},
    {"scroll", ScriptOp::Scroll, 1, "scroll DY"},
    {"resize", ScriptOp::Resize, 2, "resize WIDTH HEIGHT"},
    {"renderer", ScriptOp::Renderer, 0, "renderer NAME"},
    {"mode", ScriptOp::Mode, 0, "mode NAME"},
    {"culling", ScriptOp::Culling, 0, "culling off|frustum|occlusion"},
    {"freeze", ScriptOp::Freeze, 0, "freeze on|off"},
    {"sort", ScriptOp::Sort, 0, "sort on|off"},
    {"defaults", ScriptOp::Defaults, 0, "defaults"},
    {"msaa", ScriptOp::Msaa, 1, "msaa 1|2|4|8"},
    {"clear", ScriptOp::Clear, 0, "clear auto|pass|compute"},
    {"copies", ScriptOp::Copies, 1, "copies N"},
    {"section", ScriptOp::Section, 0, "section AXIS,VALUE[,flip] | off"},
    {"view", ScriptOp::View, 0, "view NAME"},
    {"ortho", ScriptOp::Ortho, 0, "ortho on|off"},
    {"explode", ScriptOp::Explode, 1, "explode F (0 to 1)"},
    {"xray", ScriptOp::Xray, 0, "xray on|off"},
    {"screenshot", ScriptOp::Screenshot, 0, "screenshot FILE"},
    {"drop", ScriptOp::Drop, 0, "drop FILE"},
    {"loaded", ScriptOp::Loaded, 0, "loaded"},
    {"cancel", ScriptOp::Cancel, 0, "cancel"},
    {"clear-recent", ScriptOp::ClearRecent, 0, "clear-recent"},
    {"frames", ScriptOp::Frames, 1, "frames N"},
    {"redraw", ScriptOp::Redraw, 0, "redraw"},
    {"blink", ScriptOp::Blink, 0, "blink strong|weak|clock"},
    {"rest", ScriptOp::Rest, 1, "rest SECONDS"},
    {"pipeline", ScriptOp::Pipeline, 0, "pipeline hold|release|ready"},
    {"quit", ScriptOp::Quit, 0, "quit"},
};

std::string upper(std::string text) {
    for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

bool parseNumber(const std::string& text, double& value) {
    std::istringstream in(text);
    in >> value;
    return in && in.peek() == std::char_traits<char>::eof() && std::isfinite(value);
}

// One line's command; `where` is "file:line" and prefixes every message.
ScriptCommand parseLine(const std::string& line, const std::string& where) {
    std::istringstream in(line);
    std::string time, name;
    in >> time >> name;
    auto fail = [&](const std::string& message) { throw ScriptError(where + ": " + message); };
    ScriptCommand command;
    command.where = where;
    // A command that takes one of a few words: "'NAME' takes a, b or c, not 'x'" otherwise.
    auto expectWord = [&](std::initializer_list<const char*> words) {
        const std::vector<std::string> list(words.begin(), words.end());
        if (std::find(list.begin(), list.end(), command.text) != list.end()) return;
        std::string said;
        for (size_t i = 0; i < list.size(); ++i)
            said += (i == 0 ? "" : i + 1 == list.size() ? " or " : ", ") + list[i];
        fail("'" + name + "' takes " + said + ", not '" + command.text + "'");
    };
    if (!parseNumber(time, command.seconds) || command.seconds < 0.0)
        fail("expected '<seconds> <command> [args]', and '" + time +
             "' is not a time in seconds (0 or more)");
    if (name.empty()) fail("a command must follow the time");
    const CommandSpec* spec = nullptr;
    for (const auto& candidate : commandSpecs)
        if (name == candidate.name) spec = &candidate;
    if (!spec) {
        std::string known;
        for (const auto& candidate : commandSpecs)
            known += (known.empty() ? "" : ", ") + std::string(candidate.name);
        fail("unknown command '" + name + "' (known: " + known + ")");
    }
    command.op = spec->op;

    std::vector<std::string> args;
    for (std::string word; in >> word;) args.push_back(word);
    const bool takesText = spec->op == ScriptOp::Key || spec->op == ScriptOp::Renderer ||
                           spec->op == ScriptOp::Mode || spec->op == ScriptOp::Culling ||
                           spec->op == ScriptOp::Freeze || spec->op == ScriptOp::Sort ||
                           spec->op == ScriptOp::Section || spec->op == ScriptOp::Screenshot ||
                           spec->op == ScriptOp::Drop || spec->op == ScriptOp::View ||
                           spec->op == ScriptOp::Ortho || spec->op == ScriptOp::Xray ||
                           spec->op == ScriptOp::Level || spec->op == ScriptOp::Pipeline ||
                           spec->op == ScriptOp::Blink || spec->op == ScriptOp::Clear;
    // A box may name its mode after the corners; an object's name is the rest of the line.
    const size_t expected = takesText ? 1 : spec->numbers;
    const bool restOfLine = spec->op == ScriptOp::Object || spec->op == ScriptOp::Type;
    const bool fits = restOfLine || spec->op == ScriptOp::Node ? !args.empty()
                      : spec->op == ScriptOp::Box   ? args.size() == 4 || args.size() == 5
                      : spec->op == ScriptOp::Click ? args.size() == 2 || args.size() == 3
                                                    : args.size() == expected;
    if (!fits) fail(std::string("'") + spec->name + "' takes: " + spec->usage);
    if (restOfLine) {
        const auto start = line.find(spec->name) + std::string(spec->name).size();
        command.text = line.substr(line.find_first_not_of(" \t", start));
        command.text.erase(command.text.find_last_not_of(" \t") + 1);
    }
    if (spec->op == ScriptOp::Node) {
        const char* actions[] = {"select", "add", "hide", "show"};
        const auto found = std::find(std::begin(actions), std::end(actions), args[0]);
        if (found == std::end(actions))
            fail("a node is selected, added, hidden or shown, not '" + args[0] + "' (" +
                 spec->usage + ")");
        command.values[0] = double(found - std::begin(actions));
        const size_t word = line.find(args[0], line.find("node") + 4) + args[0].size();
        const size_t start = line.find_first_not_of(" \t\r", word);
        command.text = start == std::string::npos ? "" : line.substr(start);
        command.text.erase(command.text.find_last_not_of(" \t\r") + 1);
    }
    if (spec->op == ScriptOp::Box && args.size() == 5) {
        if (args[4] == "add")
            command.mods = GLFW_MOD_CONTROL;
        else if (args[4] == "remove")
            command.mods = GLFW_MOD_ALT;
        else
            fail("a box adds or removes, not '" + args[4] + "' (" + spec->usage + ")");
    } else if (spec->op == ScriptOp::Box) {
        command.mods = GLFW_MOD_SHIFT;
    }
    if (spec->op == ScriptOp::Click && args.size() == 3) {
        if (args[2] != "ctrl") fail("a click holds ctrl or nothing, not '" + args[2] + "'");
        command.mods = GLFW_MOD_CONTROL;
    }
    for (size_t i = 0; i < spec->numbers; ++i)
        if (!parseNumber(args[i], command.values[i]))
            fail("'" + args[i] + "' is not a number (" + spec->usage + ")");
    if (takesText) command.text = args[0];

    switch (spec->op) {
    case ScriptOp::Key:
        if (auto chord = scriptKeyChord(command.text))
            std::tie(command.key, command.mods) = *chord;
        else
            fail("unknown key '" + command.text +
                 "' (A-Z, 0-9, F1-F12, ESC, SPACE, ENTER, TAB, HOME, /; shift+, ctrl+, "
                 "alt+)");
        break;
    case ScriptOp::Copies:
        if (command.values[0] < 1.0 || command.values[0] > 1e6 ||
            command.values[0] != std::floor(command.values[0]))
            fail("copies takes a whole number from 1 to 1000000");
        break;
    case ScriptOp::Explode:
        if (command.values[0] < 0.0 || command.values[0] > 1.0)
            fail("explode takes a number from 0 to 1");
        break;
    case ScriptOp::Frames:
        if (command.values[0] < 1.0 || command.values[0] > 1000.0 ||
            command.values[0] != std::floor(command.values[0]))
            fail("frames takes a whole number from 1 to 1000");
        break;
    case ScriptOp::Rest:
        if (command.values[0] <= 0.0 || command.values[0] > 60.0)
            fail("rest takes seconds, more than 0 and at most 60");
        break;
    case ScriptOp::Level:
        expectWord({"face", "solid", "assembly"});
        break;
    case ScriptOp::Move:
    case ScriptOp::Click:
    case ScriptOp::DoubleClick:
    case ScriptOp::Drag:
    case ScriptOp::Box:
        for (size_t i = 0; i < spec->numbers; ++i)
            if (command.values[i] < 0.0) fail("window coordinates cannot be negative");
        break;
    case ScriptOp::Resize:
        for (size_t i = 0; i < 2; ++i)
            if (command.values[i] < 1.0 || command.values[i] > 16384.0 ||
                command.values[i] != std::floor(command.values[i]))
                fail("window size must be whole numbers from 1 to 16384");
        break;
    case ScriptOp::Msaa: {
        const double n = command.values[0];
        if (n != 1.0 && n != 2.0 && n != 4.0 && n != 8.0) fail("msaa takes 1, 2, 4 or 8");
        break;
    }
    case ScriptOp::Renderer:
        if (!render::findTechnique(command.text))
            fail("unknown renderer '" + command.text + "' (known: " + render::techniqueNames() +
                 ")");
        break;
    case ScriptOp::Mode:
        if (!render::findDrawMode(command.text))
            fail("unknown mode '" + command.text + "' (known: " + render::drawModeNames() + ")");
        break;
    case ScriptOp::Culling:
        if (!render::findCullMode(command.text))
            fail("unknown culling '" + command.text + "' (known: " + render::cullModeNames() + ")");
        break;
    case ScriptOp::Section:
        if (command.text != "off") try {
                scene::parseSectionPlane(command.text);
            } catch (const std::invalid_argument& e) {
                fail(std::string("'section' ") + e.what() + ", or off");
            }
        break;
    case ScriptOp::Freeze:
    case ScriptOp::Sort:
    case ScriptOp::Ortho:
    case ScriptOp::Xray:
        expectWord({"on", "off"});
        break;
    case ScriptOp::Pipeline:
        expectWord({"hold", "release", "ready"});
        break;
    case ScriptOp::Blink:
        expectWord({"strong", "weak", "clock"});
        break;
    case ScriptOp::Clear:
        expectWord({"auto", "pass", "compute"});
        break;
    case ScriptOp::View:
        if (!scene::findStandardView(command.text))
            fail("unknown view '" + command.text + "' (known: " + scene::standardViewNames() + ")");
        break;
    default:
        break;
    }
    return command;
}

} // namespace

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

std::vector<ScriptCommand> parseScript(const std::string& text, const std::string& name) {
    std::vector<ScriptCommand> commands;
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (!line.empty() && line.back() == '\r') line.pop_back(); // files written on Windows
        const auto first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line[first] == '#') continue;
        commands.push_back(parseLine(line, name + ":" + std::to_string(number)));
    }
    return commands;
}

std::vector<ScriptCommand> loadScript(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw ScriptError("cannot read script '" + path + "'");
    std::ostringstream text;
    text << file.rdbuf();
    return parseScript(text.str(), path);
}

ScriptPlayer::ScriptPlayer(std::vector<ScriptCommand> commands) : commands_(std::move(commands)) {
    std::stable_sort(commands_.begin(), commands_.end(),
                     [](const auto& a, const auto& b) { return a.seconds < b.seconds; });
}

std::vector<ScriptCommand> ScriptPlayer::due(double seconds) {
    std::vector<ScriptCommand> ready;
    while (next_ < commands_.size() && commands_[next_].seconds <= seconds)
        ready.push_back(commands_[next_++]);
    return ready;
}

std::optional<double> ScriptPlayer::nextTime() const {
    if (finished()) return std::nullopt;
    return commands_[next_].seconds;
}

} // namespace app
