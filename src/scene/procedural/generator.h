// generator.h - procedural scenes. `assembly` is a small machine-like assembly (the default
// until a model ships in assets/); `tiles` is a test layout where known parts cover known
// pixels (see tilesExpectedParts).
#pragma once

#include <string>
#include <vector>

#include "scene/camera.h"
#include "scene/scene.h"

namespace scene {

// A base plate on four columns carrying a top plate with a grid of bolts and two brackets.
// Bolts and columns are instanced geometries; every face is its own part.
Scene makeAssembly();

// Two instances of a sheet of 4 x 3 square tiles (one part each), side by side at z = 0,
// in front of one back plate at z = -1 that is listed last so only the depth test keeps
// it behind. Seen by tilesCamera, every part is visible and the tiles cover known pixels.
Scene makeTiles();
Camera tilesCamera();

// Names accepted by makeScene, in the order --help lists them.
const std::vector<std::string>& sceneNames();
// Throws std::invalid_argument for an unknown name.
Scene makeScene(const std::string& name);

} // namespace scene
