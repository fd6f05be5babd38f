// kept_view.cpp - the window's own lines of the settings file: the panel's layout and the
// recent files.
#include "app/viewer/state/kept_view.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace app {
namespace {

// Narrower than the panel's labels need or wider than any screen: not a width it was dragged to.
constexpr float minPanelWidth = 200.0f, maxPanelWidth = 4000.0f;

std::string trimmed(const std::string& text) {
    const size_t begin = text.find_first_not_of(" \t\r");
    if (begin == std::string::npos) return "";
    return text.substr(begin, text.find_last_not_of(" \t\r") - begin + 1);
}

// One line's value into `view`; the reason when it is not one.
std::string readLine(const std::string& key, const std::string& value, ViewSettings& view) {
    if (key == "panel") {
        if (value != "shown" && value != "hidden") return "expects shown or hidden";
        view.panelVisible = value == "shown";
    } else if (key == "panel-width") {
        float width = 0.0f;
        const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), width);
        if (error != std::errc() || end != value.data() + value.size() || !std::isfinite(width) ||
            width < minPanelWidth || width > maxPanelWidth)
            return "expects a width in pixels";
        view.panelWidth = width;
    } else if (key == "recent") {
        if (value.empty()) return "expects a file's path";
        if (view.recentFiles.size() < maxRecentFiles) view.recentFiles.push_back(value);
    } else {
        return "is not a line the viewer keeps";
    }
    return "";
}

} // namespace

std::string keptViewText(const ViewSettings& view) {
    char width[32];
    std::snprintf(width, sizeof width, "%g", double(view.panelWidth));
    std::string text = std::string(viewLinePrefix) +
                       "panel = " + (view.panelVisible ? "shown" : "hidden") + "\n" +
                       viewLinePrefix + "panel-width = " + width + "\n";
    for (const std::string& path : view.recentFiles)
        if (path.find('\n') == std::string::npos) // one line a path
            text += std::string(viewLinePrefix) + "recent = " + path + "\n";
    return text;
}

void readKeptView(const std::string& text, const std::string& name, ViewSettings& view,
                  const Warn& warn) {
    std::istringstream lines(text);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
        line = trimmed(line);
        if (!isViewLine(line)) continue; // a flag line, a comment or nothing
        const size_t equals = line.find('=');
        const std::string key = trimmed(
            line.substr(std::string(viewLinePrefix).size(),
                        equals == std::string::npos ? std::string::npos
                                                    : equals - std::string(viewLinePrefix).size()));
        const std::string value =
            equals == std::string::npos ? "" : trimmed(line.substr(equals + 1));
        const std::string problem =
            equals == std::string::npos ? "expects NAME = VALUE" : readLine(key, value, view);
        if (!problem.empty())
            warn(name + ":" + std::to_string(number) + ": '" + line + "' " + problem + "; ignored");
    }
}

} // namespace app
