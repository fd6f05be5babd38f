// cad_worker.h - the worker's side of a CAD load (cad_jobs.h): jobs read from the socket the
// parent started it with (util/worker_pool.h), done with Open CASCADE, answered one by one.
// src/tools/load_worker.cpp is the whole program.
#pragma once

#include <string>

#include "scene/cad/cad_jobs.h"

namespace scene::cad {

// Answers jobs on `fd` until the parent closes it; returns the program's exit status.
int runLoadWorker(int fd);

// The jobs, as a worker does them (also called in process by tests). A job that fails in words
// (a damaged piece, out of memory) throws Bad; a crash inside Open CASCADE that the fault guard
// catches is one of those too.
SkeletonAnswer readSkeleton(const SkeletonJob& job);
PieceAnswer readPiece(const PieceJob& job);
WholeFileAnswer readWholeFile(const WholeFileJob& job, const CadProgress& progress = {});
// Writes the STEP file (step_export.cpp).
void writeStepExport(const StepExportJob& job);

} // namespace scene::cad
