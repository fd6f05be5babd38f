// gltf_loader.h - CAD models from glTF 2.0 (.gltf with external .bin or data URIs, and .glb)
// through tinygltf. Each mesh primitive becomes a part of its mesh's geometry (or, with
// PartMode::Components, each connected component of a primitive does); nodes that share a
// mesh share its geometry.
#pragma once

#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace scene {

enum class PartMode {
    Primitives, // one part per mesh primitive
    Components, // one part per connected component (triangles sharing a vertex index)
};

// "primitives" / "components"; parsePartMode throws std::invalid_argument otherwise.
const char* partModeName(PartMode mode);
PartMode parsePartMode(const std::string& name);

struct LoadOptions {
    PartMode parts = PartMode::Primitives;
};

struct LoadResult {
    Scene scene;
    std::vector<std::string> warnings; // e.g. "mesh 3 primitive 1: lines skipped"
};

// Loads the whole default scene of the file (all scenes' nodes if none is marked default).
// The result passes scene::validate(). Throws ModelError; never returns a half-built scene.
LoadResult loadGltf(const std::string& path, const LoadOptions& options = {});

// The same from bytes in memory (.gltf JSON or .glb, told apart by the GLB magic). `name`
// starts error messages, and its folder is where external buffers are looked up.
LoadResult loadGltfFromMemory(std::span<const unsigned char> bytes, const std::string& name,
                              const LoadOptions& options = {});

} // namespace scene
