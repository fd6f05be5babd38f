// mesh_closure.h - whether a geometry's triangles close up into consistently oriented
// surfaces: every edge (by its ends' positions) met once in each direction. A closed solid's
// tessellation, its faces' edge points shared (scene/cad/cad_shared_points.h), does; a face
// missing, a gap between faces or a face turned the wrong way does not. Plain C++.
#pragma once

#include "scene/scene.h"

namespace scene {

// Edges whose ends are one point (a collapsed triangle's side) are left out.
bool closedAndOriented(const Scene& scene, const Geometry& geometry);

} // namespace scene
