// thumbnail.cpp - idview --thumbnail: the preview is rendered by a child process, so that a
// hostile or huge file costs the file manager a few seconds at most: a watchdog kills the
// child's whole process group (its Open CASCADE load workers too) at the deadline, and a
// data-memory limit makes the child refuse what does not fit. The PNG appears only whole.
#include "app/thumbnail.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>

#include "app/headless.h"
#include "util/deadline.h"

namespace app {
namespace {

void refuse(const Options& options, const std::string& why) {
    const std::string& model = options.live.scene.model;
    std::fprintf(stderr, "idview: error: %s: no thumbnail: %s\n",
                 model.empty() ? "the default model" : model.c_str(), why.c_str());
}

// The finished PNG in `temp` becomes `out`. A file manager may make `out` itself and read the
// thumbnail back through the descriptor it keeps (tumbler, Thunar's thumbnailer, does), so an
// `out` that is there already is filled in place; else the rename makes it appear whole.
// False with errno set when neither works.
bool publish(const std::string& temp, const std::string& out) {
    const int to = open(out.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (to < 0) return std::rename(temp.c_str(), out.c_str()) == 0;
    const int from = open(temp.c_str(), O_RDONLY | O_CLOEXEC);
    bool written = from >= 0;
    char buffer[65536];
    for (ssize_t n = 0; written && (n = read(from, buffer, sizeof buffer)) != 0;)
        written = n > 0 && write(to, buffer, size_t(n)) == n;
    const int error = errno;
    if (from >= 0) close(from);
    written = close(to) == 0 && written;
    errno = error;
    if (written) std::remove(temp.c_str());
    return written;
}

// The child: its own process group (what the watchdog kills), gone with its parent (a file
// manager may kill the thumbnailer it waited too long for), under the memory cap, quiet on
// stdout (the headless summary line is for people at a terminal).
[[noreturn]] void renderChild(Options options, const std::string& temp, pid_t parent) {
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) std::_Exit(1); // the parent died before the line above
    // RLIMIT_DATA rather than the address space: GPU drivers reserve large address ranges
    // they never fill, while the heap, lavapipe's memory and the meshes all count here.
    const rlim_t bytes = rlim_t(options.thumbnail.memoryMib) << 20;
    const rlimit limit{bytes, bytes}, noCore{0, 0};
    setrlimit(RLIMIT_DATA, &limit);
    setrlimit(RLIMIT_CORE, &noCore); // a crash on a hostile file leaves no core file behind
    if (const int null = open("/dev/null", O_WRONLY); null >= 0) dup2(null, STDOUT_FILENO);
    options.screenshot = temp;
    int code = 1;
    try {
        code = runHeadless(options);
    } catch (const std::bad_alloc&) {
        refuse(options, "out of memory (over " + std::to_string(options.thumbnail.memoryMib) +
                            " MiB, --thumbnail-memory)");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "idview: error: %s\n", e.what());
    }
    std::fflush(nullptr);
    std::exit(code);
}

// waitpid's status for `child`; `timedOut` says the watchdog killed its process group at the
// deadline.
int waitWithDeadline(pid_t child, float seconds, bool& timedOut) {
    std::atomic<bool> killed = false;
    int status = 0;
    {
        const util::Deadline watchdog(
            std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                std::chrono::duration<float>(seconds)),
            [&] {
                killed = true;
                kill(-child, SIGKILL);
            });
        while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
        }
    }
    timedOut = killed && WIFSIGNALED(status);
    return status;
}

} // namespace

int runThumbnail(const Options& options) {
    // Beside the output, so the rename is atomic; named by this process, so two thumbnailers
    // writing the same file do not share it.
    const std::string temp = options.screenshot + ".idview-" + std::to_string(getpid()) + ".tmp";
    std::fflush(nullptr);
    const pid_t parent = getpid();
    const pid_t child = fork();
    if (child < 0) throw std::runtime_error(std::string("cannot start: ") + std::strerror(errno));
    if (child == 0) renderChild(options, temp, parent);
    setpgid(child, child); // here too, so the watchdog's kill cannot come before the child's
    bool timedOut = false;
    const int status = waitWithDeadline(child, options.thumbnail.seconds, timedOut);
    kill(-child, SIGKILL); // whatever of its group is left (workers die with it anyway)
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && publish(temp, options.screenshot))
        return 0;
    const int renameError = errno;
    std::remove(temp.c_str());
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g", double(options.thumbnail.seconds));
    if (timedOut)
        refuse(options, std::string("gave up after ") + seconds + " s (--thumbnail-timeout)");
    else if (WIFSIGNALED(status))
        refuse(options, std::string("the renderer ended on signal ") + strsignal(WTERMSIG(status)) +
                            " (under --thumbnail-memory " +
                            std::to_string(options.thumbnail.memoryMib) + " MiB)");
    else if (WEXITSTATUS(status) == 0)
        refuse(options, "cannot write " + options.screenshot + ": " + std::strerror(renameError));
    // else: the child said why in its own line
    return WIFEXITED(status) && WEXITSTATUS(status) != 0 ? WEXITSTATUS(status) : 1;
}

} // namespace app
