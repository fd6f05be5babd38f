// cad_conform.h - a piece's objects and parts numbered as the file lists them. The parent of a
// split load gives every object its unique part IDs from the file's text, before Open CASCADE
// reads it (scene/step/step_split.h, RepLayout): one object per solid (or one for all), one
// part per face entity. Open CASCADE's reading nearly always agrees; where it does not (its
// healing dropped or split a face, a solid failed to translate), the piece's parts are laid
// out again in the file's numbers so that every other part keeps its ID. Internal; speaks Open
// CASCADE.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/cad/brep_occt.h"
#include "scene/scene.h"

namespace scene::cad {

// Makes `piece` (one object per solid as read, each with its geometry; `kept`: each geometry's
// shape) hold exactly objectFaces.size() objects with objectFaces[k] parts each. Where it
// already does, nothing changes. Else its parts, object by object in order, are dealt out to
// the layout's objects in order: an object short of parts gets empty ones, parts past the
// layout's last join the last object's last part; each object's vertices are placed by their
// object's placement first (the new objects sit at the product's origin), and each new
// geometry's shape is the compound of its parts' faces. Says so in `warnings`.
void conformToLayout(Scene& piece, std::vector<BrepShapes::Shape>& kept,
                     const std::vector<uint32_t>& objectFaces, std::vector<std::string>& warnings);

} // namespace scene::cad
