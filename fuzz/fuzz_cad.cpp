// fuzz_cad.cpp - libFuzzer entry for the CAD loader (STEP, IGES and BREP through Open
// CASCADE): any input must either load into a scene that passes validate() or fail with a
// one-line ModelError that names the file; anything else aborts. Open CASCADE itself is not
// instrumented (Debian's build), so coverage guides the fuzzer through idview's code only,
// while the sanitizers watch every byte idview touches.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <string>
#include <thread>
#include <unistd.h>

#include "scene/cad/cad_loader.h"

namespace {

[[noreturn]] void fail(const char* what, const char* detail) {
    std::fprintf(stderr, "fuzz_cad: %s: %s\n", what, detail);
    std::abort();
}

// The reader is chosen by the file name, so the input goes to a file named after what its
// first bytes look like; mutations that break the header try another reader.
const char* extensionOf(const uint8_t* data, size_t size) {
    const std::string head(reinterpret_cast<const char*>(data), std::min<size_t>(size, 256));
    if (head.find("CASCADE Topology") != std::string::npos) return ".brep";
    if (head.find("ISO-10303-21") != std::string::npos) return ".step";
    return ".iges";
}

// Sets the load's cancel flag after a few seconds, as the viewer's Cancel button would: a
// load that takes longer is stopped, not reported as a hang (the readers' own parsing does
// not look at the flag; libFuzzer's -timeout catches what never stops).
class Watchdog {
  public:
    explicit Watchdog(std::atomic<bool>& cancel)
        : thread_([this, &cancel] {
              std::unique_lock lock(mutex_);
              if (!done_.wait_for(lock, std::chrono::seconds(5), [this] { return finished_; }))
                  cancel = true;
          }) {}
    ~Watchdog() {
        {
            std::lock_guard lock(mutex_);
            finished_ = true;
        }
        done_.notify_one();
        thread_.join();
    }

  private:
    std::mutex mutex_;
    std::condition_variable done_;
    bool finished_ = false;
    std::thread thread_;
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string stem = "/tmp/idview-fuzz-cad-" + std::to_string(::getpid());
    const std::string path = stem + extensionOf(data, size);
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
        if (!out) fail("cannot write the input to", path.c_str());
    }
    scene::CadOptions options;
    options.maxTriangles = 200'000; // a bound on each input's time, as --max-triangles is
    std::atomic<bool> cancel{false};
    try {
        const Watchdog watchdog(cancel);
        scene::CadLoadResult result = scene::loadCad(path, options, {}, 1, &cancel);
        scene::validate(result.scene);
    } catch (const scene::ModelError& e) {
        if (std::strchr(e.what(), '\n') || std::strncmp(e.what(), path.c_str(), path.size()) != 0)
            fail("ModelError breaks the one-line contract", e.what());
    } catch (const std::exception& e) {
        fail("unexpected exception", e.what());
    }
    std::remove(path.c_str());
    return 0;
}
