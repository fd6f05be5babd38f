// cad_jobs.h - what the parent of a CAD load and its worker processes (util/worker_pool.h) say
// to each other: the jobs (the skeleton of a split STEP file, one piece of it, or a whole file)
// and their answers, as bytes (scene_codec.h's writer and reader). Both ends are this build of
// idview, so the layout needs no version. Plain C++: the worker's side, which runs Open
// CASCADE, is cad_worker.h.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "scene/cad/cad_loader.h"
#include "scene/lod_policy.h"
#include "scene/scene.h"

namespace scene::cad {

enum class JobKind : uint32_t { Skeleton = 1, Piece = 2, WholeFile = 3, StepExport = 4 };
// Failed: the job's reason in words (the piece is lost, the load goes on); Stopped: the job
// found that the load cannot go on (its triangles pass --max-triangles), in words.
enum class AnswerKind : uint32_t {
    Skeleton = 101,
    Piece = 102,
    WholeFile = 103,
    StepExport = 104, // the STEP file is written (no bytes)
    Progress = 150,   // a stage and how far it is, while a whole file loads
    Stopped = 198,
    Failed = 199
};

// How every shape of one load is meshed.
struct MeshSettings {
    double deflection =
        0.0; // model units, never 0 in a job: the parent works out the automatic one
    double angularDeflection = 0.5;
    uint32_t levels = 1;
    Healing healing = Healing::On; // Open CASCADE's shape healing after a STEP transfer
    uint64_t maxTriangles = kDefaultMaxTriangles;
};

// The skeleton of a split STEP file (scene/step/step_split.h) and the entity numbers of its
// pieces' GEOMETRIC_SETs, by piece.
struct SkeletonJob {
    std::string text;
    std::vector<uint64_t> dummySets;
};

// A leaf of the skeleton's assembly tree, as the whole file would give it.
struct SkeletonLeaf {
    int32_t piece = -1; // whose set its shape is; -1: no piece's (a shape of the skeleton's own)
    uint32_t faces = 0; // faces of a shape of the skeleton's own (0 for a piece's set)
    glm::dmat4 world{1.0};
    std::string name, product, group;
    std::optional<glm::dvec4> color; // the instance's colour (the product's comes with its piece)
    glm::dvec3 boxMin{0.0}, boxMax{0.0}; // the set's two points, in model units
};

struct SkeletonAnswer {
    std::vector<SkeletonLeaf> leaves;
    uint32_t entities = 0, failedEntities = 0; // what the reader dropped of the skeleton
    double ms = 0.0;
};

// One piece: its text, the objects its parts must come out as (RepLayout), how to mesh.
struct PieceJob {
    uint32_t piece = 0;
    std::string text;
    std::vector<uint32_t> objectFaces;
    MeshSettings mesh;
};

// What a worker spent on a piece or a whole file, in milliseconds of its own time.
struct WorkerFigures {
    double parseMs = 0.0, transferMs = 0.0, healingMs = 0.0, meshMs = 0.0, buildMs = 0.0,
           levelsMs = 0.0, encodeMs = 0.0;
    uint64_t peakBytes = 0; // the worker's VmHWM when it answered
    bool healed = false;    // read with Open CASCADE's healing (Auto: read again with it)
    uint32_t entities = 0, failedEntities = 0, faceEntities = 0; // ReaderLosses
};

struct PieceAnswer {
    uint32_t piece = 0;
    // One object per layout object, in order, each with its geometry (objects may share one),
    // its placement within the product (`world`), and material 0 ("default": no colour of its
    // own) or the product's colour; materials are the piece's colours; part materials the
    // faces' own colours. Unique part IDs as the layout numbers them.
    Scene mesh;
    std::vector<std::string> brep;              // per geometry: encodeShape's bytes
    std::vector<GeometryCandidates> candidates; // levels of detail to choose among
    std::vector<std::string> warnings;
    uint32_t faces = 0, facesFailed = 0;
    WorkerFigures figures;
};

// A file read whole, as before files were split: IGES, BREP, and STEP files the splitter
// could not split. `options.deflection` 0 asks for the automatic one.
struct WholeFileJob {
    std::string path;
    CadOptions options;
    uint32_t levels = 1;
};

struct WholeFileAnswer {
    CadLoadResult result; // its scene's B-rep encoded in `brep`
    std::vector<std::string> brep;
    WorkerFigures figures;
};

// A STEP file of some objects of a scene loaded from a CAD file (step_exterior.h): the source
// read again whole, healed as the scene was, its objects checked against the scene's by path.
struct StepExportJob {
    std::string source;
    std::string out; // written at partialStepPath(out), then renamed
    Healing healing = Healing::On;
    std::vector<std::string> paths; // the scene's objects, in order
    std::vector<uint8_t> keep;      // per object: nonzero to write it
};
// Where the worker writes the file before renaming it to `out`, so that it appears whole.
inline std::string partialStepPath(const std::string& out) {
    return out + ".part";
}

// A Progress frame's bytes: the stage's name and the fraction.
std::string encodeProgress(const char* stage, double fraction);
std::pair<std::string, double> decodeProgress(std::string_view bytes);

std::string encode(const SkeletonJob& job);
std::string encode(const SkeletonAnswer& answer);
std::string encode(const PieceJob& job);
std::string encode(const PieceAnswer& answer);
std::string encode(const WholeFileJob& job);
std::string encode(const WholeFileAnswer& answer);
std::string encode(const StepExportJob& job);
// Throw std::runtime_error on bytes that do not hold what encode wrote.
SkeletonJob decodeSkeletonJob(std::string_view bytes);
SkeletonAnswer decodeSkeletonAnswer(std::string_view bytes);
PieceJob decodePieceJob(std::string_view bytes);
PieceAnswer decodePieceAnswer(std::string_view bytes);
WholeFileJob decodeWholeFileJob(std::string_view bytes);
WholeFileAnswer decodeWholeFileAnswer(std::string_view bytes);
StepExportJob decodeStepExportJob(std::string_view bytes);

} // namespace scene::cad
