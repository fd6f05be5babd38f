// file_browser.cpp - listing, filtering and moving through folders for the panel's browser.
#include "app/viewer/state/file_browser.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "scene/formats.h"

namespace fs = std::filesystem;

namespace app {
namespace {

std::string lower(std::string text) {
    for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

bool isPath(const std::string& text) {
    return !text.empty() && (text[0] == '/' || text.rfind("~/", 0) == 0 || text == "~");
}

// "~" and "~/x" to the home folder; "" when there is none.
std::string expanded(const std::string& text) {
    if (text.empty() || text[0] != '~') return text;
    const char* home = std::getenv("HOME");
    return home ? std::string(home) + text.substr(1) : text;
}

// The nearest folder that exists at or above `path`.
std::string existingFolder(fs::path path) {
    std::error_code error;
    path = fs::absolute(path, error).lexically_normal();
    while (!path.empty() && !fs::is_directory(path, error)) {
        if (path == path.parent_path()) break;
        path = path.parent_path();
    }
    std::string text = path.string();
    if (text.size() > 1 && text.back() == '/') text.pop_back();
    return text.empty() ? "/" : text;
}

} // namespace

FileBrowser::FileBrowser(const std::string& folder, const std::vector<std::string>& recentFiles) {
    for (const std::string& file : recentFiles) {
        const std::string parent = fs::path(file).parent_path().string();
        std::error_code error;
        if (!parent.empty() && fs::is_directory(parent, error) &&
            std::find(recentFolders_.begin(), recentFolders_.end(), parent) == recentFolders_.end())
            recentFolders_.push_back(parent);
    }
    goTo(folder);
}

void FileBrowser::goTo(const std::string& folder) {
    folder_ = existingFolder(expanded(folder));
    filter_.clear();
    list();
}

void FileBrowser::up() {
    goTo(fs::path(folder_).parent_path().string());
}

// The folder's sub-folders (not hidden ones) and the files of the formats idview reads.
void FileBrowser::list() {
    all_.clear();
    problem_.clear();
    std::error_code error;
    fs::directory_iterator it(folder_, fs::directory_options::skip_permission_denied, error);
    for (; !error && it != fs::directory_iterator(); it.increment(error)) {
        const std::string name = it->path().filename().string();
        if (name.empty() || name[0] == '.') continue;
        std::error_code kind;
        if (it->is_directory(kind))
            all_.push_back({name, true});
        else if (scene::formatOfName(name))
            all_.push_back({name, false});
    }
    if (error) problem_ = folder_ + ": " + error.message();
    std::sort(all_.begin(), all_.end(), [](const Entry& a, const Entry& b) {
        if (a.folder != b.folder) return a.folder;
        return lower(a.name) < lower(b.name);
    });
    if (folder_ != "/") all_.insert(all_.begin(), {"..", true});
    filterChanged();
}

void FileBrowser::filterChanged() {
    note_.clear();
    shown_.clear();
    const std::string part = lower(filter_);
    for (const Entry& entry : all_)
        if (isPath(filter_) || lower(entry.name).find(part) != std::string::npos)
            shown_.push_back(entry);
    // The first entry below "..", which Backspace and Up reach: Enter takes the first match.
    highlighted_ = shown_.size() > 1 && shown_[0].name == ".." ? 1 : 0;
}

void FileBrowser::highlight(size_t index) {
    if (index < shown_.size()) highlighted_ = index;
}

void FileBrowser::move(int steps) {
    if (shown_.empty()) return;
    const long next = long(highlighted_) + steps;
    highlighted_ = size_t(std::clamp(next, 0L, long(shown_.size()) - 1));
}

FileBrowser::Outcome FileBrowser::activate() {
    if (isPath(filter_)) return activatePath(filter_);
    return activate(highlighted_);
}

FileBrowser::Outcome FileBrowser::activate(size_t index) {
    if (index >= shown_.size()) return {};
    const Entry entry = shown_[index];
    if (entry.name == "..") {
        up();
        return {};
    }
    const std::string path = (fs::path(folder_) / entry.name).string();
    if (entry.folder) {
        goTo(path);
        return {};
    }
    return {path, ""};
}

FileBrowser::Outcome FileBrowser::activatePath(const std::string& typed) {
    const std::string path = expanded(typed);
    std::error_code error;
    if (fs::is_directory(path, error)) {
        goTo(path);
        return {};
    }
    if (fs::exists(path, error)) return {path, ""}; // its reader says if it is no model
    return {std::nullopt, typed + ": no such file or folder"};
}

std::string FileBrowser::describe() const {
    std::string line = folder_ + ": " + std::to_string(shown_.size()) + " of " +
                       std::to_string(all_.size()) + " entries";
    for (size_t i = 0; i < shown_.size() && i < 12; ++i)
        line += (i ? ", " : ": ") + shown_[i].name + (shown_[i].folder ? "/" : "");
    if (shown_.size() > 12) line += ", ...";
    if (!shown_.empty()) line += "; highlighted " + shown_[highlighted_].name;
    return line;
}

std::optional<std::string> FileBrowser::news() {
    std::string line = describe();
    if (line == told_) return std::nullopt;
    told_ = line;
    return line;
}

} // namespace app
