// cli.cpp - flag table, value parsing and usage text.
#include "app/cli.h"

#include <algorithm>
#include <charconv>
#include <functional>

#include "app/scene_source.h"
#include "render/technique.h"
#include "scene/copies.h"

namespace app {
namespace {

uint32_t parseCount(const std::string& flag, const std::string& text, uint32_t min, uint32_t max) {
    uint32_t value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || value < min || value > max)
        throw UsageError(flag + " expects a whole number from " + std::to_string(min) + " to " +
                         std::to_string(max) + ", not '" + text + "'");
    return value;
}

float parseFraction(const std::string& flag, const std::string& text) {
    try {
        size_t used = 0;
        float value = std::stof(text, &used);
        if (used == text.size() && value >= 0.0f && value <= 1.0f) return value;
    } catch (const std::exception&) {
    }
    throw UsageError(flag + " expects a number from 0 to 1, not '" + text + "'");
}

float parseSeconds(const std::string& flag, const std::string& text) {
    try {
        size_t used = 0;
        float value = std::stof(text, &used);
        if (used == text.size() && value >= 0.0f && value <= 1e6f) return value;
    } catch (const std::exception&) {
    }
    throw UsageError(flag + " expects seconds from 0 to 1000000, not '" + text + "'");
}

void parseSize(const std::string& text, Options& o) {
    auto x = text.find('x');
    if (x == std::string::npos) throw UsageError("--size expects WIDTHxHEIGHT, not '" + text + "'");
    o.width = parseCount("--size width", text.substr(0, x), 1, 16384);
    o.height = parseCount("--size height", text.substr(x + 1), 1, 16384);
}

Options::Pixel parsePixel(const std::string& flag, const std::string& text) {
    auto comma = text.find(',');
    if (comma == std::string::npos) throw UsageError(flag + " expects X,Y, not '" + text + "'");
    return {parseCount(flag + " x", text.substr(0, comma), 0, 16383),
            parseCount(flag + " y", text.substr(comma + 1), 0, 16383)};
}

struct Flag {
    const char* name;
    const char* value; // nullptr for a switch
    const char* help;
    std::function<void(Options&, const std::string&)> apply;
};

const std::vector<Flag>& flags() {
    static const std::vector<Flag> table = {
        {"--help", nullptr, "print this text", [](Options& o, auto&) { o.help = true; }},
        {"--headless", nullptr, "render offscreen without a window or surface",
         [](Options& o, auto&) { o.headless = true; }},
        {"--size", "WxH", "render size in pixels (default 1280x720)",
         [](Options& o, auto& v) { parseSize(v, o); }},
        {"--msaa", "N", "samples per pixel: 1 (default), 2, 4 or 8, as the device offers",
         [](Options& o, auto& v) {
             o.msaa = parseCount("--msaa", v, 1, 8);
             if (o.msaa & (o.msaa - 1)) throw UsageError("--msaa expects 1, 2, 4 or 8, not " + v);
         }},
        {"--frames", "N", "frames to render headless (default 10); files hold the last one",
         [](Options& o, auto& v) { o.frames = parseCount("--frames", v, 1, 1000000); }},
        {"--screenshot", "FILE", "write the last frame's colour image as PNG",
         [](Options& o, auto& v) { o.screenshot = v; }},
        {"--id-image", "FILE",
         "write the last frame's part IDs: W*H little-endian uint32, row-major, top row first, "
         "0xFFFFFFFF where no part is",
         [](Options& o, auto& v) { o.idImage = v; }},
        {"--model", "FILE", "open a glTF model (.gltf or .glb); default: assets/default.glb",
         [](Options& o, auto& v) { o.model = v; }},
        {"--scene", "SPEC",
         "built-in scene instead of a model: assembly, tiles (the test layout) or "
         "procedural[:preset=small|car-like][,seed=N]",
         [](Options& o, auto& v) {
             try {
                 parseSceneSpec(v);
             } catch (const std::invalid_argument& e) {
                 throw UsageError(std::string("--scene: ") + e.what());
             }
             o.scene = v;
         }},
        {"--parts", "MODE",
         "glTF parts: primitives (one part per primitive, default) or components (one per "
         "connected component, recovers CAD faces merged by an exporter)",
         [](Options& o, auto& v) {
             if (v != "primitives" && v != "components")
                 throw UsageError("--parts expects primitives or components, not '" + v + "'");
             o.parts = v;
         }},
        {"--copies", "N", "replicate the model N times on a grid (default 1)",
         [](Options& o, auto& v) { o.copies = parseCount("--copies", v, 1, 1000000); }},
        {"--copy-axes", "AXES",
         "axes the copies' grid spans: any of x, y, z, e.g. x, xz or xyz (default xy)",
         [](Options& o, auto& v) {
             try {
                 scene::parseCopyAxes(v);
             } catch (const std::invalid_argument& e) {
                 throw UsageError(std::string("--copy-axes: ") + e.what());
             }
             o.copyAxes = v;
         }},
        {"--search-batch", "N", "parts per draw of the search techniques, 1 to 32 (default 16)",
         [](Options& o, auto& v) { o.searchBatch = parseCount("--search-batch", v, 1, 32); }},
        {"--nsearch-n", "N", "nsearch renderers: offsets read per step, 3 to 16 (default 3)",
         [](Options& o, auto& v) { o.nsearchN = parseCount("--nsearch-n", v, 3, 16); }},
        {"--nsearch-guess", "on|off",
         "nsearch renderers: start at the part a uniform part size predicts (default off)",
         [](Options& o, auto& v) {
             if (v != "on" && v != "off")
                 throw UsageError("--nsearch-guess expects on or off, not '" + v + "'");
             o.nsearchGuess = v == "on";
         }},
        {"--nsearch-linear", "N",
         "nsearch renderers: scan linearly from N parts left, 0 to 64 (default 8)",
         [](Options& o, auto& v) { o.nsearchLinear = parseCount("--nsearch-linear", v, 0, 64); }},
        {"--nsearch-steps", "N",
         "nsearch renderers: N-ary steps at most, 1 to 64, a linear scan finishes (default 16)",
         [](Options& o, auto& v) { o.nsearchSteps = parseCount("--nsearch-steps", v, 1, 64); }},
        {"--visible", "F",
         "draw only the first ceil(F * objects) objects in scene order, 0 to 1 (default 1)",
         [](Options& o, auto& v) { o.visible = parseFraction("--visible", v); }},
        {"--ignore-materials", nullptr,
         "shade every object with one neutral grey, so only part colours show",
         [](Options& o, auto&) { o.ignoreMaterials = true; }},
        {"--stats", nullptr,
         "print the scene's statistics as one JSON object (objects, geometries, parts, "
         "triangles, load_ms, ID buffer bytes) and exit",
         [](Options& o, auto&) { o.stats = true; }},
        {"--export", "FILE", "write the scene (after copies) as binary glTF and exit",
         [](Options& o, auto& v) { o.exportPath = v; }},
        {"--renderer", "NAME",
         "part-ID technique (see --list-renderers; default per-draw); with --benchmark a comma "
         "list or all (default)",
         [](Options& o, auto& v) {
             rendererList(v); // throws on unknown names
             o.renderer = v;
         }},
        {"--mode", "NAME",
         "per-draw parameter mode (default push); with --benchmark a comma list or all (default)",
         [](Options& o, auto& v) {
             modeList(v);
             o.mode = v;
         }},
        {"--benchmark", nullptr,
         "headless: time every renderer x mode and the no-id floor; defaults 2560x1440, "
         "--msaa 4, --copies 3, --frames 200 (each flag overrides)",
         [](Options& o, auto&) { o.benchmark = o.headless = true; }},
        {"--benchmark-out", "FILE", "write the benchmark as JSON (CSV when FILE ends in .csv)",
         [](Options& o, auto& v) { o.benchmarkOut = v; }},
        {"--part-weight", "F", "blend of part colour over material colour, 0 to 1 (default 0.5)",
         [](Options& o, auto& v) { o.partWeight = parseFraction("--part-weight", v); }},
        {"--colorize-draws", nullptr, "replace material colours by a colour per draw call",
         [](Options& o, auto&) { o.colorizeDraws = true; }},
        {"--no-sort-draws", nullptr,
         "keep draws in scene order instead of by geometry and material",
         [](Options& o, auto&) { o.sortDraws = false; }},
        {"--gs-ordinary", nullptr,
         "gs renderers: use an ordinary geometry shader even where "
         "VK_NV_geometry_shader_passthrough "
         "is offered",
         [](Options& o, auto&) { o.gsPassthrough = false; }},
        {"--pick", "X,Y",
         "headless: pick the part at pixel X,Y (top-left origin) and print one JSON line "
         "{x,y,part,object,local_part,depth}; repeatable; the last point stays hovered in "
         "the images",
         [](Options& o, auto& v) { o.picks.push_back(parsePixel("--pick", v)); }},
        {"--select", "X,Y", "headless: select the part at pixel X,Y as a click there would",
         [](Options& o, auto& v) { o.selects = {parsePixel("--select", v)}; }},
        {"--animate", nullptr,
         "exploded-view animation: objects move out from the scene centre to twice their "
         "distance and back every 4 s, their matrices written on the GPU each frame; headless "
         "at --time, else at frame / 60 s",
         [](Options& o, auto&) { o.animate = true; }},
        {"--time", "SECONDS",
         "with --animate: the moment of the loop to render (default: frame / 60)",
         [](Options& o, auto& v) { o.time = parseSeconds("--time", v); }},
        {"--list-renderers", nullptr, "print the renderers and modes, then exit",
         [](Options& o, auto&) { o.listRenderers = true; }},
        {"--validation", nullptr, "enable the Khronos validation layer; messages make exit 3",
         [](Options& o, auto&) { o.validation = true; }},
        {"--sync-validation", nullptr,
         "--validation plus the layer's synchronization validation (slower; for testing)",
         [](Options& o, auto&) { o.validation = o.syncValidation = true; }},
        {"--device", "INDEX|NAME", "Vulkan device by index or name substring (default: best)",
         [](Options& o, auto& v) { o.device = v; }},
        {"--list-devices", nullptr, "print the Vulkan devices and whether idview runs there",
         [](Options& o, auto&) { o.listDevices = true; }},
        {"--shader-dir", "DIR", "read shaders from DIR instead of the built-in location",
         [](Options& o, auto& v) { o.shaderDir = v; }},
        {"--script", "FILE",
         "viewer: run scripted input, lines '<seconds> <command> [args]' (key, move, click, "
         "drag, scroll, resize, renderer, mode, msaa, screenshot, drop, quit)",
         [](Options& o, auto& v) { o.script = v; }},
    };
    return table;
}

template <typename Entry, typename Find>
std::vector<std::string> splitNames(const char* flag, const std::string& value,
                                    const std::vector<Entry>& all, Find find,
                                    const std::string& known) {
    std::vector<std::string> names;
    if (value == "all") {
        for (const auto& entry : all) names.push_back(entry.name);
        return names;
    }
    size_t start = 0;
    while (start <= value.size()) {
        const size_t comma = std::min(value.find(',', start), value.size());
        const std::string name = value.substr(start, comma - start);
        if (!find(name))
            throw UsageError(std::string(flag) + ": unknown name '" + name + "' (known: " + known +
                             ", or all)");
        names.push_back(name);
        start = comma + 1;
    }
    return names;
}

} // namespace

