// file_browser.h - the panel's own file browser, for a desktop with neither the file chooser
// portal nor zenity: a folder's sub-folders and the model files idview reads (scene/formats.h),
// a filter typed over them that also takes a whole path, the folders of the recent files, and
// a highlighted entry the arrow keys move. Plain C++ over std::filesystem (no ImGui), so it is
// unit-tested; panel_browser.cpp draws it.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace app {

class FileBrowser {
  public:
    struct Entry {
        std::string name; // "..", a folder's name, or a file's
        bool folder = false;
        bool operator==(const Entry&) const = default;
    };
    // What activating an entry (Enter, a double-click, Open) did.
    struct Outcome {
        std::optional<std::string> open; // a model file to open: the browser is done
        std::string problem;             // a typed path that is neither folder nor model file
    };

    // Opens at `folder` (made absolute; an unreadable or missing one falls back to its
    // nearest existing parent). `recentFiles` gives the recent folders, newest first.
    FileBrowser(const std::string& folder, const std::vector<std::string>& recentFiles);

    const std::string& folder() const { return folder_; }
    const std::vector<std::string>& recentFolders() const { return recentFolders_; }
    // The entries the filter keeps: ".." first (but at the root), then folders, then model
    // files, each by name without regard to case.
    const std::vector<Entry>& shown() const { return shown_; }
    size_t highlighted() const { return highlighted_; }
    size_t entryCount() const { return all_.size(); } // in the folder, whatever the filter
    // Why the folder could not be read, or "".
    const std::string& problem() const { return problem_; }

    // The filter: a part of a name (case does not matter), or a path ("/...", "~/...").
    std::string& filterText() { return filter_; }
    void filterChanged(); // after the text changed: the entries shown again, first highlighted
    void highlight(size_t index);
    void move(int steps); // the arrow keys: up (-1) or down (+1), stopping at the ends
    void goTo(const std::string& folder);
    void up();
    // The highlighted entry, or the typed path when the filter holds one: a folder is entered,
    // a model file returned to open.
    Outcome activate();
    Outcome activate(size_t index);

    // A line for the event log: the folder, how many entries show of how many, and the first
    // names.
    std::string describe() const;
    // describe()'s line when it changed since the last call, for the event records.
    std::optional<std::string> news();
    // A typed path that led nowhere, until the filter changes.
    const std::string& note() const { return note_; }
    void note(std::string text) { note_ = std::move(text); }

    bool wantsFocus = true; // the filter takes the keys in the next frame (opened, a folder)

  private:
    void list();
    Outcome activatePath(const std::string& typed);

    std::string folder_, filter_, problem_, told_, note_;
    std::vector<Entry> all_, shown_;
    std::vector<std::string> recentFolders_;
    size_t highlighted_ = 0;
};

} // namespace app
