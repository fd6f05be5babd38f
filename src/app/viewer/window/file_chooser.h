// file_chooser.h - Open...: the desktop's own file chooser, off the UI thread. The XDG
// desktop portal's FileChooser (through libportal, when idview was built with it and a D-Bus
// session with a portal runs), else zenity --file-selection when it is on PATH (a run-time
// choice, never a build dependency), else none: the viewer then points to its open field.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace app {

// A named set of glob patterns ("*.step"), as both choosers take them.
struct FileFilter {
    std::string name;
    std::vector<std::string> patterns;
};

// What the chooser said.
struct ChooserResult {
    enum class Kind { Chosen, Cancelled, Unavailable };
    Kind kind = Kind::Unavailable;
    std::string path; // Chosen: the file
    std::string via;  // "portal" or "zenity"; Unavailable: why neither could be used
};

class FileChooser {
  public:
    FileChooser() = default;
    ~FileChooser(); // closes a chooser still open (the viewer is quitting) and waits for it
    FileChooser(const FileChooser&) = delete;
    FileChooser& operator=(const FileChooser&) = delete;

    // Opens a chooser titled `title` with `filters` (the first is chosen at first) on a worker
    // thread; `done` is called on that thread when the answer is in (to wake the UI loop,
    // which then polls). False when one is open already.
    bool start(const std::string& title, const std::vector<FileFilter>& filters,
               std::function<void()> done);
    // The answer, once, on the UI thread; nullopt while the chooser is open or none was.
    std::optional<ChooserResult> poll();
    // Started and its answer not yet taken by poll().
    bool open() const { return job_ != nullptr; }

    struct Job; // shared by the UI thread and the worker (file_chooser.cpp)

  private:
    std::shared_ptr<Job> job_;
    std::thread worker_;
};

// The portal's answer (portal_chooser.cpp), or nullopt when no portal can be asked (no
// session bus, no portal service, or idview built without libportal): then zenity is tried.
// `onCancel` receives the function that closes the portal's dialog from another thread.
std::optional<ChooserResult> askPortal(const std::string& title,
                                       const std::vector<FileFilter>& filters,
                                       const std::function<void(std::function<void()>)>& onCancel);

} // namespace app