std::vector<std::string> rendererList(const std::string& value) {
    return splitNames("--renderer", value, render::techniques(), render::findTechnique,
                      render::techniqueNames());
}

std::vector<std::string> modeList(const std::string& value) {
    return splitNames("--mode", value, render::drawModes(), render::findDrawMode,
                      render::drawModeNames());
}

Options parseArgs(const std::vector<std::string>& args) {
    Options options;
    for (size_t i = 0; i < args.size(); ++i) {
        std::string name = args[i], value;
        bool inlineValue = false;
        if (auto eq = name.find('='); name.rfind("--", 0) == 0 && eq != std::string::npos) {
            value = name.substr(eq + 1);
            name = name.substr(0, eq);
            inlineValue = true;
        }
        const Flag* flag = nullptr;
        for (const auto& f : flags())
            if (name == f.name) flag = &f;
        if (!flag) throw UsageError("unknown option '" + args[i] + "'");
        if (flag->value && !inlineValue) {
            if (i + 1 >= args.size())
                throw UsageError(name + " needs a value (" + flag->value + ")");
            value = args[++i];
        } else if (!flag->value && inlineValue) {
            throw UsageError(name + " takes no value");
        }
        flag->apply(options, value);
        options.given.push_back(name);
    }
    auto given = [&](const char* name) {
        return std::find(options.given.begin(), options.given.end(), name) != options.given.end();
    };
    if (options.benchmark) {
        if (!given("--size")) options.width = 2560, options.height = 1440;
        if (!given("--msaa")) options.msaa = 4;
        if (!given("--copies")) options.copies = 3;
        if (!given("--frames")) options.frames = 200;
        if (!given("--renderer")) options.renderer = "all";
        if (!given("--mode")) options.mode = "all";
    } else if (rendererList(options.renderer).size() != 1 || modeList(options.mode).size() != 1 ||
               options.renderer == "all" || options.mode == "all") {
        throw UsageError("--renderer and --mode take one name each unless --benchmark is given");
    }
    if (options.time && !options.animate) throw UsageError("--time needs --animate");
    auto outside = [&](const Options::Pixel& p) {
        return p.x >= options.width || p.y >= options.height;
    };
    for (const auto* list : {&options.picks, &options.selects})
        for (const auto& p : *list)
            if (outside(p))
                throw UsageError("pixel " + std::to_string(p.x) + "," + std::to_string(p.y) +
                                 " is outside the " + std::to_string(options.width) + "x" +
                                 std::to_string(options.height) + " image");
    return options;
}

Options parseArgs(int argc, char** argv) {
    return parseArgs(std::vector<std::string>(argv + 1, argv + argc));
}

std::string usage() {
    std::string text = "usage: idview [OPTIONS]\n"
                       "Renders a CAD assembly and knows which part is at every pixel.\n\n";
    for (const auto& f : flags()) {
        std::string left = std::string("  ") + f.name + (f.value ? std::string(" ") + f.value : "");
        if (left.size() < 26)
            left.resize(26, ' ');
        else
            left += "\n" + std::string(26, ' ');
        text += left + f.help + "\n";
    }
    text += "\nExit codes: 0 ok, 1 error (no device, missing features, I/O), 2 bad command line,\n"
            "3 validation messages were reported (with --validation).\n";
    return text;
}

} // namespace app
