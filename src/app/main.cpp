// main.cpp - idview's entry point: parses the command line and runs the requested path.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "app/benchmark.h"
#include "app/census.h"
#include "app/cli.h"
#include "app/headless.h"
#include "app/saved_settings.h"
#include "app/scene_source.h"
#include "app/thumbnail.h"
#include "app/version.h"
#include "app/viewer/viewer.h"
#include "render/culling.h"
#include "render/technique.h"
#include "scene/gltf/gltf_writer.h"
#include "vk/context.h"

namespace {

// One section per kind, each line "  NAME  description": scripts read the names from here.
// Techniques that need a device feature say so; the panel and the benchmark say whether the
// device in use has it.
int listRenderers() {
    auto line = [](const render::Technique& t) {
        std::printf("  %-15s %s%s\n", t.name, t.description,
                    t.usesMeshShader() ? " [needs VK_EXT_mesh_shader]" : "");
    };
    std::printf("renderers:\n");
    for (const render::Technique* t : render::partIdTechniques()) line(*t);
    std::printf("per-draw modes:\n");
    for (const auto& m : render::drawModes()) std::printf("  %-15s %s\n", m.name, m.description);
    std::printf("reference (the benchmark's floors, no part IDs):\n");
    for (const render::Technique& t : render::techniques())
        if (t.isFloor()) line(t);
    std::printf("culling modes (--culling, default %s):\n",
                render::cullModeName(render::CullSettings{}.mode));
    for (const auto& c : render::cullModes()) std::printf("  %-15s %s\n", c.name, c.description);
    std::printf("what each per-draw mode and renderer gets of them:\n");
    for (const auto& m : render::drawModes())
        for (const auto& c : render::cullModes()) {
            if (c.mode == render::CullMode::Off) continue;
            // The renderers that get the same, in registry order, under one line.
            std::vector<std::pair<std::string, std::string>> lines; // text, renderers
            for (const render::Technique& t : render::techniques()) {
                const std::string text = render::describeCulling(t, m, c.mode);
                auto same = std::find_if(lines.begin(), lines.end(),
                                         [&](const auto& l) { return l.first == text; });
                if (same == lines.end())
                    lines.push_back({text, t.name});
                else
                    same->second += std::string(", ") + t.name;
            }
            for (const auto& [text, names] : lines)
                std::printf("  %-17s %-10s %s (%s)\n", m.name, c.name, text.c_str(), names.c_str());
        }
    return 0;
}

int listDevices(const app::Options& options) {
    vk::Instance instance({options.validation, {}, options.syncValidation});
    const auto devices = instance.devices();
    if (devices.empty()) std::printf("no Vulkan devices\n");
    for (const auto& info : devices) {
        auto missing = vk::missingRequirements(info);
        std::string verdict = "usable";
        for (size_t i = 0; i < missing.size(); ++i)
            verdict = (i == 0 ? "cannot run idview: missing " : verdict + ", ") + missing[i];
        std::printf("%s | %s\n", vk::describeDevice(info).c_str(), verdict.c_str());
    }
    return 0;
}

// --distance or --properties: answered from the loaded scene, nothing rendered.
bool inspects(const app::Options& options) {
    return options.distance || options.propertiesObject || options.propertiesAll;
}

void warn(const std::string& line) {
    std::fprintf(stderr, "idview: %s\n", line.c_str());
}

// The viewer's options: its defaults, the settings it kept, then the command line; and one
// line naming the flags it does not read.
app::Options viewerOptions(const std::vector<std::string>& args) {
    app::Options options = app::viewerOptions(args, app::savedSettingsPath(), warn);
    std::string ignored;
    for (const std::string& flag : app::ignoredByViewer(options))
        ignored += (ignored.empty() ? "" : ", ") + flag;
    if (!ignored.empty()) warn(ignored + ": only read with --headless; ignored");
    return options;
}

} // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    app::Options options;
    try {
        options = app::parseArgs(args);
        if (!options.help && !options.version && !options.listRenderers && !options.listDevices &&
            !options.stats && !options.tree && options.exportPath.empty() && !options.headless &&
            !inspects(options))
            options = viewerOptions(args);
    } catch (const app::UsageError& e) {
        // One line and where to look: the usage would scroll it away.
        std::fprintf(stderr, "idview: %s\nsee idview --help\n", e.what());
        return 2;
    }
    if (options.help) {
        std::printf("%s", app::usage().c_str());
        return 0;
    }
    if (options.version) {
        std::printf("%s\n", app::versionLine().c_str());
        return 0;
    }
    try {
        if (options.listRenderers) return listRenderers();
        if (options.listDevices) return listDevices(options);
        if (options.thumbnail.size > 0) return app::runThumbnail(options);
        // --stats with --headless renders first, to say how long the first frame took.
        const bool renderedStats = options.stats && options.headless && !options.benchmark &&
                                   !options.tree && options.exportPath.empty();
        // --distance and --properties need no image; with --headless they come with its lines.
        if (!renderedStats && (options.stats || options.tree || !options.exportPath.empty() ||
                               (inspects(options) && !options.headless))) {
            const app::LoadedScene loaded = app::loadScene(options.live.scene);
            // Checked and answered before anything is written: a wrong ID leaves no file.
            const std::vector<std::string> inspection = app::inspectionJson(options, loaded.scene);
            if (!options.exportPath.empty()) scene::writeGlb(loaded.scene, options.exportPath);
            if (options.stats)
                std::printf("%s\n", app::statsJson(loaded, options.live.render).c_str());
            if (options.tree) std::printf("%s\n", app::treeJson(loaded).c_str());
            for (const std::string& line : inspection) std::printf("%s\n", line.c_str());
            return 0;
        }
        if (options.census.views > 0) return app::runCensus(options);
        if (options.benchmark) return app::benchmarkCommand(options);
        if (!options.headless) return app::runViewer(options);
        return app::runHeadless(options);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "idview: error: %s\n", e.what());
        return 1;
    }
}
