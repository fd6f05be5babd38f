// saved_settings.cpp - which viewer settings are kept between runs, how each is written as
// its flag, and reading the file back through the flag table (cli_flags.h).
#include "app/saved_settings.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <type_traits>

#include "app/cli.h"
#include "app/cli_flags.h"
#include "render/culling.h"

namespace app {
namespace {

// A kept setting: its flag, its value as the flag takes it, and putting it back to a default.
struct Kept {
    const char* flag;
    std::function<std::string(const LiveSettings&, const WindowPlace&)> text;
    std::function<void(LiveSettings&, const LiveSettings&)> reset;
};

std::string valueText(uint32_t value) {
    return std::to_string(value);
}
std::string valueText(float value) {
    char text[32]; // 9 digits: the float comes back exactly
    std::snprintf(text, sizeof text, "%.9g", double(value));
    return text;
}
std::string valueText(bool value) {
    return value ? "on" : "off";
}
std::string valueText(const render::Technique* technique) {
    return technique->name;
}
std::string valueText(const render::DrawMode* mode) {
    return mode->name;
}
std::string valueText(render::CullMode mode) {
    return render::cullModeName(mode);
}
std::string valueText(render::ClearPath path) {
    return render::clearPathName(path);
}
std::string valueText(const glm::vec3& color) {
    return hexColor(color);
}

// `field` is a generic lambda returning the setting of a const or non-const LiveSettings.
template <typename Field>
Kept kept(const char* flag, Field field) {
    return {flag,
            [field](const LiveSettings& o, const WindowPlace&) { return valueText(field(o)); },
            [field](LiveSettings& o, const LiveSettings& d) { field(o) = field(d); }};
}

// A setting of a const or non-const LiveSettings, for kept().
// clang-format off
#define FIELD(path) [](auto& o) -> auto& { return o.path; }
// clang-format on

// What the viewer's user chooses and expects back next time: the renderer, its look and
// culling, not the model, its copies or the camera. Switches are written when they differ
// from the viewer's default, which is what their flag changes.
const std::vector<Kept>& keptSettings() {
    static const std::vector<Kept> list = {
        kept("--renderer", FIELD(render.pipeline.technique)),
        kept("--mode", FIELD(render.pipeline.mode)),
        kept("--msaa", FIELD(render.pipeline.msaa)),
        kept("--clear", FIELD(render.clear)),
        kept("--search-batch", FIELD(render.pipeline.searchBatch)),
        kept("--nsearch-n", FIELD(render.pipeline.nsearch.n)),
        kept("--nsearch-guess", FIELD(render.pipeline.nsearch.guess)),
        kept("--nsearch-linear", FIELD(render.pipeline.nsearch.linearBelow)),
        kept("--nsearch-steps", FIELD(render.pipeline.nsearch.maxSteps)),
        kept("--no-sort-draws", FIELD(render.draws.sortDraws)),
        kept("--part-weight", FIELD(render.shading.partWeight)),
        kept("--colorize-draws", FIELD(render.shading.colorizeDraws)),
        kept("--ignore-materials", FIELD(render.shading.ignoreMaterials)),
        kept("--tint-levels", FIELD(render.shading.tintLevels)),
        kept("--edges", FIELD(render.edges.on)),
        kept("--edge-width", FIELD(render.edges.width)),
        kept("--edge-color", FIELD(render.edges.color)),
        kept("--culling", FIELD(render.culling.mode)),
        kept("--lod-levels", FIELD(scene.lodLevels)),
        kept("--lod-error", FIELD(render.lod.errorPixels)),
        kept("--raster-pixels", FIELD(render.raster.trianglePixels)),
        kept("--raster-all", FIELD(render.raster.all)),
        kept("--ortho", FIELD(camera.ortho)),
        // The window's geometry at the last close: flags too, so a --size on the command line
        // wins as it does for every kept flag; Reset to defaults leaves them as they are.
        {"--size",
         [](const LiveSettings&, const WindowPlace& w) {
             return std::to_string(w.width) + "x" + std::to_string(w.height);
         },
         [](LiveSettings&, const LiveSettings&) {}},
        {"--window-pos",
         [](const LiveSettings&, const WindowPlace& w) {
             return w.position
                        ? std::to_string((*w.position)[0]) + "," + std::to_string((*w.position)[1])
                        : std::string();
         },
         [](LiveSettings&, const LiveSettings&) {}},
    };
    return list;
}
#undef FIELD

const Flag& flagNamed(const std::string& name) {
    for (const Flag& flag : flags())
        if (name == flag.name) return flag;
    throw std::logic_error("no flag " + name); // not reached: the kept list names flags
}

bool isKept(const std::string& name) {
    return std::any_of(keptSettings().begin(), keptSettings().end(),
                       [&](const Kept& k) { return name == k.flag; });
}

std::string trimmed(const std::string& text) {
    const size_t begin = text.find_first_not_of(" \t\r");
    if (begin == std::string::npos) return "";
    return text.substr(begin, text.find_last_not_of(" \t\r") - begin + 1);
}

} // namespace

bool isViewLine(const std::string& line) {
    return line.starts_with(viewLinePrefix);
}

std::string savedSettingsPath() {
    const char* config = std::getenv("XDG_CONFIG_HOME");
    const char* home = std::getenv("HOME");
    if (config && *config) return std::string(config) + "/idview/viewer.conf";
    if (home && *home) return std::string(home) + "/.config/idview/viewer.conf";
    return "";
}

std::string savedSettingsText(const LiveSettings& live, const WindowPlace& window) {
    const Options defaults = viewerDefaults();
    std::string text = "# idview's viewer settings, written when it closes: one command-line "
                       "flag a line (the command line wins, idview --help), then the window's "
                       "own viewer. lines\n";
    for (const Kept& k : keptSettings()) {
        const std::string value = k.text(live, window);
        if (value == k.text(defaults.live, windowPlace(defaults))) continue;
        text += k.flag;
        if (flagNamed(k.flag).value) text += " " + value;
        text += "\n";
    }
    return text;
}

std::vector<std::string> savedArgs(const std::string& text, const std::string& name,
                                   const Warn& warn) {
    std::vector<std::string> args;
    std::istringstream lines(text);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
        line = trimmed(line);
        if (line.empty() || line[0] == '#' || isViewLine(line)) continue;
        const size_t space = line.find_first_of(" \t=");
        std::vector<std::string> one = {line.substr(0, space)};
        if (space != std::string::npos) one.push_back(trimmed(line.substr(space + 1)));
        const std::string where = name + ":" + std::to_string(number) + ": ";
        if (!isKept(one[0])) {
            warn(where + "'" + line + "' is not a setting the viewer keeps; ignored");
            continue;
        }
        try {
            parseArgs(one, viewerDefaults()); // each line on its own, so one bad line is dropped
        } catch (const UsageError& e) {
            warn(where + e.what() + "; ignored");
            continue;
        }
        args.insert(args.end(), one.begin(), one.end());
    }
    return args;
}

