// cli.h - command-line options of idview and their parsing. Parsing never touches Vulkan,
// so every flag is unit-tested.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace app {

struct Options {
    bool help = false;
    bool listDevices = false;
    bool listRenderers = false;
    bool headless = false;
    bool validation = false;
    std::string device; // index or name substring; empty: best device
    uint32_t width = 1280;
    uint32_t height = 720;
    uint32_t frames = 10;
    std::string screenshot; // PNG path
    std::string idImage;    // raw little-endian uint32 path
    std::string scene = "assembly";
    std::string renderer = "per-draw";
    std::string mode = "push";
    float partWeight = 0.5f;
    bool colorizeDraws = false;
    std::string shaderDir;
};

// A bad command line: main() prints the message and the usage, and exits 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Accepts "--flag value" and "--flag=value". Throws UsageError.
Options parseArgs(const std::vector<std::string>& args);
Options parseArgs(int argc, char** argv);

std::string usage();

} // namespace app
