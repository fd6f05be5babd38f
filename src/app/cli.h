// cli.h - command-line options of idview and their parsing. Parsing never touches Vulkan,
// so every flag is unit-tested.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/technique.h" // NarySearch defaults (plain C++)

namespace app {

struct Options {
    bool help = false;
    bool listDevices = false;
    bool listRenderers = false;
    bool headless = false;
    bool validation = false;
    bool syncValidation = false; // implies validation
    std::string device;          // index or name substring; empty: best device
    uint32_t width = 1280;
    uint32_t height = 720;
    uint32_t frames = 10;
    uint32_t msaa = 1;      // samples per pixel of the scene pass: 1, 2, 4 or 8
    std::string screenshot; // PNG path
    std::string idImage;    // raw little-endian uint32 path
    std::string model;      // glTF file; with scene empty too, the default model
    std::string scene;      // built-in or procedural scene spec (scene_source.h)
    std::string parts = "primitives";
    uint32_t copies = 1;
    std::string copyAxes = "xy"; // axes the copies' grid spans (scene/copies.h)
    uint32_t searchBatch = 16;
    // nsearch-*: render::NarySearch, flag by flag.
    uint32_t nsearchN = render::NarySearch{}.n; // defaults measured best on the H100
    bool nsearchGuess = render::NarySearch{}.guess;
    uint32_t nsearchLinear = 8;
    uint32_t nsearchSteps = 16;
    float visible = 1.0f; // draw the first ceil(visible * objects) objects
    bool ignoreMaterials = false;
    bool stats = false;
    std::string exportPath; // write the scene as .glb and exit
    std::string renderer = "per-draw";
    std::string mode = "push";
    float partWeight = 0.5f;
    bool colorizeDraws = false;
    bool sortDraws = true;     // by geometry, then material
    bool gsPassthrough = true; // where the device offers it
    std::string shaderDir;
    bool benchmark = false;         // --renderer and --mode then take comma lists or "all"
    std::string benchmarkOut;       // JSON, or CSV when the name ends in .csv
    std::vector<std::string> given; // flags on the command line, for mode-specific defaults
    // Headless picking: one frame per point picks it and prints a JSON line; `select` is
    // picked first and selected as a click there would (steady highlight in the images).
    struct Pixel {
        uint32_t x = 0, y = 0;
        bool operator==(const Pixel&) const = default;
    };
    std::vector<Pixel> picks;
    std::vector<Pixel> selects; // at most one; a vector keeps "not given" apart from 0,0
    // Exploded view: with `animate` it follows scene::explodeLoop at `time` seconds, or at
    // frame / 60 without --time; otherwise it stays at `explode` (0..1, set by in-process
    // callers such as the tests).
    bool animate = false;
    std::optional<float> time;
    float explode = 0.0f;
    // Viewer: scripted input, one `<seconds> <command> [args]` per line (app/input_script.h).
    std::string script;
};

// A bad command line: main() prints the message and the usage, and exits 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Accepts "--flag value" and "--flag=value". Throws UsageError.
// With --benchmark, flags not given take the benchmark's defaults (the seed's results table:
// 2560x1440, 4x MSAA, 3 copies, 200 frames, all renderers and modes).
Options parseArgs(const std::vector<std::string>& args);

// The names a --renderer or --mode value lists ("all" expands to every one; no-id is never
// in a list: the benchmark adds it itself).
std::vector<std::string> rendererList(const std::string& value);
std::vector<std::string> modeList(const std::string& value);
Options parseArgs(int argc, char** argv);

std::string usage();

} // namespace app
