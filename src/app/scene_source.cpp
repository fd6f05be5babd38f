// scene_source.cpp - scene loading by source, copies, and the opening camera (the --stats
// and --tree JSON are in scene_report.cpp).
#include "app/scene_source.h"

#include <charconv>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

#include "app/out_of_memory.h"
#include "app/progress_lines.h"
#include "render/renderer.h"
#include "scene/cad/cad_cache.h"
#include "scene/cad/cad_loader.h"
#include "scene/copies.h"
#include "scene/formats.h"
#include "scene/gltf/gltf_loader.h"
#include "scene/inspect.h"
#include "scene/lod.h"
#include "scene/procedural/generator.h"
#include "scene/procedural/procedural.h"
#include "scene/stl/stl_loader.h"
#include "util/program_paths.h"

namespace app {

SceneSpec parseSceneSpec(const std::string& text) {
    SceneSpec spec;
    const auto colon = text.find(':');
    spec.builtin = text.substr(0, colon);
    const bool known =
        spec.builtin == "procedural" || spec.builtin == "assembly" || spec.builtin == "tiles";
    if (!known)
        throw std::invalid_argument("unknown scene '" + spec.builtin +
                                    "' (known: assembly, tiles, procedural)");
    if (colon == std::string::npos) return spec;
    if (spec.builtin != "procedural")
        throw std::invalid_argument("scene '" + spec.builtin + "' takes no parameters");
    std::istringstream params(text.substr(colon + 1));
    std::string item;
    while (std::getline(params, item, ',')) {
        const auto eq = item.find('=');
        const std::string key = item.substr(0, eq),
                          value = eq == std::string::npos ? "" : item.substr(eq + 1);
        if (key == "preset") {
            bool found = false;
            for (const auto& name : scene::proceduralPresets()) found |= name == value;
            if (!found) throw std::invalid_argument("unknown procedural preset '" + value + "'");
            spec.preset = value;
        } else if (key == "seed") {
            auto [end, error] =
                std::from_chars(value.data(), value.data() + value.size(), spec.seed);
            if (value.empty() || error != std::errc() || end != value.data() + value.size())
                throw std::invalid_argument("procedural seed must be a whole number, not '" +
                                            value + "'");
        } else {
            throw std::invalid_argument("unknown procedural parameter '" + item +
                                        "' (preset=NAME, seed=N)");
        }
    }
    return spec;
}

std::string defaultModelPath() {
    return util::dataPath("assets/default.glb").string();
}

std::string sourceOf(const SceneSettings& settings) {
    if (settings.model.empty() && !settings.builtin.empty()) return settings.builtin;
    return settings.model.empty() ? defaultModelPath() : settings.model;
}

// Copies add objects: refuse in words, before allocating, a count whose object arrays (the
// scene's on the host, the GPU's copy, the draw lists) would not fit in this machine's RAM.
void checkCopiesFit(const scene::Scene& scene, uint32_t copies) {
    const uint64_t objects = uint64_t(scene.objects.size()) * copies;
    const uint64_t perObject = sizeof(scene::Object) + 2 * sizeof(gpu::ObjectData);
    const uint64_t needed = objects * perObject;
    const uint64_t ram = uint64_t(sysconf(_SC_PHYS_PAGES)) * uint64_t(sysconf(_SC_PAGE_SIZE));
    if (needed > ram / 2)
        throw std::runtime_error(std::to_string(copies) + " copies make " +
                                 std::to_string(objects) + " objects, about " +
                                 std::to_string(needed >> 30) + " GiB for their arrays alone; " +
                                 "this machine has " + std::to_string(ram >> 30) + " GiB");
}

namespace {

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

// A CAD file into `loaded`: through the tessellation cache unless --no-cache.
void loadCadFile(LoadedScene& loaded, const SceneSettings& settings, LoadProgress* progress,
                 const std::atomic<bool>* cancel, const scene::CadPartialSink& partial) {
    const scene::CadProgress onStderr = stderrProgress(loaded.source, settings.progress);
    const scene::CadProgress report = [&](const char* stage, double fraction) {
        if (onStderr) onStderr(stage, fraction);
        if (progress) progress->set(stage, fraction);
    };
    scene::CadLoadResult result = settings.cadCache
                                      ? scene::loadCadCached(loaded.source, settings.cad, report,
                                                             settings.lodLevels, cancel, partial)
                                      : scene::loadCad(loaded.source, settings.cad, report,
                                                       settings.lodLevels, cancel, partial);
    loaded.cad = true;
    loaded.cadLoad = result; // the figures; the scene and warnings move below
    if (!settings.cadCache) loaded.cadLoad.cacheNote = "--no-cache";
    loaded.lodMs = result.levelsMs;
    loaded.scene = std::move(result.scene);
    loaded.warnings = std::move(result.warnings);
    if (settings.parts != scene::PartMode::Primitives)
        loaded.warnings.insert(loaded.warnings.begin(),
                               "--parts is ignored for CAD files: a part is a B-rep face");
    loaded.scene.unit = scene::cadUnit(loaded.source);
}

// The file, built-in or procedural scene `settings` name, as it is (no levels, no copies).
void loadSource(LoadedScene& loaded, const SceneSettings& settings, LoadProgress* progress,
                const std::atomic<bool>* cancel, const scene::CadPartialSink& partial) {
    loaded.source = sourceOf(settings);
    if (!settings.model.empty() || settings.builtin.empty()) {
        // Every file, whatever its format, is refused here in one line when its content is
        // not what its name says, before a reader can answer in its own words.
        const scene::Reader reader = scene::checkModelFile(loaded.source).reader;
        refuseOutOfMemory(loaded.source, loadingWhat(loaded.source), [&] {
            if (scene::isBrepReader(reader))
                return loadCadFile(loaded, settings, progress, cancel, partial);
            const bool stl = reader == scene::Reader::Stl;
            scene::LoadResult result = stl ? scene::loadStl(loaded.source)
                                           : scene::loadGltf(loaded.source, {settings.parts});
            loaded.scene = std::move(result.scene);
            loaded.warnings = std::move(result.warnings);
            loaded.scene.unit = stl ? scene::stlUnit() : scene::gltfUnit();
            if (stl && settings.parts != scene::PartMode::Primitives)
                loaded.warnings.insert(loaded.warnings.begin(),
                                       "--parts is ignored for STL files: a part is a solid");
        });
        return;
    }
    const SceneSpec spec = parseSceneSpec(settings.builtin);
    refuseOutOfMemory(loaded.source, "generating it", [&] {
        if (spec.builtin == "procedural")
            loaded.scene = scene::makeProcedural({spec.preset, spec.seed});
        else
            loaded.scene = scene::makeScene(spec.builtin);
    });
    loaded.tilesLayout = spec.builtin == "tiles" && settings.copies == 1;
}

} // namespace

LoadedScene loadScene(const SceneSettings& settings, LoadProgress* progress,
                      const std::atomic<bool>* cancel, const scene::CadPartialSink& partial) {
    const auto start = std::chrono::steady_clock::now();
    LoadedScene loaded;
    loaded.settings = settings;
    loadSource(loaded, settings, progress, cancel, partial);
    if (settings.lodLevels > 1 && !loaded.cad) {
        // Before the copies, which share their geometries. CAD files tessellate theirs.
        const auto lodStart = std::chrono::steady_clock::now();
        refuseOutOfMemory(loaded.source, levelsWhat(settings.lodLevels, loaded.scene), [&] {
            scene::buildLevels(loaded.scene, {.levels = settings.lodLevels}, [&](double fraction) {
                if (progress) progress->set("levels of detail", fraction);
            });
        });
        loaded.lodMs = msSince(lodStart);
    }
    if (settings.copies > 1)
        loaded.scene = makeCopies(loaded.source, loaded.scene, settings.copies, settings.copyAxes);
    if (settings.lodLevel > 0) scene::retargetToLevel(loaded.scene, settings.lodLevel);
    loaded.scene.precision = scene::scenePrecision(loaded.scene);
    loaded.loadMs = msSince(start);
    return loaded;
}

scene::Scene makeCopies(const std::string& source, const scene::Scene& scene, uint32_t copies,
                        uint32_t axes) {
    checkCopiesFit(scene, copies);
    return refuseOutOfMemory(source, copiesWhat(copies, scene),
                             [&] { return scene::replicate(scene, copies, axes); });
}

void uploadScene(render::Renderer& renderer, const std::string& source, const scene::Scene& scene,
                 const render::RenderSettings& settings) {
    refuseOutOfMemory(source, uploadWhat(scene), [&] { renderer.setScene(scene, settings); });
}

scene::Camera initialCamera(const LoadedScene& loaded, float aspect, const CameraSettings& view) {
    return initialCamera(loaded, aspect, view, loaded.scene.bounds());
}

scene::Camera initialCamera(const LoadedScene& loaded, float aspect, const CameraSettings& view,
                            const scene::Bounds& bounds) {
    scene::Camera camera;
    if (loaded.tilesLayout) {
        camera = scene::tilesCamera();
    } else {
        // A three-quarter view from the front, above: how CAD viewers open an assembly. glTF
        // is y-up, the built-in scenes z-up.
        const scene::ModelFormat* format = scene::formatOfName(loaded.source);
        const bool yUp = format && format->reader == scene::Reader::Gltf;
        const glm::vec3 up = yUp ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
        const glm::vec3 direction =
            yUp ? glm::vec3(0.9f, 1.2f, 1.6f) : glm::vec3(0.9f, -1.6f, 1.2f);
        camera = scene::fitCamera(bounds, direction, up, glm::radians(40.0f), aspect);
    }
    // The standard views turn about the fitted target at the fitted distance, the model's
    // up axis being the opening camera's.
    if (view.standard) camera = scene::turnedTo(camera, *view.standard, camera.up);
    camera.ortho = view.ortho;
    if (view.ortho) scene::fitPlanes(camera, bounds);
    return camera;
}

} // namespace app
