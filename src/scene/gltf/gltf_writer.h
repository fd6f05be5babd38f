// gltf_writer.h - saves a Scene as binary glTF (.glb): one mesh per (geometry, material)
// pair with one primitive per part, one root node per object, named after it, whose matrix
// also turns idview's z-up into glTF's y-up. Loading the file back in `primitives` part mode
// gives the same parts, triangles, unique part IDs and object names; the nodes are flat (a
// hierarchy would reorder objects and so change their IDs), so each path comes back as just
// the object's name. Empty parts (Part::empty) are left out, as glTF has no primitive without
// triangles, and an object without triangles is a node without a mesh: where a scene has
// them, the parts with triangles come back in order, numbered without the empty ones.
#pragma once

#include <string>

#include "scene/scene.h"

namespace scene {

// The rotation the writer puts into every node: idview's z-up to glTF's y-up.
glm::dmat4 zUpToYUp();

// The file appears whole or not at all (written beside it, then renamed). Throws
// std::runtime_error naming the file when it cannot be written.
void writeGlb(const Scene& scene, const std::string& path);

} // namespace scene
