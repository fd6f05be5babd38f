// cad_loader.cpp - loadCad: the file read down to its leaf instances (cad_read.h); every
// distinct shape sewn where the format needs it, tessellated once (in parallel) and turned
// into a geometry with one part per triangulated face (cad_build.h), and levels of detail
// (cad_levels.h).
#include "scene/cad/cad_loader.h"

#include "scene/cad/brep_occt.h"
#include "scene/cad/cad_build.h"
#include "scene/cad/cad_check.h"
#include "scene/cad/cad_levels.h"
#include "scene/cad/cad_mesh.h"
#include "scene/cad/cad_read.h"
#include "scene/cad/cad_reader_losses.h"
#include "scene/cad/cad_sew.h"
#include "scene/cad/fault_guard.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <new>
#include <set>

#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Standard_Failure.hxx>
#include <Standard_OutOfMemory.hxx>
#include <TopoDS_Compound.hxx>

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
using Clock = std::chrono::steady_clock;

// Far beyond any sample; a bound on what the readers are asked to hold in memory.
constexpr uintmax_t kMaxFileBytes = uintmax_t(1) << 31;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The readers trace to OCCT's default messenger, which prints on stdout, where idview writes
// its JSON lines: take its console printers away, once per process.
void quietOcct() {
    static std::once_flag once;
    std::call_once(once, [] {
        Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    });
}

void checkFile(const std::string& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Bad("file not found");
    if (!fs::is_regular_file(path, ec)) throw Bad("not a regular file");
    const uintmax_t size = fs::file_size(path, ec);
    if (ec) throw Bad("cannot read the file size: " + ec.message());
    if (size == 0) throw Bad("the file is empty");
    if (size > kMaxFileBytes) throw Bad("file too large (" + std::to_string(size) + " bytes)");
}

// Open CASCADE crashes on some damaged files (7.6's IGES reader on a B-spline surface whose
// parameter lines are blank dereferences a null array): such a crash on this thread is
// refused in words that name the stage. Faults on the mesher's worker threads are not caught.
template <typename Body>
void guarded(const char* stage, Body&& body) {
    if (const int signal = runGuarded(body))
        throw Bad(std::string("Open CASCADE crashed while ") + stage + " (" + faultName(signal) +
                  "): the file is damaged or holds something its reader does not handle");
}

// The file's format, once the settings and the file itself are fit to load.
Format checkedFormat(const std::string& path, const CadOptions& options, uint32_t levels) {
    const Format format = formatOf(path);
    if (format == Format::None) throw Bad("not a STEP, IGES or BREP file name");
    if (!(options.deflection >= 0.0) || !std::isfinite(options.deflection))
        throw Bad("the linear deflection must be a finite number of at least 0");
    if (!(options.angularDeflection > 0.0) || !std::isfinite(options.angularDeflection))
        throw Bad("the angular deflection must be a positive number of radians");
    if (levels > maxLevels)
        throw Bad("levels of detail: 1 to " + std::to_string(maxLevels) + ", not " +
                  std::to_string(levels));
    checkFile(path);
    return format;
}

// What reading the file gives.
struct Read {
    std::vector<Leaf> leaves;
    ReaderLosses losses;
    double sewTolerance = 0.0; // IGES: its faces are sewn within it
};

Read readLeaves(const std::string& path, Format format, const std::string& stem,
                const CadProgress& progress, const std::atomic<bool>* cancel) {
    Read read;
    {
        const CoutCapture quiet;
        guarded("reading the file", [&] {
            read.leaves = format == Format::Brep ? readBrep(path, stem, progress, cancel)
                                                 : readXde(path, format, progress, read.losses,
                                                           read.sewTolerance, cancel);
        });
    }
    read.leaves = splitSolids(std::move(read.leaves), stem);
    if (read.leaves.empty()) throw Bad("the file holds no shapes");
    return read;
}

