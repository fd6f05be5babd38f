// cad_stages.cpp - the stages of reading a CAD file in one process (cad_stages.h).
#include "scene/cad/cad_stages.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <mutex>

#include <BRep_Builder.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <TopoDS_Compound.hxx>

#include "scene/cad/cad_check.h"
#include "scene/cad/cad_levels.h"
#include "scene/cad/cad_mesh.h"
#include "scene/cad/cad_sew.h"

namespace scene::cad {
namespace {

namespace fs = std::filesystem;

// Far beyond any sample; a bound on what the readers are asked to hold in memory. A STEP file
// is split before any reader sees it (each reads a piece), so it may be larger: it is only
// mapped and indexed, about 31 bytes an entity.
constexpr uintmax_t kMaxFileBytes = uintmax_t(1) << 31;
constexpr uintmax_t kMaxStepBytes = uintmax_t(1) << 36;

void checkFile(const std::string& path, Format format) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Bad("file not found");
    if (!fs::is_regular_file(path, ec)) throw Bad("not a regular file");
    const uintmax_t size = fs::file_size(path, ec);
    if (ec) throw Bad("cannot read the file size: " + ec.message());
    if (size == 0) throw Bad("the file is empty");
    if (size > (format == Format::Step ? kMaxStepBytes : kMaxFileBytes))
        throw Bad("file too large (" + std::to_string(size) + " bytes)");
}

// Refuses a tessellation that passed the budget, in words: what the whole would have come
// to, at the rate of the faces counted so far.
[[noreturn]] void refuseOverBudget(const std::vector<Distinct>& shapes, const MeshBudget& budget,
                                   double deflection) {
    uint64_t faces = 0;
    for (const Distinct& d : shapes) faces += uint64_t(d.faces.Extent());
    const double meshed = std::max(1.0, double(budget.facesMeshed.load()));
    const double estimate = double(budget.triangles) * std::max(1.0, double(faces) / meshed);
    throw OverBudget(triangleLimitReason(uint64_t(estimate), budget.maxTriangles, deflection));
}

} // namespace

void checkWholeFileSize(const std::string& path) {
    std::error_code ec;
    const uintmax_t size = fs::file_size(path, ec);
    if (!ec && size > kMaxFileBytes)
        throw Bad("file too large to read whole (" + std::to_string(size) + " bytes)");
}

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void quietOcct() {
    static std::once_flag once;
    std::call_once(once, [] {
        Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    });
}

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
    checkFile(path, format);
    return format;
}

Read readLeaves(const XdeSource& source, Format format, const std::string& stem,
                const CadProgress& progress, const std::atomic<bool>* cancel) {
    Read read;
    {
        const CoutCapture quiet;
        guarded("reading the file", [&] {
            read.leaves = format == Format::Brep ? readBrep(source.path, stem, progress, cancel)
                                                 : readXde(source, format, progress, read.losses,
                                                           read.sewTolerance, cancel);
        });
    }
    read.leaves = splitSolids(std::move(read.leaves), stem);
    if (read.leaves.empty()) throw Bad("the file holds no shapes");
    return read;
}

double automaticDeflection(const Bnd_Box& world) {
    const double diagonal =
        world.IsVoid() || world.IsOpen() ? 0.0 : std::sqrt(world.SquareExtent());
    return std::isfinite(diagonal) && diagonal > 0.0 ? diagonal * kRelativeDeflection : 0.01;
}

std::set<const void*> tessellate(std::vector<Distinct>& shapes, double sewTolerance,
                                 double deflection, double gapTolerance, const CadOptions& options,
                                 const CadProgress& progress, const std::atomic<bool>* cancel) {
    // Colours were matched by the faces as read; sewing keeps their order. STEP and BREP
    // files state their faces' shared edges; only IGES files (sewTolerance set) are sewn.
    guarded("sewing the faces", [&] {
        for (Distinct& d : shapes) sewFaces(d.shape, d.faces, sewTolerance, gapTolerance);
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

std::vector<GeometryCandidates>
levelCandidates(const Scene& scene, const std::vector<BrepShapes::Shape>& kept,
                const std::set<const void*>& skipped, double deflection, const CadOptions& options,
                const CadProgress& progress, const std::atomic<bool>* cancel) {
    return cadCandidates(scene, kept, deflection, options.angularDeflection, skipped,
                         [&](double fraction) {
                             if (cancel && *cancel) throw Bad("cancelled");
                             if (progress) progress("levels of detail", fraction);
                         });
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
                                  " faces could not be triangulated: their parts draw nothing");
    if (emptyShapes)
        result.warnings.push_back(std::to_string(emptyShapes) +
                                  " shapes had no face that triangulated: they draw nothing");
}

} // namespace scene::cad
