// cad_piece.cpp - a worker's piece of a split STEP file (cad_worker.h): read from its text,
// split into its solids as the whole file's leaf would be, meshed at the load's deflection, and
// handed back as a small scene whose objects and parts are numbered as the file lists them
// (cad_conform.h), with each geometry's B-rep and, where asked, its candidate levels of detail.
#include <new>

#include <TopExp_Explorer.hxx>

#include "scene/cad/brep_occt.h"
#include "scene/cad/cad_conform.h"
#include "scene/cad/cad_healing.h"
#include "scene/cad/cad_stages.h"
#include "scene/cad/cad_worker.h"
#include "scene/mesh_closure.h"
#include "util/memory.h"

namespace scene::cad {
namespace {

// The reading's two halves, told apart by the moment the reader starts translating.
struct ReadTimes {
    Clock::time_point start = Clock::now(), translating = start;
    CadProgress progress() {
        return [this](const char* stage, double fraction) {
            if (fraction == 0.0 && std::string_view(stage) == "translating")
                translating = Clock::now();
        };
    }
};

CadOptions optionsOf(const MeshSettings& mesh) {
    CadOptions options;
    options.deflection = mesh.deflection;
    options.angularDeflection = mesh.angularDeflection;
    options.maxTriangles = mesh.maxTriangles;
    options.healing = mesh.healing;
    return options;
}

// Adds the reading's time (a piece read twice, healed the second time, counts both).
void readFigures(PieceAnswer& out, const ReadTimes& times, const ReaderLosses& losses) {
    const auto ms = [](Clock::time_point a, Clock::time_point b) {
        return std::chrono::duration<double, std::milli>(b - a).count();
    };
    const double healing = takeHealingMs();
    out.figures.parseMs += ms(times.start, times.translating);
    out.figures.healingMs += healing;
    out.figures.transferMs += ms(times.translating, Clock::now()) - healing;
    out.figures.entities = losses.entities;
    out.figures.failedEntities = losses.failedEntities;
    out.figures.faceEntities = losses.faceEntities;
}

// The piece's geometries and objects, one part per face (an empty one for a face that did not
// triangulate), before they are matched to the layout.
struct Built {
    Scene scene;
    std::vector<BrepShapes::Shape> kept;
    std::set<const void*> skipped;
    BuiltGeometries counts;
};

// Whether every geometry is of solids that meshed whole, each face triangulated, the surface
// closed and consistently oriented: what healing would have had to mend shows there.
bool meshedWhole(const Built& built) {
    if (built.counts.facesFailed > 0 || !built.skipped.empty()) return false;
    for (size_t g = 0; g < built.scene.geometries.size(); ++g) {
        const TopoDS_Shape& shape = built.kept[g].shape;
        if (shape.IsNull() || !TopExp_Explorer(shape, TopAbs_SOLID).More() ||
            TopExp_Explorer(shape, TopAbs_FACE, TopAbs_SOLID).More())
            return false; // faces of no solid: nothing tells what they should close
        if (!closedAndOriented(built.scene, built.scene.geometries[g])) return false;
    }
    return true;
}

Built build(const Read& read, const PieceJob& job, PieceAnswer& out) {
    Built built;
    DistinctShapes shapes = distinctShapes(read.leaves);
    if (shapes.faceless == read.leaves.size()) throw Bad("the piece holds no shape with faces");
    const CadOptions options = optionsOf(job.mesh);
    auto start = Clock::now();
    built.skipped = tessellate(shapes.shapes, 0.0, job.mesh.deflection, job.mesh.deflection,
                               options, {}, nullptr);
    out.figures.meshMs += msSince(start);
    start = Clock::now();
    Materials materials(built.scene);
    built.counts = buildGeometries(built.scene, shapes.shapes, "", materials, {}, nullptr);
    addObjects(built.scene, read.leaves, shapes, materials, "");
    built.kept = keptShapes(shapes.shapes, built.scene.geometries.size());
    out.figures.buildMs += msSince(start);
    return built;
}

// The piece read (healed or not) and meshed.
Built readAndBuild(const PieceJob& job, bool heal, PieceAnswer& out) {
    setStepHealing(heal);
    takeHealingMs();
    ReadTimes times;
    const Read read = readLeaves({"piece " + std::to_string(job.piece), &job.text}, Format::Step,
                                 "", times.progress(), nullptr);
    readFigures(out, times, read.losses);
    return build(read, job, out);
}

} // namespace

PieceAnswer readPiece(const PieceJob& job) {
    PieceAnswer out;
    out.piece = job.piece;
    quietOcct();
    bool heal = job.mesh.healing == Healing::On;
    Built built = readAndBuild(job, heal, out);
    if (job.mesh.healing == Healing::Auto && !meshedWhole(built)) {
        heal = true;
        built = readAndBuild(job, true, out);
    }
    out.figures.healed = heal;
    if (!built.skipped.empty())
        out.warnings.push_back(std::to_string(built.skipped.size()) +
                               " faces have edges that run off their surface (a damaged file) "
                               "and are not meshed");
    out.faces = built.counts.faces;
    out.facesFailed = built.counts.facesFailed;
    conformToLayout(built.scene, built.kept, job.objectFaces, out.warnings);
    if (job.mesh.levels > 1) {
        const auto start = Clock::now();
        out.candidates = levelCandidates(built.scene, built.kept, built.skipped,
                                         job.mesh.deflection, optionsOf(job.mesh), {}, nullptr);
        out.figures.levelsMs = msSince(start);
    }
    const auto start = Clock::now();
    for (const BrepShapes::Shape& shape : built.kept)
        out.brep.push_back(shape.shape.IsNull() ? std::string() : encodeShape(shape));
    out.mesh = std::move(built.scene);
    out.figures.encodeMs = msSince(start);
    out.figures.peakBytes = util::peakResidentBytes();
    return out;
}

} // namespace scene::cad