// kRelativeDeflection of the diagonal of the placed shapes' box.
double automaticDeflection(const Bnd_Box& world) {
    const double diagonal =
        world.IsVoid() || world.IsOpen() ? 0.0 : std::sqrt(world.SquareExtent());
    return std::isfinite(diagonal) && diagonal > 0.0 ? diagonal * kRelativeDeflection : 0.01;
}

// Refuses a tessellation that passed the budget, in words: what the whole would have come
// to, at the rate of the faces counted so far.
[[noreturn]] void refuseOverBudget(const std::vector<Distinct>& shapes, const MeshBudget& budget,
                                   double deflection) {
    uint64_t faces = 0;
    for (const Distinct& d : shapes) faces += uint64_t(d.faces.Extent());
    const double meshed = std::max(1.0, double(budget.facesMeshed.load()));
    const double estimate = double(budget.triangles) * std::max(1.0, double(faces) / meshed);
    throw Bad(triangleLimitReason(uint64_t(estimate), budget.maxTriangles, deflection));
}

// Every distinct shape sewn where the format needs it, then tessellated once, all in one call
// so that faces mesh in parallel. Returns the faces not meshed (edges off their surface).
std::set<const void*> tessellate(std::vector<Distinct>& shapes, const Read& read, double deflection,
                                 double automatic, const CadOptions& options,
                                 const CadProgress& progress, const std::atomic<bool>* cancel) {
    // Colours were matched by the faces as read; sewing keeps their order. A gap the file's
    // resolution leaves open but narrower than the deflection is below what the tessellation
    // draws (its triangles stray that far from the surface anyway), yet each side would be
    // sampled on its own and the background would show through: such gaps are sewn too, never
    // wider than the automatic deflection, so that a coarse --deflection cannot join edges that
    // are apart in the model. STEP and BREP files state their faces' shared edges; only IGES
    // files (sewTolerance set) are sewn.
    const double gapTolerance = std::min(deflection, automatic);
    guarded("sewing the faces", [&] {
        for (Distinct& d : shapes) sewFaces(d.shape, d.faces, read.sewTolerance, gapTolerance);
    });
    TopoDS_Compound all;
    BRep_Builder builder;
    builder.MakeCompound(all);
    for (const Distinct& d : shapes)
        if (d.faces.Extent() > 0) builder.Add(all, d.shape);
    IMeshTools_Parameters parameters;
    parameters.Deflection = deflection;
    parameters.Angle = options.angularDeflection;
    parameters.Relative = false;
    parameters.InParallel = true;
    Handle(ProgressRelay) relay;
    MeshBudget budget;
    budget.maxTriangles = options.maxTriangles;
    budget.cancel = cancel;
    guarded("checking the faces", [&] { budget.skipped = facesLeavingTheirSurface(all); });
    guarded("tessellating", [&] {
        meshCounted(all, parameters, budget, startStage(relay, progress, "tessellating", [&budget] {
                        return budget.stop();
                    }));
    });
    if (cancel && *cancel) throw Bad("cancelled");
    if (budget.over) refuseOverBudget(shapes, budget, deflection);
    return std::move(budget.skipped);
}

// Levels of detail: the shapes tessellated again (cad_levels.h), chosen among by the policy
// every kind of geometry shares (scene/lod_policy.h).
void addLevels(Scene& scene, const BrepShapes::Impl& kept, const std::set<const void*>& skipped,
               double deflection, const CadOptions& options, uint32_t levels,
               const CadProgress& progress, const std::atomic<bool>* cancel) {
    std::vector<GeometryCandidates> candidates =
        cadCandidates(scene, kept.geometries, deflection, options.angularDeflection, skipped,
                      [&](double fraction) {
                          if (cancel && *cancel) throw Bad("cancelled");
                          if (progress) progress("levels of detail", fraction);
                      });
    addChosenLevels(scene, candidates, LodOptions{.levels = levels});
}

