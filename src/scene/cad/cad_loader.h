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

struct CadOptions {
    // Linear deflection of the tessellation in model units; 0 picks
    // kRelativeDeflection x the model's bounding box diagonal.
    double deflection = 0.0;
    double angularDeflection = 0.5; // radians
    // The most triangles full detail may have (over the distinct shapes, before instancing):
    // the tessellation stops as soon as its faces pass it, and the load fails in words.
    uint64_t maxTriangles = kDefaultMaxTriangles;
    bool operator==(const CadOptions&) const = default;
};

// The automatic linear deflection, as a fraction of the bounding box diagonal.
constexpr double kRelativeDeflection = 0.001;

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
};

struct CadLoadResult : CadLoadFigures {
    Scene scene;
    std::vector<std::string> warnings;
};

// How far a load is: `stage` is "reading", "translating" (the file's entities into shapes),
// "tessellating", "building" (the scene) or "levels of detail", `fraction` 0..1 within it. Calls
// may come from Open CASCADE's worker threads, one at a time.
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

// True for .step/.stp/.iges/.igs/.brep in any case.
bool isCadPath(const std::string& path);

// The unit a CAD file's coordinates come out in: STEP and IGES in the one Open CASCADE's
// readers convert them to (its xstep.cascade.unit, millimetres unless changed), whatever
// unit the file was written in; BREP files store none.
LengthUnit cadUnit(const std::string& path);

// Loads the whole model. The result passes scene::validate(). Throws ModelError with one
// line "<path>: <reason>"; never returns a half-built scene. With `levels` above 1 (up to
// maxLevels, scene/lod.h), each shape also gets up to levels - 1 levels of detail: its faces
// tessellated again at coarser deflections (cad_levels.h), chosen among as every kind of
// geometry's candidates are (scene/lod_policy.h); progress then reports a "levels of detail"
// stage.
// While `cancel` is set the load stops at the next face or progress step, throwing ModelError
// "<path>: cancelled". A tessellation that passes options.maxTriangles stops between faces
// and throws ModelError "<path>: <triangleLimitReason>".
CadLoadResult loadCad(const std::string& path, const CadOptions& options = {},
                      const CadProgress& progress = {}, uint32_t levels = 1,
                      const std::atomic<bool>* cancel = nullptr);

// "the tessellation passes --max-triangles LIMIT (about ESTIMATE triangles at deflection D);
// try --deflection X": X is D scaled so that the estimate falls to half the limit (a curved
// face's triangles grow as 1 / deflection), rounded up to two significant digits.
std::string triangleLimitReason(uint64_t estimate, uint64_t limit, double deflection);

} // namespace scene
