// cad_surface.h - a B-rep face's SurfaceInfo, measured by Open CASCADE at load.
#pragma once

#include <TopoDS_Face.hxx>

#include "scene/surface_info.h"

namespace scene {

SurfaceInfo surfaceOf(const TopoDS_Face& face);

} // namespace scene
