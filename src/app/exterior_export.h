// exterior_export.h - writing what a visibility census saw (its "exterior") to a file, for
// `idview --census-export` and the viewer's Export seen...: .glb the seen parts
// (scene::keptParts), .step/.stp the solids with a seen face (scene::writeStepSubset).
#pragma once

#include <cstdint>
#include <string>

#include "scene/cad/cad_loader.h"
#include "scene/census.h"
#include "scene/scene.h"

namespace app {

// What went into the file: its parts (glTF primitives, or the faces of the STEP's solids)
// and objects (glTF nodes, or STEP solids).
struct ExteriorWritten {
    uint32_t parts = 0, objects = 0;
};

// Before any work: a path that is not .glb, .step or .stp, or a STEP export of a mesh model
// (`scene` without a B-rep, loaded from `source`). Throws std::runtime_error with one line.
void checkExteriorExport(const std::string& path, const scene::Scene& scene,
                         const std::string& source);

// Writes `path` from `scene` (the scene the census counted: exploded where it was) and
// `census`; a STEP file reads `sourcePath` again, healed as `healing` says (step_exterior.h).
// The file appears whole or not at all. Blocks until written (seconds for a big STEP file);
// safe on any thread. Throws std::runtime_error with one line.
ExteriorWritten writeExterior(const std::string& path, const scene::Scene& scene,
                              const scene::Census& census, const std::string& sourcePath,
                              scene::Healing healing);

} // namespace app
