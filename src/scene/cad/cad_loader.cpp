// cad_loader.cpp - loadCad: the file read down to its leaf instances (cad_read.h); every
// distinct shape sewn where the format needs it, tessellated once (in parallel) and turned
// into a geometry with one part per triangulated face (cad_build.h), and levels of detail
// (cad_levels.h).
#include "scene/cad/cad_loader.h"

#include "scene/cad/brep_occt.h"
#include "scene/cad/cad_healing.h"
#include "scene/cad/cad_session.h"
#include "scene/cad/cad_stages.h"
#include "util/memory.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <new>
#include <set>

#include <Standard_Failure.hxx>
#include <Standard_OutOfMemory.hxx>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif

namespace scene {

#if defined(__SANITIZE_ADDRESS__)
OcctLeaksIgnored::OcctLeaksIgnored() {
    __lsan_disable();
}
OcctLeaksIgnored::~OcctLeaksIgnored() {
    __lsan_enable();
}
#else
OcctLeaksIgnored::OcctLeaksIgnored() = default;
OcctLeaksIgnored::~OcctLeaksIgnored() = default;
#endif

namespace {

using namespace cad;
namespace fs = std::filesystem;

// The stages in order: read, distinct shapes, sew and tessellate, build the geometries and
// objects, levels of detail, the shapes kept, warnings, and a last check.
CadLoadResult loadHere(const std::string& path, const CadOptions& options,
                       const CadProgress& progress, uint32_t levels,
                       const std::atomic<bool>* cancel) {
    const Format format = checkedFormat(path, options, levels);
    quietOcct();
    // A file read whole is read healed unless asked not to: it has no pieces to try without.
    setStepHealing(options.healing != Healing::Off);
    const std::string stem = fs::path(path).stem().string();
    CadLoadResult result;
    auto start = Clock::now();
    const Read read = readLeaves({path}, format, stem, progress, cancel);
    result.readMs = msSince(start);
    DistinctShapes shapes = distinctShapes(read.leaves);
    if (shapes.faceless == read.leaves.size()) throw Bad("the file holds no shapes with faces");

    const double automatic = automaticDeflection(shapes.world);
    result.deflection = options.deflection == 0.0 ? automatic : options.deflection;
    start = Clock::now();
    // A gap the file's resolution leaves open but narrower than the deflection is below what
    // the tessellation draws (its triangles stray that far from the surface anyway), yet each
    // side would be sampled on its own and the background would show through: such gaps are
    // sewn too, never wider than the automatic deflection, so that a coarse --deflection
    // cannot join edges that are apart in the model.
    const std::set<const void*> skipped =
        tessellate(shapes.shapes, read.sewTolerance, result.deflection,
                   std::min(result.deflection, automatic), options, progress, cancel);
    result.tessellationMs = msSince(start);

    Scene& scene = result.scene;
    Materials materials(scene);
    const BuiltGeometries built =
        buildGeometries(scene, shapes.shapes, stem, materials, progress, cancel);
    result.faces = built.faces;
    result.facesFailed = built.facesFailed;
    if (scene.indices.empty()) throw Bad("no face of the model could be triangulated");
    // Objects before levels: the levels chosen weigh the objects that draw each geometry.
    addObjects(scene, read.leaves, shapes, materials, stem);
    std::vector<BrepShapes::Shape> kept = keptShapes(shapes.shapes, scene.geometries.size());
    if (levels > 1) {
        start = Clock::now();
        std::vector<GeometryCandidates> candidates =
            levelCandidates(scene, kept, skipped, result.deflection, options, progress, cancel);
        addChosenLevels(scene, candidates, LodOptions{.levels = levels});
        result.levelsMs = msSince(start);
    }
    kept.resize(scene.geometries.size()); // levels have no shape
    scene.brep = encodedShapes(kept);
    addWarnings(result, shapes.faceless, read.losses, format, skipped.size(), built.emptyShapes);
    try {
        validate(scene);
    } catch (const std::invalid_argument& e) {
        throw Bad(std::string("inconsistent tessellation: ") + e.what());
    }
    return result;
}

// Runs `load`, turning every way it can fail into one ModelError line naming the file.
template <typename Load>
CadLoadResult refusedInWords(const std::string& path, const std::atomic<bool>* cancel,
                             Load&& load) {
    try {
        return load();
    } catch (const Bad& e) {
        // A reader broken off by the flag says only that it read nothing.
        if (cancel && *cancel) throw ModelError(path + ": cancelled");
        throw ModelError(path + ": " + e.what());
    } catch (const Standard_OutOfMemory&) {
        throw ModelError(path + ": out of memory reading it whole (" +
                         std::to_string(util::mebibytes(util::residentBytes())) + " MiB in use)");
    } catch (const Standard_Failure& e) {
        const char* message = e.GetMessageString();
        throw ModelError(path + ": Open CASCADE failed: " + e.DynamicType()->Name() +
                         (message && *message ? std::string(": ") + message : std::string()));
    } catch (const std::bad_alloc&) {
        throw ModelError(path + ": out of memory reading it whole (" +
                         std::to_string(util::mebibytes(util::residentBytes())) + " MiB in use)");
    }
}

} // namespace

const char* healingName(Healing healing) {
    return healing == Healing::On ? "on" : healing == Healing::Off ? "off" : "auto";
}

bool isCadPath(const std::string& path) {
    return formatOf(path) != Format::None;
}

std::string triangleLimitReason(uint64_t estimate, uint64_t limit, double deflection) {
    // A curved face's triangles grow as 1 / deflection: aim at half the limit.
    double suggested =
        deflection * std::max(2.0, 2.0 * double(estimate) / double(std::max<uint64_t>(limit, 1)));
    const double step = std::pow(10.0, std::floor(std::log10(suggested)) - 1.0);
    suggested = std::ceil(suggested / step) * step;
    char text[200];
    std::snprintf(text, sizeof text,
                  "the tessellation passes --max-triangles %llu (about %llu triangles at "
                  "deflection %.3g); try --deflection %g",
                  static_cast<unsigned long long>(limit), static_cast<unsigned long long>(estimate),
                  deflection, suggested);
    return text;
}

CadLoadResult loadCadInProcess(const std::string& path, const CadOptions& options,
                               const CadProgress& progress, uint32_t levels,
                               const std::atomic<bool>* cancel) {
    return refusedInWords(path, cancel,
                          [&] { return loadHere(path, options, progress, levels, cancel); });
}

CadLoadResult loadCad(const std::string& path, const CadOptions& options,
                      const CadProgress& progress, uint32_t levels, const std::atomic<bool>* cancel,
                      const CadPartialSink& partial) {
    return refusedInWords(path, cancel, [&] {
        return loadWithWorkers(path, options, progress, levels, cancel, partial);
    });
}

} // namespace scene
