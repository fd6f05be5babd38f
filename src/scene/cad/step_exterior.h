// step_exterior.h - a STEP file of some of a CAD scene's objects (the visibility census's
// "exterior"): the scene's source file read again in a worker process (Open CASCADE's readers
// are not thread-safe) and its assembly copied with only the kept leaf instances, keeping
// names and colours. Free of Open CASCADE types; the worker's side is step_export.cpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/cad/cad_loader.h"
#include "scene/scene.h"

namespace scene {

// Writes `outPath` (STEP AP214, through Open CASCADE's XCAF writer) holding the objects of
// `scene` that `keepObject` marks nonzero: one entry per object, in scene order. `scene` must
// be what loadCad made of `sourcePath` (a STEP, IGES or BREP file), with `healing` as it was
// loaded (the source is read again, whole; its objects are checked against the scene's by
// path). A leaf instance not kept leaves the assembly (another instance of its shape stays),
// an assembly left empty goes too; a compound split into solids keeps only the kept ones.
// Names and colours (instance, product, face) stay as the reader gave them; a BREP source's
// solids go under one product named after its stem. The file appears whole or not at all
// (written beside it, then renamed). Safe on any thread; blocks until written.
// Throws std::runtime_error with one line for people: nothing kept, a source that is not a
// CAD file, a path that cannot be written, a source that no longer gives the scene, a
// reader's or writer's failure.
void writeStepSubset(const std::string& sourcePath, const Scene& scene,
                     const std::vector<uint8_t>& keepObject, const std::string& outPath,
                     Healing healing = Healing::On);

} // namespace scene
