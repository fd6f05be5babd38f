// cad_loader.h - CAD models in B-rep formats (STEP, IGES, BREP) through Open CASCADE.
//
// Mapping: every leaf shape instance of the assembly tree is one object, placed by the
// locations accumulated from the root; instances of one shape share one geometry; each face
// of that shape (in TopExp::MapShapes(shape, TopAbs_FACE) order) is one part. A face that
// does not triangulate has no triangles, and a part needs some (scene::validate), so such a
// face is left out (the parts after it move down one) and counted in CadLoadResult and in a
// warning. Names: the instance label's name, else the product's, else "<file stem> solid N";
// the path is the assembly names from the root joined by '/', the object's own name last.
// Colours: a face with an XCAF colour of its own (on the face, or on a solid or shell holding
// it) shows it (Geometry::partMaterials); the other faces take their object's material: the
// instance's colour, else the product's, else a default grey.
// This header stays free of Open CASCADE types.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace scene {

// The default --max-triangles. Measured on the 2-core development machine, shared with two
// other builds (Release, `idview --stats --no-cache`, peak resident memory by /usr/bin/time):
// Motor-c.brep at --deflection 0.003 --angular-deflection 0.05 makes 546,696 triangles in
// 166 MB and 18.6 s of tessellation; at 0.001 and 0.02, 2,236,816 triangles in 632 MB and
// 335 s. So about 280 bytes per triangle at load: 4 M triangles take about 1.1 GB, a small
// share of a 24 GB machine even with the renderer's copy beside it, while the time to mesh
// grows faster than the count (minutes of both cores already at 2 M), which the limit bounds
// too. A face is counted once meshed, so one huge face (terrain.brep: 230,288 triangles,
// 1.8 GB, 31.6 s) is not stopped half-way; the viewer's Cancel is.
constexpr uint64_t kDefaultMaxTriangles = 4'000'000;

enum class Healing : uint8_t { On, Off, Auto };
// "auto", "on", "off".
const char* healingName(Healing healing);

struct CadOptions {
    // Linear deflection of the tessellation in model units; 0 picks
    // kRelativeDeflection x the model's bounding box diagonal.
    double deflection = 0.0;
    double angularDeflection = 0.5; // radians
    // The most triangles full detail may have (over the distinct shapes, before instancing):
    // the tessellation stops as soon as its faces pass it, and the load fails in words.
    uint64_t maxTriangles = kDefaultMaxTriangles;
    // Open CASCADE's shape healing (ShapeFix) after a STEP file's translation, which takes
    // most of the translation's time (4.2 of 5.1 s on a 41 MB board): On (the default);
    // Off never, leaving the file's own flaws (gaps, wrong tolerances, missing seams) as they
    // are; Auto reads each piece of a split file without it and keeps that only where every
    // solid of the piece meshes whole (every face triangulated, every triangle edge met once
    // each way by another), else reads the piece again healed. Files read whole heal unless Off.
    Healing healing = Healing::On;
    // Worker processes that read, translate and mesh a file's pieces: 0, one per core. The
    // scene does not depend on it.
    unsigned workers = 0;
    bool operator==(const CadOptions&) const = default;
};

// The automatic linear deflection, as a fraction of the bounding box diagonal.
constexpr double kRelativeDeflection = 0.001;

// Where a parallel load spent its time and memory (--stats "stages"). Milliseconds of wall time
// for the parent's own stages; of the workers' own time, summed over pieces, for theirs.
struct CadStageFigures {
    bool split = false;   // read as a skeleton and pieces; else whole, in one worker
    std::string notSplit; // why not, where it was not
    uint32_t workers = 0; // worker processes
    uint32_t pieces = 0, piecesLost = 0, workerRestarts = 0;
    double lexMs = 0.0, splitMs = 0.0, skeletonMs = 0.0; // the parent's, before any piece
    double firstSolidMs = 0.0;   // from the start of the load to the first solid meshed
    double piecesMs = 0.0;       // from the first piece sent to the last answer
    double largestPieceMs = 0.0; // the longest piece: the parallel stage's floor
    uint32_t piecesHealed = 0;   // read healed: asked, or read again since they did not mesh whole
    double parseMs = 0.0, transferMs = 0.0, healingMs = 0.0, meshMs = 0.0, buildMs = 0.0,
           levelsMs = 0.0, encodeMs = 0.0; // the workers', summed
    double assemblyMs = 0.0;               // the parent putting the answers together, levels chosen
    // Peak resident memory of the whole process tree (this process and its workers added up,
    // sampled while it waits), per stage, and the workers' own peaks at their largest.
    uint64_t peakLexBytes = 0, peakSkeletonBytes = 0, peakPiecesBytes = 0, peakAssemblyBytes = 0;
    uint64_t peakWorkerBytes = 0;
};

