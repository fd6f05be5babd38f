// gltf_detail.h - internals of the glTF loader shared by its source files: checked accessor
// reads and the conversion of one glTF mesh into parts of a geometry. Not a public interface.
#pragma once

#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "scene/gltf/gltf_loader.h"
#include "scene/mesh_builder.h"

namespace scene::gltf {

// A reason the model cannot be loaded, without the path; loadGltf adds "<path>: ".
struct Bad : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The bytes of a model file: a regular file of sane size, whole. Throws Bad.
std::vector<unsigned char> readFileBytes(const std::string& path);

// tinygltf's messages span lines and may quote file content: one printable line of them.
std::string oneLine(const std::string& text);

// The file parsed as glTF 2.0 (gltf_parse.cpp): its GLB container and version checked first,
// external buffers read only from inside `name`'s folder, images skipped; tinygltf's warnings
// go to `warnings`. Throws Bad.
tinygltf::Model parse(std::span<const unsigned char> bytes, const std::string& name,
                      std::vector<std::string>& warnings);

// Throws Bad naming the first required extension idview cannot honour.
void checkRequiredExtensions(const std::vector<std::string>& required);

// Float VEC3 attribute data (POSITION, NORMAL), sparse substitution applied. Every byte read
// is range-checked first; `what` names the attribute in messages.
std::vector<glm::vec3> readVec3(const tinygltf::Model& model, int accessor,
                                const std::string& what);

// u8/u16/u32 SCALAR index data, widened to 32 bits.
std::vector<uint32_t> readIndices(const tinygltf::Model& model, int accessor);

// What addMesh produced: whether any triangle part was added, and the glTF material of the
// first triangle primitive (-1: none), which becomes the objects' material.
struct MeshInfo {
    bool hasTriangles = false;
    int material = -1;
};

// Adds the triangle primitives of glTF mesh `mesh` to `builder` as parts (one per primitive
// or one per connected component). Points and lines are skipped with a warning.
MeshInfo addMesh(const tinygltf::Model& model, int mesh, PartMode mode, MeshBuilder& builder,
                 std::vector<std::string>& warnings);

} // namespace scene::gltf