void addWarnings(CadLoadResult& result, uint32_t faceless, const ReaderLosses& losses,
                 Format format, size_t skipped, uint32_t emptyShapes) {
    if (faceless)
        result.warnings.push_back(std::to_string(faceless) +
                                  " shapes without faces (wires or points) skipped");
    if (const auto dropped =
            lossWarning(losses, result.faces, format == Format::Step ? "STEP" : "IGES"))
        result.warnings.push_back(*dropped);
    if (skipped)
        result.warnings.push_back(std::to_string(skipped) +
                                  " faces have edges that run off their surface (a damaged "
                                  "file) and are not meshed");
    if (result.facesFailed)
        result.warnings.push_back(std::to_string(result.facesFailed) + " of " +
                                  std::to_string(result.faces) +
                                  " faces could not be triangulated and are left out");
    if (emptyShapes)
        result.warnings.push_back(std::to_string(emptyShapes) +
                                  " shapes had no face that triangulated and are left out");
}

// The stages in order: read, distinct shapes, sew and tessellate, build the geometries and
// objects, levels of detail, the shapes kept, warnings, and a last check.
CadLoadResult load(const std::string& path, const CadOptions& options, const CadProgress& progress,
                   uint32_t levels, const std::atomic<bool>* cancel) {
    const Format format = checkedFormat(path, options, levels);
    quietOcct();
    const std::string stem = fs::path(path).stem().string();
    CadLoadResult result;
    auto start = Clock::now();
    const Read read = readLeaves(path, format, stem, progress, cancel);
    result.readMs = msSince(start);
    DistinctShapes shapes = distinctShapes(read.leaves);
    if (shapes.faceless == read.leaves.size()) throw Bad("the file holds no shapes with faces");

    const double automatic = automaticDeflection(shapes.world);
    result.deflection = options.deflection == 0.0 ? automatic : options.deflection;
    start = Clock::now();
    const std::set<const void*> skipped =
        tessellate(shapes.shapes, read, result.deflection, automatic, options, progress, cancel);
    result.tessellationMs = msSince(start);

    Scene& scene = result.scene;
    Materials materials(scene);
    const BuiltGeometries built =
        buildGeometries(scene, shapes.shapes, stem, materials, progress, cancel);
    result.faces = built.faces;
    result.facesFailed = built.facesFailed;
    // Objects before levels: the levels chosen weigh the objects that draw each geometry.
    addObjects(scene, read.leaves, shapes, materials, stem);
    std::unique_ptr<BrepShapes::Impl> kept = keptShapes(shapes.shapes, scene.geometries.size());
    if (levels > 1) {
        start = Clock::now();
        addLevels(scene, *kept, skipped, result.deflection, options, levels, progress, cancel);
        result.levelsMs = msSince(start);
    }
    kept->geometries.resize(scene.geometries.size()); // levels have no shape
    scene.brep = std::make_shared<const BrepShapes>(std::move(kept));
    addWarnings(result, shapes.faceless, read.losses, format, skipped.size(), built.emptyShapes);
    try {
        validate(scene);
    } catch (const std::invalid_argument& e) {
        throw Bad(std::string("inconsistent tessellation: ") + e.what());
    }
    return result;
}

} // namespace

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

CadLoadResult loadCad(const std::string& path, const CadOptions& options,
                      const CadProgress& progress, uint32_t levels,
                      const std::atomic<bool>* cancel) {
    try {
        return load(path, options, progress, levels, cancel);
    } catch (const Bad& e) {
        // A reader broken off by the flag says only that it read nothing.
        if (cancel && *cancel) throw ModelError(path + ": cancelled");
        throw ModelError(path + ": " + e.what());
    } catch (const Standard_OutOfMemory&) {
        throw ModelError(path + ": out of memory");
    } catch (const Standard_Failure& e) {
        const char* message = e.GetMessageString();
        throw ModelError(path + ": Open CASCADE failed: " + e.DynamicType()->Name() +
                         (message && *message ? std::string(": ") + message : std::string()));
    } catch (const std::bad_alloc&) {
        throw ModelError(path + ": out of memory");
    }
}

} // namespace scene