// What a CAD load took and did, beside the scene it built.
struct CadLoadFigures {
    double readMs = 0.0;         // parsing the file and building the shapes
    double tessellationMs = 0.0; // sewing (IGES) and BRepMesh_IncrementalMesh, every distinct shape
    double levelsMs = 0.0;       // the coarser tessellations of the levels of detail
    double deflection = 0.0;     // the linear deflection used, in model units
    uint32_t faces = 0;          // faces over all distinct shapes
    uint32_t facesFailed = 0;    // of those, the ones without triangles (left out)
    // The tessellation cache (scene/cad/cad_cache.h): "off" (not asked, or no folder), "hit" or
    // "miss"; for misses and "off" what happened ("no entry", "checksum mismatch", ...); the
    // time spent reading (hit) or writing (miss) the entry.
    std::string cache = "off";
    std::string cacheNote;
    double cacheMs = 0.0;
    CadStageFigures stages;
};

struct CadLoadResult : CadLoadFigures {
    Scene scene;
    std::vector<std::string> warnings;
};

// How far a load is: `stage` and `fraction` 0..1 within it. A file read whole goes through
// "reading", "translating" (the file's entities into shapes), "tessellating", "building" (the
// scene) and "levels of detail"; a split STEP file through "reading" (its text lexed and
// split), "reading the assembly structure", "loading solids" (the pieces read, translated and
// meshed by the workers: the share of them done) and "building". Calls may come from Open
// CASCADE's worker threads, one at a time.
using CadProgress = std::function<void(const char* stage, double fraction)>;

// While one lives, LeakSanitizer does not track this thread's new allocations (in ASan
// builds; nothing otherwise). Only around Open CASCADE calls that leak by design: the
// data-exchange toolkits' one-time registrations (first reader, writer or XDE application of
// the process) and the IGES parser's buffers on a failed read.
struct OcctLeaksIgnored {
    OcctLeaksIgnored();
    ~OcctLeaksIgnored();
    OcctLeaksIgnored(const OcctLeaksIgnored&) = delete;
    OcctLeaksIgnored& operator=(const OcctLeaksIgnored&) = delete;
};

// True for the names of the formats Open CASCADE reads as B-reps (scene/formats.h: STEP,
// IGES, BREP), in any case.
bool isCadPath(const std::string& path);

// The unit a CAD file's coordinates come out in: STEP and IGES in the one Open CASCADE's
// readers convert them to (its xstep.cascade.unit, millimetres unless changed), whatever
// unit the file was written in; BREP files store none.
LengthUnit cadUnit(const std::string& path);

// What a load has shown so far, for a viewer that draws it while the rest loads. Every object
// of the model is there from the start, with its final unique part IDs (a pick or selection
// made now stays valid); an object whose solid is not meshed yet draws nothing (its geometry's
// parts have no triangles) and has the box of its vertices as the file states them.
struct CadPartial {
    std::shared_ptr<const Scene> scene;
    std::vector<Bounds> boxes;  // per object, in the world
    std::vector<uint8_t> state; // per object: kObjectWaiting, kObjectReady or kObjectLost
    uint32_t solidsReady = 0, solidsLost = 0, solidsTotal = 0;
    uint64_t bytesDone = 0, bytesTotal = 0; // of the file's pieces, read and meshed
};
constexpr uint8_t kObjectWaiting = 0, kObjectReady = 1, kObjectLost = 2;
// Called on the loading thread: first with the assembly tree and every box, then as solids
// come, at most every so often (and not at all for files that are read whole).
using CadPartialSink = std::function<void(const CadPartial&)>;

// Loads the whole model. The result passes scene::validate(). Throws ModelError with one
// line "<path>: <reason>"; never returns a half-built scene. With `levels` above 1 (up to
// maxLevels, scene/lod.h), each shape also gets up to levels - 1 levels of detail: its faces
// tessellated again at coarser deflections (cad_levels.h), chosen among as every kind of
// geometry's candidates are (scene/lod_policy.h); progress then reports a "levels of detail"
// stage.
// While `cancel` is set the load stops at the next face or progress step, throwing ModelError
// "<path>: cancelled". A tessellation that passes options.maxTriangles stops between faces
// and throws ModelError "<path>: <triangleLimitReason>".
//
// STEP files are split into a skeleton and pieces (scene/step/step_split.h) that worker
// processes read, translate and mesh in parallel (options.workers); other files, and STEP files
// that cannot be split, are read whole by one worker. A worker that crashes or is killed costs
// the solids it was on (named in a warning), never the load; no worker outlives the call.
CadLoadResult loadCad(const std::string& path, const CadOptions& options = {},
                      const CadProgress& progress = {}, uint32_t levels = 1,
                      const std::atomic<bool>* cancel = nullptr,
                      const CadPartialSink& partial = {});

// The whole file read in this process, on its threads: what a worker does with a file it
// reads whole, and what the fuzzer drives. Same contract as loadCad.
CadLoadResult loadCadInProcess(const std::string& path, const CadOptions& options = {},
                               const CadProgress& progress = {}, uint32_t levels = 1,
                               const std::atomic<bool>* cancel = nullptr);

// "the tessellation passes --max-triangles LIMIT (about ESTIMATE triangles at deflection D);
// try --deflection X": X is D scaled so that the estimate falls to half the limit (a curved
// face's triangles grow as 1 / deflection), rounded up to two significant digits.
std::string triangleLimitReason(uint64_t estimate, uint64_t limit, double deflection);

} // namespace scene
