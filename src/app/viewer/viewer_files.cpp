// viewer_files.cpp - Open...: the desktop's file chooser (file_chooser.h), its answer, and
// the panel's own file browser where there is none (file_browser.h).
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/viewer/viewer.h"
#include "scene/formats.h"

namespace app {

// A format's extensions as chooser globs, in either case: the choosers' globs are
// case-sensitive.
namespace {

std::vector<std::string> globsOf(const scene::ModelFormat& format) {
    std::vector<std::string> globs;
    for (std::string_view ext : format.extensions) {
        std::string upper(ext);
        for (char& c : upper) c = char(std::toupper(static_cast<unsigned char>(c)));
        globs.push_back(std::string("*").append(ext));
        globs.push_back(std::string("*").append(upper));
    }
    return globs;
}

} // namespace

void Viewer::chooseFile() {
    // The formats openDrops takes (scene/formats.h): all of them, then each, then any file.
    std::vector<FileFilter> filters = {{"Models", {}}};
    for (const scene::ModelFormat& format : scene::modelFormats()) {
        filters.push_back({std::string(format.name) + " files", globsOf(format)});
        filters[0].patterns.insert(filters[0].patterns.end(), filters.back().patterns.begin(),
                                   filters.back().patterns.end());
    }
    filters.push_back({"All files", {"*"}});
    if (noChooser_) {
        openBrowser();
        events_.say("file_chooser", [](util::JsonWriter& j) { j.member("state", "none"); });
        return;
    }
    // The answer wakes the loop, which may be resting in its event wait.
    if (chooser_.start("Open a model - idview", filters, [] { glfwPostEmptyEvent(); }))
        events_.say("file_chooser", [](util::JsonWriter& j) { j.member("state", "open"); });
}

void Viewer::focusOpenField() {
    view_.panelVisible = true;
    view_.focusOpen = true;
}

void Viewer::openBrowser() {
    view_.panelVisible = true;
    const std::string& source = scene_.loaded().source;
    std::error_code error;
    std::string folder;
    if (!source.empty() && std::filesystem::is_regular_file(source, error))
        folder = std::filesystem::path(source).parent_path().string();
    else if (!view_.recentFiles.empty())
        folder = std::filesystem::path(view_.recentFiles.front()).parent_path().string();
    else if (const char* home = std::getenv("HOME"))
        folder = home;
    else
        folder = std::filesystem::current_path(error).string();
    view_.browser.emplace(folder, view_.recentFiles);
}

void Viewer::chosen(const ChooserResult& result) {
    switch (result.kind) {
    case ChooserResult::Kind::Chosen:
        events_.say("file_chooser", [&](util::JsonWriter& j) {
            j.member("state", "chosen").member("path", result.path).member("via", result.via);
        });
        input_.onDrop(result.path); // opened as a dropped file
        break;
    case ChooserResult::Kind::Cancelled:
        events_.say("file_chooser", [](util::JsonWriter& j) { j.member("state", "cancelled"); });
        break;
    case ChooserResult::Kind::Unavailable:
        // The panel's own browser instead, where the model shown lies (else a recent folder,
        // else home); the keys go to its filter.
        // Said once: the next Open... goes to the browser at once.
        openBrowser();
        noChooser_ = true;
        std::fprintf(stderr, "idview: no desktop file chooser: %s; browsing in the panel\n",
                     result.via.c_str());
        events_.say("file_chooser", [](util::JsonWriter& j) { j.member("state", "none"); });
        break;
    }
}

} // namespace app
