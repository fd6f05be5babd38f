// exterior.h - a scene cut down to some of its unique parts: what a visibility census saw,
// for writing out the exterior of a model (--census-export FILE.glb). Plain scene data.
#pragma once

#include "scene/part_set.h"
#include "scene/scene.h"

namespace scene {

// The objects of `scene` with a part in `keep`, in order, each holding only those parts (in
// order, with their faces, surfaces and materials); their unique part IDs are numbered anew.
// An object keeping all its parts keeps its geometry; objects of one geometry keeping the
// same parts share one new geometry. Vertices and materials are shared with `scene`; the
// B-rep and levels of detail are not carried (the parts no longer match the shapes).
Scene keptParts(const Scene& scene, const PartSet& keep);

} // namespace scene
