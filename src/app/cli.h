// cli.h - idview's command line: the options a run is made of and their parsing. The flag
// table writes straight into the settings structs (Options::live, live_settings.h) that
// headless rendering, the benchmark and the viewer then hold unchanged; the rest of Options
// is what to do (one-shot queries, outputs) and how the run starts.
// Parsing never touches Vulkan, so every flag is unit-tested.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/live_settings.h"
#include "render/culling.h"
#include "render/pick.h"
#include "scene/camera_path.h"
#include "scene/census.h"

namespace app {

struct Options {
    // What to do.
    bool help = false;
    bool version = false; // print the version line and exit
    bool listDevices = false;
    bool listRenderers = false;
    bool headless = false;
    bool stats = false;
    bool tree = false;      // print the assembly tree as JSON and exit
    std::string exportPath; // write the scene as .glb and exit
    bool benchmark = false;
    std::string benchmarkOut; // JSON, or CSV when the name ends in .csv
    // --benchmark: what to time, as --renderer and --mode list it (every part-ID technique
    // and every mode when not given). Other runs use live.render.pipeline alone.
    std::vector<const render::Technique*> benchmarkTechniques;
    std::vector<const render::DrawMode*> benchmarkModes;
    std::vector<const render::CullModeEntry*> benchmarkCulling; // --culling (default: all)
    std::vector<float> benchmarkLodErrors; // --lod-error (default: live.render.lod's one value)

    // The device and how it is driven.
    std::string device; // index or name substring; empty: best device
    bool validation = false;
    bool syncValidation = false; // implies validation
    std::string shaderDir;

    // The image.
    uint32_t width = 1280;
    uint32_t height = 720;
    uint32_t frames = 10;
    // Headless and the benchmark: the camera moves along this path, frame by frame over
    // `frames` frames (scene/camera_path.h); the images hold the last frame.
    scene::CameraPath cameraPath = scene::CameraPath::None;
    // In-process callers (the tests): keep every frame's images, not only the last's
    // (HeadlessResult::frames); each frame is then waited for.
    bool keepEveryFrame = false;
    std::string screenshot; // PNG path
    // --thumbnail SIZE: a file manager's preview (thumbnail.h): a SIZExSIZE PNG written to
    // `screenshot` by a child process that is given up on after `seconds` or past `memoryMib`
    // of data memory, leaving no file. size 0: not a thumbnail run.
    struct Thumbnail {
        uint32_t size = 0;
        float seconds = 10.0f;
        uint32_t memoryMib = 4096;
    } thumbnail;
    std::string idImage; // raw little-endian uint32 path
    // Headless picking: one frame per point picks it and prints a JSON line; `selects` is
    // picked first and selected as a click there would (steady highlight in the images).
    struct Pixel {
        uint32_t x = 0, y = 0;
        bool operator==(const Pixel&) const = default;
    };
    std::vector<Pixel> picks;
    std::vector<Pixel> selects; // at most one; a vector keeps "not given" apart from 0,0
    // Headless box selection: the parts inside the rectangle become the selection and one
    // JSON line {"rect","parts","count"} is printed. Taken after --select, before --pick.
    std::optional<render::PartSetQuery> selectRect;
    // Headless measuring: both points picked (after --pick) and one JSON line
    // {"p0","p1","distance","delta","parts"} printed, from the world points their depths give.
    std::optional<std::array<Pixel, 2>> measure;
    // Headless face properties: each point picked (after --measure) and one JSON line of the
    // part's surface printed (scene/face_info.h).
    std::vector<Pixel> faceInfos;
    // Exact inspection (scene/inspect.h), printed as JSON lines without rendering, as --tree
    // is: the minimum distance between two unique parts; an object's volume, area, centre of
    // mass and box, or every object's and their sum (propertiesAll).
    std::optional<std::array<uint32_t, 2>> distance;
    std::optional<uint32_t> propertiesObject;
    bool propertiesAll = false;
    // Headless edges: each point picked (after --face-info) and one JSON line of the edge of
    // its part's face nearest it (scene/edge_info.h), within scene::edgePickPixels.
    std::vector<Pixel> edgeInfos;
    // Headless visibility: the parts --hide names are not drawn; --isolate draws only its
    // parts. Unique part IDs; checked against the scene when it is loaded.
    std::vector<uint32_t> hide, isolate;
    bool visibleParts = false; // print {"count","parts"} of the last frame's ID image
    // --census VIEWSxSIZE (app/census.h): views 0 means no census. --census-csv writes its
    // lines as CSV too; --census-export the exterior (.glb, or .step/.stp for CAD models).
    scene::CensusSpec census;
    std::string censusCsv, censusExport;

    // What is drawn, how and from where: all a headless run or the benchmark renders with,
    // and all the viewer is handed to edit while it runs (live_settings.h).
    LiveSettings live;

    // Viewer: scripted input, one `<seconds> <command> [args]` per line (viewer/script.h),
    // and the event lines (title, selection, opened, screenshot, reload) on stdout.
    std::string script;
    bool printEvents = false;
    // Viewer: read the settings kept between runs at start and write them at exit
    // (saved_settings.h); --no-saved-settings does neither.
    bool savedSettings = true;
    // Viewer: where the window opens (its top left corner, screen coordinates), kept between
    // runs with --size (saved_settings.h); pulled onto the screen if it lies off it.
    std::optional<std::array<int, 2>> windowPos;

    std::vector<std::string> given; // flags on the command line, for mode-specific defaults
};

// A bad command line: main() prints the message and a pointer to --help, and exits 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Whether the flag `name` was on the command line (Options::given).
bool given(const Options& options, const char* name);

// Whether --census-export's FILE is written as STEP (.step, .stp) rather than glTF (.glb).
bool censusExportsStep(const std::string& path);

// Accepts "--flag value" and "--flag=value", and one argument that is no flag: the model's path
// or file:// URI, as --model (a launcher's `idview %f`). Throws UsageError.
// With --benchmark, flags not given take the benchmark's defaults (the seed's results table:
// 2560x1440, 4x MSAA, 3 copies, 200 frames, all renderers, modes and culling modes).
Options parseArgs(const std::vector<std::string>& args);
Options parseArgs(int argc, char** argv);
// The same, the flags applied over `start` instead of the settings structs' defaults.
Options parseArgs(const std::vector<std::string>& args, Options start);

// What the viewer opens on before its saved settings and the command line: the settings
// structs' defaults, but the technique and per-draw mode README's "Which technique?"
// recommends. Headless runs and the benchmark keep the registries' first rows, which their
// tests and scripted comparisons rely on.
Options viewerDefaults();
// The window the viewer opens: --size and --window-pos.
WindowPlace windowPlace(const Options& options);
// The flags given that only headless runs read (Flag::headlessOnly), for the viewer to say
// it ignores them.
std::vector<std::string> ignoredByViewer(const Options& options);

// The registry entries a --renderer or --mode value names: a comma list, or "all" (every
// one; for --renderer every part-ID technique, the benchmark adds the no-id floor itself).
std::vector<const render::Technique*> techniqueList(const std::string& value);
std::vector<const render::DrawMode*> modeList(const std::string& value);
std::vector<const render::CullModeEntry*> cullingList(const std::string& value);

// The usage's first two lines, which the manual page's SYNOPSIS and NAME print too
// (src/tools/idview_docs.cpp).
inline constexpr const char* usageSynopsis = "idview [OPTIONS] [FILE]";
inline constexpr const char* programSummary =
    "Renders a CAD assembly and knows which part is at every pixel.";
// --help: those lines, every flag group by group, and the exit codes (app/exit_code.h).
std::string usage();

} // namespace app