Options viewerOptions(const std::vector<std::string>& args, const std::string& path,
                      const Warn& warn) {
    Options given = parseArgs(args, viewerDefaults());
    if (!given.savedSettings || path.empty()) return given;
    std::ifstream file(path);
    if (!file) return given; // nothing kept yet
    std::stringstream text;
    text << file.rdbuf();
    std::vector<std::string> all = savedArgs(text.str(), path, warn);
    all.insert(all.end(), args.begin(), args.end());
    try {
        return parseArgs(all, viewerDefaults());
    } catch (const UsageError& e) {
        warn(path + ": the saved settings do not go with the command line (" + e.what() +
             "); ignored");
        return given;
    }
}

void resetSavedSettings(LiveSettings& live) {
    const LiveSettings defaults = viewerDefaults().live;
    for (const Kept& k : keptSettings()) k.reset(live, defaults);
}

std::string readSavedSettings(const std::string& path) {
    std::ifstream file(path);
    std::stringstream text;
    if (file) text << file.rdbuf();
    return text.str();
}

void writeSavedSettings(const std::string& path, const LiveSettings& live,
                        const WindowPlace& window, const Warn& warn, const std::string& viewText) {
    if (path.empty()) return warn("settings not saved: neither XDG_CONFIG_HOME nor HOME is set");
    std::error_code error;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path(), error);
    // Written beside the file and renamed over it: a crash never leaves half a file.
    const std::string partial = path + ".partial";
    std::ofstream(partial) << savedSettingsText(live, window) << viewText;
    std::filesystem::rename(partial, path, error);
    if (error) warn("cannot save the settings to " + path + ": " + error.message());
}

} // namespace app
