// cad_stages.h - the stages of reading a CAD file in one process, shared by the whole-file
// load (cad_loader.cpp: IGES, BREP, STEP files that are not split) and a worker's piece of a
// split STEP file (cad_piece.cpp): checks, reading down to the leaves, sewing and tessellating
// the distinct shapes, levels of detail, and the warnings. Internal; speaks Open CASCADE.
#pragma once

#include <atomic>
#include <chrono>
#include <set>
#include <string>
#include <vector>

#include <Bnd_Box.hxx>

#include "scene/cad/cad_build.h"
#include "scene/cad/cad_read.h"
#include "scene/cad/fault_guard.h"
#include "scene/lod_policy.h"

namespace scene::cad {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point start);

// The readers trace to OCCT's default messenger, which prints on stdout, where idview writes
// its JSON lines: takes its console printers away, once per process.
void quietOcct();

// Open CASCADE crashes on some damaged files (7.6's IGES reader on a B-spline surface whose
// parameter lines are blank dereferences a null array): such a crash on this thread is
// refused in words that name the stage. Faults on the mesher's worker threads are not caught
// (in a worker process they end the worker alone, and the parent says what that cost).
template <typename Body>
void guarded(const char* stage, Body&& body) {
    if (const int signal = runGuarded(body))
        throw Bad(std::string("Open CASCADE crashed while ") + stage + " (" + faultName(signal) +
                  "): the file is damaged or holds something its reader does not handle");
}

// The file's format, once the settings and the file itself are fit to load. Throws Bad.
Format checkedFormat(const std::string& path, const CadOptions& options, uint32_t levels);
// Throws Bad where the file is too large for a reader to hold whole (a STEP file may be
// larger when it is split).
void checkWholeFileSize(const std::string& path);

// What reading a file gives.
struct Read {
    std::vector<Leaf> leaves;
    ReaderLosses losses;
    double sewTolerance = 0.0; // IGES: its faces are sewn within it
};

// The leaves of the file (or STEP text), compounds split into their solids (splitSolids).
// Throws Bad where it holds no shape.
Read readLeaves(const XdeSource& source, Format format, const std::string& stem,
                const CadProgress& progress, const std::atomic<bool>* cancel);

// kRelativeDeflection of the diagonal of `world`.
double automaticDeflection(const Bnd_Box& world);

// Every distinct shape sewn where the format needs it (sewTolerance, gaps narrower than
// `gapTolerance`), then tessellated at `deflection` once, all in one call so that faces mesh in
// parallel. Throws Bad when cancelled or past options.maxTriangles. Returns the faces not
// meshed (edges off their surface).
std::set<const void*> tessellate(std::vector<Distinct>& shapes, double sewTolerance,
                                 double deflection, double gapTolerance, const CadOptions& options,
                                 const CadProgress& progress, const std::atomic<bool>* cancel);

// Levels of detail: the shapes tessellated again (cad_levels.h), chosen among as every kind of
// geometry's are (scene/lod_policy.h), or, with `keep`, the candidates handed back unchosen.
std::vector<GeometryCandidates>
levelCandidates(const Scene& scene, const std::vector<BrepShapes::Shape>& kept,
                const std::set<const void*>& skipped, double deflection, const CadOptions& options,
                const CadProgress& progress, const std::atomic<bool>* cancel);

// The warnings of a load: faceless leaves, what the reader dropped, faces not meshed, faces
// and shapes without triangles.
void addWarnings(CadLoadResult& result, uint32_t faceless, const ReaderLosses& losses,
                 Format format, size_t skipped, uint32_t emptyShapes);

} // namespace scene::cad
