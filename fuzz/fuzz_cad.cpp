// fuzz_cad.cpp - libFuzzer entry for the CAD loader (STEP, IGES and BREP through Open
// CASCADE), in process as a worker reads a whole file, and for the STEP splitter, which lexes
// every STEP file before Open CASCADE sees it: any input must either load into a scene that
// passes validate() or fail with a one-line ModelError that names the file; the splitter must
// split it (every piece's text made) or refuse it in one line; anything else aborts. Open CASCADE
// itself is not instrumented (Debian's build), so coverage guides the fuzzer through idview's code
// only, while the sanitizers watch every byte idview touches.
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <unistd.h>

#include "scene/cad/cad_loader.h"
#include "scene/step/step_split.h"
#include "util/deadline.h"

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

// The load's cancel flag is set after a few seconds (util::Deadline), as the viewer's Cancel
// button would: a load that takes longer is stopped, not reported as a hang (the readers' own
// parsing does not look at the flag; libFuzzer's -timeout catches what never stops).
constexpr std::chrono::seconds kCancelAfter{5};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string stem = "/tmp/idview-fuzz-cad-" + std::to_string(::getpid());
    const std::string path = stem + extensionOf(data, size);
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
        if (!out) fail("cannot write the input to", path.c_str());
    }
    if (std::strcmp(extensionOf(data, size), ".step") == 0) {
        try {
            const scene::step::StepSplit split(path);
            if (const auto& refused = split.notSplit()) {
                if (refused->reason.empty() || refused->reason.find('\n') != std::string::npos)
                    fail("the splitter's refusal breaks the one-line contract",
                         refused->reason.c_str());
            } else {
                (void)split.skeleton().size();
                for (size_t i = 0; i < split.pieces().size(); ++i)
                    if (split.pieceText(i).size() != split.pieces()[i].bytes)
                        fail("a piece's text is not its announced size", path.c_str());
            }
        } catch (const std::runtime_error& e) {
            fail("the splitter threw", e.what()); // only a file it cannot map may
        }
    }
    scene::CadOptions options;
    options.maxTriangles = 200'000; // a bound on each input's time, as --max-triangles is
    std::atomic<bool> cancel{false};
    try {
        const util::Deadline watchdog(kCancelAfter, [&cancel] { cancel = true; });
        scene::CadLoadResult result = scene::loadCadInProcess(path, options, {}, 1, &cancel);
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
