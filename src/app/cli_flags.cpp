// cli_flags.cpp - the flag table's groups in help order, the kinds of flag they share
// (cli_flag_tables.h), and the groups for running the program and for the viewer. Values
// are read by cli_values.h.
#include "app/cli_flags.h"

#include <cstdio>

#include "app/cli_flag_tables.h"

namespace app {

namespace flag_tables {

std::string within(render::Range range, uint32_t value) {
    return ", " + std::to_string(range.min) + " to " + std::to_string(range.max) + byDefault(value);
}

std::string percent(double fraction) {
    char text[32];
    std::snprintf(text, sizeof text, "%g%%", fraction * 100.0);
    return text;
}

std::string onOff(bool value) {
    return byDefault(value ? "on" : "off");
}

Flag text(const char* name, const char* value, std::string help, std::string Options::*field) {
    return {name, value, std::move(help),
            [field](Options& o, const std::string& v) { o.*field = v; }};
}

Flag on(const char* name, std::string help, bool Options::*field) {
    return {name, nullptr, std::move(help),
            [field](Options& o, const std::string&) { o.*field = true; }};
}

Flag headless(Flag flag) {
    flag.headlessOnly = true;
    return flag;
}

Flag rangeFlag(const char* name, const char* help, render::Range range, uint32_t value,
               uint32_t& (*field)(Options&)) {
    return {name, "N", help + within(range, value),
            [=](Options& o, const std::string& v) { field(o) = parseRange(name, v, range); }};
}

std::vector<Flag> runningFlags(const Options&) {
    return {
        on("--help", "print this text", &Options::help),
        on("--version", "print idview's version and the commit it was built from, then exit",
           &Options::version),
        on("--headless", "render offscreen without a window or surface", &Options::headless),
        on("--validation", "enable the Khronos validation layer; messages make exit 3",
           &Options::validation),
        {"--sync-validation", nullptr,
         "--validation plus the layer's synchronization validation (slower; for testing)",
         [](Options& o, auto&) { o.validation = o.syncValidation = true; }},
        text("--device", "INDEX|NAME", "Vulkan device by index or name substring (default: best)",
             &Options::device),
        on("--list-devices", "print the Vulkan devices and whether idview runs there",
           &Options::listDevices),
        on("--list-renderers", "print the renderers and modes, then exit", &Options::listRenderers),
        text("--shader-dir", "DIR", "read shaders from DIR instead of the built-in location",
             &Options::shaderDir),
        {"--no-cache", nullptr,
         "neither read nor write the caches in $XDG_CACHE_HOME/idview (else "
         "~/.cache/idview): CAD files' tessellations, and the driver's compiled pipelines "
         "(then kept in memory only)",
         [](Options& o, auto&) { o.live.scene.cadCache = false; }},
    };
}

std::vector<Flag> viewerFlags(const Options&) {
    return {
        text("--script", "FILE",
             "viewer: run scripted input, lines '<seconds> <command> [args]' (key, move, click, "
             "drag, scroll, resize, renderer, mode, msaa, sort, defaults, copies, explode, "
             "frames, "
             "screenshot, drop, quit)",
             &Options::script),
        on("--print-events",
           "viewer: print one JSON record a line on stdout per event (title, selection, opened "
           "model, screenshot, shader reload...), for scripts and tests; quiet otherwise",
           &Options::printEvents),
        {"--window-pos", "X,Y",
         "viewer: the window's top left corner on the screen, kept between runs with "
         "--size; pulled onto the screen's work area if it lies off it",
         [](Options& o, auto& v) { o.windowPos = parseWindowPos(v); }},
        {"--no-saved-settings", nullptr,
         "viewer: open on the defaults, neither reading nor writing the settings kept "
         "between runs ($XDG_CONFIG_HOME/idview/viewer.conf, else "
         "~/.config/idview/viewer.conf)",
         [](Options& o, auto&) { o.savedSettings = false; }},
    };
}

} // namespace flag_tables

const std::vector<FlagGroup>& flagGroups() {
    using namespace flag_tables;
    static const std::vector<FlagGroup> groups = [] {
        const Options d; // the defaults, as the settings structs define them
        return std::vector<FlagGroup>{
            {"Running", runningFlags(d)},
            {"Scene", sceneFlags(d)},
            {"CAD files", cadFlags(d)},
            {"Image", imageFlags(d)},
            {"Part-ID techniques", techniqueFlags(d)},
            {"Culling and levels of detail", cullingFlags(d)},
            {"Shading, edges, sections", shadingFlags(d)},
            {"View and animation", viewFlags(d)},
            {"Headless output", headlessFlags(d)},
            {"Reports", reportFlags(d)},
            {"Benchmark", benchmarkFlags(d)},
            {"Viewer", viewerFlags(d)},
        };
    }();
    return groups;
}

const std::vector<Flag>& flags() {
    static const std::vector<Flag> all = [] {
        std::vector<Flag> list;
        for (const FlagGroup& group : flagGroups())
            list.insert(list.end(), group.flags.begin(), group.flags.end());
        return list;
    }();
    return all;
}

} // namespace app
