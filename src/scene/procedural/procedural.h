// procedural.h - deterministic machine-like assemblies generated from a seed: plates with
// holes, shafts, bolts and nuts, gears, brackets and pipes, every tessellated face its own
// part with its own vertices, geometries instanced many times, and a long-tailed part size
// distribution. Presets: `small` (tests) and `car-like` (the statistics of the model in the
// reference sample's results table: ~2,260 objects, ~99,000 parts, 2.3-2.4 M triangles).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace scene {

struct ProceduralOptions {
    std::string preset = "small";
    uint64_t seed = 1;
};

// Preset names in the order help texts list them.
const std::vector<std::string>& proceduralPresets();

// Same options, same scene, bit for bit. Throws std::invalid_argument for an unknown preset.
Scene makeProcedural(const ProceduralOptions& options);

} // namespace scene
