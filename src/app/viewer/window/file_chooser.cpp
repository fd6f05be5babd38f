// file_chooser.cpp - the chooser's worker thread and the zenity fallback: a child process
// whose standard output is the chosen path, killed if the viewer quits first.
#include "app/viewer/window/file_chooser.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <mutex>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace app {

struct FileChooser::Job {
    std::mutex mutex;
    std::optional<ChooserResult> result;
    bool quitting = false;             // the viewer closes: no new chooser starts
    pid_t child = 0;                   // zenity while it runs
    std::function<void()> closePortal; // while the portal's dialog is open
};

namespace {

// zenity's exit codes: 0 a file chosen, 1 cancelled or closed; anything else (or no zenity)
// means it could not show its dialog.
ChooserResult runZenity(const std::string& title, const std::vector<FileFilter>& filters,
                        FileChooser::Job& job) {
    std::vector<std::string> args = {"zenity", "--file-selection", "--title=" + title};
    for (const FileFilter& filter : filters) {
        std::string patterns;
        for (const std::string& p : filter.patterns) patterns += " " + p;
        args.push_back("--file-filter=" + filter.name + " |" + patterns);
    }
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    int out[2];
    if (pipe(out) != 0) return {ChooserResult::Kind::Unavailable, "", "no pipe for zenity"};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, out[0]);
    pid_t pid = 0;
    int spawned = 0;
    {
        std::lock_guard lock(job.mutex);
        spawned = job.quitting
                      ? ECANCELED
                      : posix_spawnp(&pid, "zenity", &actions, nullptr, argv.data(), environ);
        if (spawned == 0) job.child = pid;
    }
    posix_spawn_file_actions_destroy(&actions);
    close(out[1]);
    std::string text;
    char buffer[4096];
    for (ssize_t n; spawned == 0 && (n = read(out[0], buffer, sizeof buffer)) != 0;)
        if (n > 0)
            text.append(buffer, size_t(n));
        else if (errno != EINTR)
            break;
    close(out[0]);
    if (spawned != 0) return {ChooserResult::Kind::Unavailable, "", "zenity is not on PATH"};
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    {
        std::lock_guard lock(job.mutex);
        job.child = 0;
    }
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && !text.empty())
        return {ChooserResult::Kind::Chosen, text, "zenity"};
    if (WIFEXITED(status) && WEXITSTATUS(status) == 1)
        return {ChooserResult::Kind::Cancelled, "", "zenity"};
    // POSIX shells answer 127 for a program not found: a zenity that cannot run at all.
    return {ChooserResult::Kind::Unavailable, "", "zenity could not open its dialog"};
}

} // namespace

#ifndef IDVIEW_HAVE_LIBPORTAL
// Built without libportal (CMakeLists.txt): no portal to ask, zenity is tried at once.
std::optional<ChooserResult> askPortal(const std::string&, const std::vector<FileFilter>&,
                                       const std::function<void(std::function<void()>)>&) {
    return std::nullopt;
}
#endif

namespace {

// The portal's answer, else zenity's, on the worker.
ChooserResult ask(const std::string& title, const std::vector<FileFilter>& filters,
                  FileChooser::Job& job) {
    std::optional<ChooserResult> answer =
        askPortal(title, filters, [&job](std::function<void()> close) {
            std::lock_guard lock(job.mutex);
            job.closePortal = std::move(close);
            if (job.quitting && job.closePortal) job.closePortal();
        });
    {
        std::lock_guard lock(job.mutex);
        job.closePortal = nullptr;
    }
    if (!answer || answer->kind == ChooserResult::Kind::Unavailable)
        answer = runZenity(title, filters, job);
    if (answer->kind == ChooserResult::Kind::Unavailable)
        answer->via = "neither the desktop portal nor zenity is there (" + answer->via + ")";
    return *answer;
}

} // namespace

FileChooser::~FileChooser() {
    if (job_) {
        std::lock_guard lock(job_->mutex);
        job_->quitting = true;
        if (job_->child > 0) kill(job_->child, SIGTERM); // our own zenity
        if (job_->closePortal) job_->closePortal();
    }
    if (worker_.joinable()) worker_.join();
}

bool FileChooser::start(const std::string& title, const std::vector<FileFilter>& filters,
                        std::function<void()> done) {
    if (job_) return false;
    if (worker_.joinable()) worker_.join(); // the last one's thread, done already
    job_ = std::make_shared<Job>();
    worker_ = std::thread([job = job_, title, filters, done = std::move(done)] {
        std::optional<ChooserResult> answer;
        try {
            answer = ask(title, filters, *job);
        } catch (const std::exception& e) {
            // Out of memory, no thread or process to start: the viewer says so in its panel,
            // as it does when no chooser is there.
            answer = ChooserResult{ChooserResult::Kind::Unavailable,
                                   {},
                                   std::string("the file chooser failed: ") + e.what()};
        }
        {
            std::lock_guard lock(job->mutex);
            job->result = std::move(answer);
        }
        done();
    });
    return true;
}

std::optional<ChooserResult> FileChooser::poll() {
    if (!job_) return std::nullopt;
    std::optional<ChooserResult> result;
    {
        std::lock_guard lock(job_->mutex);
        result = std::move(job_->result);
    }
    if (result) job_.reset(); // the thread has only done() left: joined at the next start
    return result;
}

} // namespace app
