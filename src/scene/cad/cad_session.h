// cad_session.h - a CAD load done by worker processes (loadCad, cad_loader.h): a STEP file
// split by the lexer (scene/step/step_split.h), its skeleton read first, its pieces read,
// translated and meshed by the workers in parallel and put together as they come
// (cad_assembly.h); any other file read whole by one worker. The parent never runs Open
// CASCADE's readers. Internal to the CAD loader.
#pragma once

#include <atomic>
#include <string>

#include "scene/cad/cad_loader.h"

namespace scene::cad {

// Throws Bad (the loader puts the path in front) or ModelError (already named).
CadLoadResult loadWithWorkers(const std::string& path, const CadOptions& options,
                              const CadProgress& progress, uint32_t levels,
                              const std::atomic<bool>* cancel, const CadPartialSink& partial);

// The worker program: $IDVIEW_LOAD_WORKER, else idview-load-worker beside this executable, else
// ../libexec/idview (installed), else this binary's build folder. Throws Bad where there is none.
std::string loadWorkerProgram();

// options.workers, or one per core.
unsigned workerCount(const CadOptions& options);

} // namespace scene::cad
