// cli.cpp - parsing the command line with the flag table (cli_flags.h), the registry lists
// that --renderer, --mode and --culling take, and the usage text.
#include "app/cli.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <string>
#include <utility>

#include "app/cli_flags.h"
#include "app/cli_values.h"
#include "app/exit_code.h"
#include "render/culling.h"
#include "render/technique.h"
#include "scene/lod.h"

namespace app {
namespace {

template <typename Entry>
std::vector<const Entry*> namedEntries(const char* flag, const std::string& value,
                                       const std::vector<Entry>& all,
                                       const Entry* (*find)(const std::string&),
                                       const std::string& known, bool (*inAll)(const Entry&)) {
    std::vector<const Entry*> entries;
    if (value == "all") {
        for (const auto& entry : all)
            if (inAll(entry)) entries.push_back(&entry);
        return entries;
    }
    for (const std::string& name : commaList(value)) {
        const Entry* entry = find(name);
        if (!entry)
            throw UsageError(std::string(flag) + ": unknown name '" + name + "' (known: " + known +
                             ", or all)");
        entries.push_back(entry);
    }
    return entries;
}

} // namespace

std::vector<const render::Technique*> techniqueList(const std::string& value) {
    return namedEntries<render::Technique>("--renderer", value, render::techniques(),
                                           render::findTechnique, render::techniqueNames(),
                                           [](const render::Technique& t) { return !t.isFloor(); });
}

std::vector<const render::DrawMode*> modeList(const std::string& value) {
    return namedEntries<render::DrawMode>("--mode", value, render::drawModes(),
                                          render::findDrawMode, render::drawModeNames(),
                                          [](const render::DrawMode&) { return true; });
}

std::vector<const render::CullModeEntry*> cullingList(const std::string& value) {
    return namedEntries<render::CullModeEntry>("--culling", value, render::cullModes(),
                                               render::findCullMode, render::cullModeNames(),
                                               [](const render::CullModeEntry&) { return true; });
}

Options viewerDefaults() {
    Options options;
    options.live.render.pipeline.technique = render::findTechnique("vertex-fs");
    options.live.render.pipeline.mode = render::findDrawMode("mdi-baseinstance");
    return options;
}

WindowPlace windowPlace(const Options& options) {
    return {options.width, options.height, options.windowPos};
}

std::vector<std::string> ignoredByViewer(const Options& options) {
    std::vector<std::string> ignored;
    for (const Flag& flag : flags())
        if (flag.headlessOnly &&
            std::find(options.given.begin(), options.given.end(), flag.name) != options.given.end())
            ignored.push_back(flag.name);
    return ignored;
}

Options parseArgs(const std::vector<std::string>& args) {
    return parseArgs(args, Options{});
}

bool given(const Options& options, const char* name) {
    return std::find(options.given.begin(), options.given.end(), name) != options.given.end();
}

namespace {

// The one argument that is no flag: the model, as --model would take it (a launcher's %f);
// refused after another model, where which one was meant is a guess.
void applyModelArgument(const std::string& argument, Options& options) {
    if (given(options, "--model"))
        throw UsageError(
            "one model at a time: '" + argument + "' after " +
            (options.live.scene.model.empty() ? "--model" : "'" + options.live.scene.model + "'"));
    options.live.scene.model = modelPath(argument);
    options.given.push_back("--model");
}

// Each argument through its flag (--name value or --name=value), recorded in Options::given.
void applyFlags(const std::vector<std::string>& args, Options& options) {
    bool positionalModel = false;
    for (size_t i = 0; i < args.size(); ++i) {
        if (!args[i].empty() && args[i][0] != '-') {
            applyModelArgument(args[i], options);
            positionalModel = true;
            continue;
        }
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
        if (name == "--model" && positionalModel)
            throw UsageError("one model at a time: --model after '" + options.live.scene.model +
                             "'");
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
}

// --benchmark: its defaults where the flags are not given. Otherwise the lists (and "all")
// are the benchmark's: one name each.
void settleBenchmarkLists(Options& options) {
    if (options.benchmark) {
        if (!given(options, "--size")) options.width = 2560, options.height = 1440;
        if (!given(options, "--msaa")) options.live.render.pipeline.msaa = 4;
        if (!given(options, "--copies")) options.live.scene.copies = 3;
        if (!given(options, "--frames")) options.frames = 200;
        if (!given(options, "--renderer")) options.benchmarkTechniques = techniqueList("all");
        if (!given(options, "--mode")) options.benchmarkModes = modeList("all");
        if (!given(options, "--culling")) options.benchmarkCulling = cullingList("all");
        if (!given(options, "--lod-error"))
            options.benchmarkLodErrors = {options.live.render.lod.errorPixels};
        return;
    }
    const bool oneEach =
        (!given(options, "--renderer") || options.benchmarkTechniques.size() == 1) &&
        (!given(options, "--mode") || options.benchmarkModes.size() == 1) &&
        (!given(options, "--culling") || options.benchmarkCulling.size() == 1);
    if (!oneEach)
        throw UsageError("--renderer, --mode and --culling take one name each unless "
                         "--benchmark is given");
    if (options.benchmarkLodErrors.size() > 1)
        throw UsageError("--lod-error takes one value unless --benchmark is given");
    options.benchmarkTechniques.clear();
    options.benchmarkModes.clear();
    options.benchmarkCulling.clear();
    options.benchmarkLodErrors.clear();
}

// Levels of detail, and the exploded view's two forms.
void settleLevelsAndAnimation(Options& options) {
    if (options.live.scene.lodLevel >= options.live.scene.lodLevels)
        throw UsageError("--lod-level " + std::to_string(options.live.scene.lodLevel) +
                         " needs --lod-levels " + std::to_string(options.live.scene.lodLevel + 1) +
                         " or more");
    // Levels to choose from: all of them unless the levels built are given.
    const bool chosen = options.live.render.lod.errorPixels > 0.0f;
    if (chosen && !given(options, "--lod-levels")) options.live.scene.lodLevels = scene::maxLevels;
    if (chosen && options.live.scene.lodLevels < 2)
        throw UsageError("--lod-error needs --lod-levels 2 or more");
    if (chosen && options.live.scene.lodLevel > 0)
        throw UsageError("--lod-error and --lod-level cannot be combined: --lod-level draws one "
                         "level everywhere");
    if (options.live.animation.time && !options.live.animation.animate)
        throw UsageError("--time needs --animate");
    if (options.live.animation.animate && options.live.animation.explode > 0.0f)
        throw UsageError("--explode and --animate cannot be combined: --animate runs the "
                         "exploded view from 0 to 1 and back");
}

// --thumbnail: a square image of one frame, written where --screenshot says.
void settleThumbnail(Options& options) {
    if (options.thumbnail.size == 0) return;
    if (options.screenshot.empty())
        throw UsageError("--thumbnail needs --screenshot FILE, where the PNG goes");
    if (options.benchmark) throw UsageError("--thumbnail and --benchmark cannot be combined");
    options.width = options.height = options.thumbnail.size;
    options.frames = 1;
}

// Every pixel a flag names lies in the image.
void checkPixels(const Options& options) {
    std::vector<Options::Pixel> pixels = options.picks;
    pixels.insert(pixels.end(), options.faceInfos.begin(), options.faceInfos.end());
    pixels.insert(pixels.end(), options.edgeInfos.begin(), options.edgeInfos.end());
    if (options.measure)
        pixels.insert(pixels.end(), options.measure->begin(), options.measure->end());
    pixels.insert(pixels.end(), options.selects.begin(), options.selects.end());
    if (const auto& rect = options.selectRect) {
        pixels.push_back({rect->min.x, rect->min.y});
        pixels.push_back({rect->max.x, rect->max.y});
    }
    for (const auto& p : pixels)
        if (p.x >= options.width || p.y >= options.height)
            throw UsageError("pixel " + std::to_string(p.x) + "," + std::to_string(p.y) +
                             " is outside the " + std::to_string(options.width) + "x" +
                             std::to_string(options.height) + " image");
}

} // namespace

Options parseArgs(const std::vector<std::string>& args, Options start) {
    Options options = std::move(start);
    applyFlags(args, options);
    settleBenchmarkLists(options);
    settleLevelsAndAnimation(options);
    settleThumbnail(options);
    checkPixels(options);
    if (!options.hide.empty() && !options.isolate.empty())
        throw UsageError("--hide and --isolate cannot be combined: --isolate hides the rest");
    if (options.census.views == 0 && !(options.censusCsv.empty() && options.censusExport.empty()))
        throw UsageError("--census-csv and --census-export need --census VIEWSxSIZE");
    return options;
}

bool censusExportsStep(const std::string& path) {
    return path.ends_with(".step") || path.ends_with(".stp");
}

Options parseArgs(int argc, char** argv) {
    return parseArgs(std::vector<std::string>(argv + 1, argv + argc));
}

std::string usage() {
    std::string text = std::string("usage: ") + usageSynopsis + "\n" + programSummary + "\n";
    for (const FlagGroup& group : flagGroups()) {
        text.append("\n").append(group.title).append(":\n");
        for (const Flag& f : group.flags) {
            std::string left =
                std::string("  ") + f.name + (f.value ? std::string(" ") + f.value : "");
            if (left.size() < 26)
                left.resize(26, ' ');
            else
                left.append("\n").append(26, ' ');
            text += left + f.help + "\n";
        }
    }
    // "Exit codes: 0 ok, 1 error ..., 3 ...", broken before 90 columns.
    std::string line = "\nExit codes:";
    const auto& codes = exitCodes();
    for (size_t i = 0; i < codes.size(); ++i) {
        const std::string item = " " + std::to_string(codes[i].code) + " " + codes[i].meaning +
                                 (i + 1 < codes.size() ? "," : ".");
        if (line.size() - line.rfind('\n') + item.size() > 90) line += "\n";
        line += line.back() == '\n' ? item.substr(1) : item;
    }
    return text + line + "\n";
}

} // namespace app
