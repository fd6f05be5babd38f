// cli_flag_tables.h - what the flag tables (cli_flags*.cpp) are built from: help text that
// quotes the settings' own defaults, the common kinds of flag, and one table per group.
// Only those files include it.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "app/cli_flags.h"

namespace app::flag_tables {

// " (default 16)": help text from the settings' own defaults.
template <typename T>
std::string byDefault(const T& value) {
    std::ostringstream text;
    text << " (default " << value << ")";
    return text.str();
}
// ", 1 to 32 (default 16)".
std::string within(render::Range range, uint32_t value);
// "0.1%".
std::string percent(double fraction);
// " (default on)", " (default off)".
std::string onOff(bool value);

// A flag whose value is stored as given in a string of Options.
Flag text(const char* name, const char* value, std::string help, std::string Options::*field);
// A switch that sets a bool of Options.
Flag on(const char* name, std::string help, bool Options::*field);
// A flag only headless runs read.
Flag headless(Flag flag);
// A whole-number flag within `range`, written into the field `field` names.
Flag rangeFlag(const char* name, const char* help, render::Range range, uint32_t value,
               uint32_t& (*field)(Options&));

// --renderer or --mode: one registry entry into the pipeline key, or with --benchmark a list.
template <typename Entry>
Flag registryFlag(const char* name, const char* help, const char* value, const char* viewer,
                  std::vector<const Entry*> (*list)(const std::string&),
                  std::vector<const Entry*> Options::*benchmarkList,
                  const Entry* render::PipelineKey::*field) {
    return {name, "NAME",
            help + byDefault(value) + ", the viewer opens on " + viewer +
                "; with --benchmark a comma list or all (default)",
            [=](Options& o, const std::string& v) {
                o.*benchmarkList = list(v);
                o.live.render.pipeline.*field = (o.*benchmarkList).front();
            }};
}

// The groups' tables, each given the defaults (Options as the settings structs define
// them) its help quotes. cli_flags.cpp: running the program, the viewer.
std::vector<Flag> runningFlags(const Options& defaults);
std::vector<Flag> viewerFlags(const Options& defaults);
// cli_flags_scene.cpp: what is loaded, CAD tessellation, the view and its animation.
std::vector<Flag> sceneFlags(const Options& defaults);
std::vector<Flag> cadFlags(const Options& defaults);
std::vector<Flag> viewFlags(const Options& defaults);
// cli_flags_render.cpp: the image, the part-ID techniques, culling and levels of detail,
// shading.
std::vector<Flag> imageFlags(const Options& defaults);
std::vector<Flag> techniqueFlags(const Options& defaults);
std::vector<Flag> cullingFlags(const Options& defaults);
std::vector<Flag> shadingFlags(const Options& defaults);
// cli_flags_output.cpp: what headless runs write and print, reports, the benchmark.
std::vector<Flag> headlessFlags(const Options& defaults);
std::vector<Flag> reportFlags(const Options& defaults);
std::vector<Flag> benchmarkFlags(const Options& defaults);

} // namespace app::flag_tables
