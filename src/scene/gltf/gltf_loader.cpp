// gltf_loader.cpp - loadGltf: parses a .gltf/.glb with tinygltf, walks the node hierarchy of
// the default scene and builds a Scene; every failure becomes one ModelError line.
#include "scene/gltf/gltf_loader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <new>
#include <string_view>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene/gltf/gltf_detail.h"

namespace scene {
namespace {

using gltf::Bad;
namespace fs = std::filesystem;

using gltf::checkRequiredExtensions;
using gltf::oneLine;
using gltf::parse;
using gltf::readFileBytes;

constexpr size_t kMaxObjects = size_t(1) << 24;

// In double, as the file gives it: a root node at map coordinates keeps its millimetres.
glm::dmat4 localTransform(const tinygltf::Node& node, size_t index) {
    const std::string name = "node " + std::to_string(index);
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) throw Bad(name + " has a matrix without 16 numbers");
        return glm::make_mat4(node.matrix.data()); // both column-major
    }
    if ((!node.translation.empty() && node.translation.size() != 3) ||
        (!node.rotation.empty() && node.rotation.size() != 4) ||
        (!node.scale.empty() && node.scale.size() != 3))
        throw Bad(name + " has a malformed translation, rotation or scale");
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (!node.translation.empty())
        t = glm::translate(glm::dmat4(1.0), glm::make_vec3(node.translation.data()));
    if (!node.rotation.empty()) {
        const auto& q = node.rotation; // glTF order x, y, z, w
        glm::dquat quat{q[3], q[0], q[1], q[2]};
        const double len = glm::length(quat);
        if (len > 0.0 && std::isfinite(len)) r = glm::mat4_cast(quat / len);
    }
    if (!node.scale.empty()) s = glm::scale(glm::dmat4(1.0), glm::make_vec3(node.scale.data()));
    return t * r * s;
}

bool isFinite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// The name of node `index`, which the object it places takes and which is its element of
// every path through it: the node's own name; for a node without one, the name of its mesh;
// when both are empty (or it has no mesh), "node <index>" with the node's index in the file,
// which no other node shares. Names are kept as the file spells them, '/' included.
std::string nodeName(const tinygltf::Model& model, size_t index) {
    const tinygltf::Node& node = model.nodes[index];
    if (!node.name.empty()) return node.name;
    if (node.mesh >= 0 && size_t(node.mesh) < model.meshes.size() &&
        !model.meshes[size_t(node.mesh)].name.empty())
        return model.meshes[size_t(node.mesh)].name;
    return "node " + std::to_string(index);
}

// Every object keeps a copy of its path, so a crafted deep chain of nodes with meshes would
// need memory quadratic in its depth: a path longer than this keeps only its last elements
// that fit, after ".../" (the object's own name always stays whole).
constexpr size_t kMaxPathChars = 1024;

std::string clipPath(const std::string& path) {
    const size_t last = path.rfind('/');
    if (path.size() <= kMaxPathChars || last == std::string::npos) return path;
    const size_t cut = std::min(path.find('/', path.size() - kMaxPathChars), last);
    return ".../" + path.substr(cut + 1);
}

// Builds the Scene from a parsed model: geometries on first use, objects per node instance.
class Builder {
  public:
    Builder(const tinygltf::Model& model, const LoadOptions& options)
        : model_(model), options_(options), geometryOfMesh_(model.meshes.size(), kUnbuilt),
          materialForMesh_(model.meshes.size(), 0), materialOf_(model.materials.size(), kUnbuilt) {}

    LoadResult build(std::vector<std::string> warnings) {
        result_.warnings = std::move(warnings);
        checkParents();
        for (int root : roots()) addTree(root);
        if (result_.scene.objects.empty()) throw Bad("empty scene: nothing with triangles to show");
        try {
            validate(result_.scene);
        } catch (const std::invalid_argument& e) {
            throw Bad(e.what());
        }
        return std::move(result_);
    }

  private:
    static constexpr int64_t kUnbuilt = -2, kDropped = -1;

    void checkNodeIndex(int index, const std::string& who) const {
        if (index < 0 || size_t(index) >= model_.nodes.size())
            throw Bad(who + " refers to missing node " + std::to_string(index));
    }

    // glTF nodes form strict trees; a node listed as a child twice would be drawn twice and
    // a crafted file could make that exponential, so it is an error like a cycle.
    void checkParents() {
        parentCount_.assign(model_.nodes.size(), 0);
        for (size_t n = 0; n < model_.nodes.size(); ++n)
            for (int child : model_.nodes[n].children) {
                checkNodeIndex(child, "node " + std::to_string(n));
                if (++parentCount_[size_t(child)] > 1)
                    throw Bad("node " + std::to_string(child) + " has more than one parent");
            }
    }

    std::vector<int> roots() {
        const auto& scenes = model_.scenes;
        if (model_.defaultScene >= 0 && size_t(model_.defaultScene) >= scenes.size())
            throw Bad("the default scene " + std::to_string(model_.defaultScene) +
                      " does not exist");
        std::vector<int> out;
        for (size_t s = 0; s < scenes.size(); ++s)
            if (model_.defaultScene < 0 || size_t(model_.defaultScene) == s)
                for (int n : scenes[s].nodes) {
                    checkNodeIndex(n, "scene " + std::to_string(s));
                    out.push_back(n);
                }
        return out;
    }

    // Depth-first without recursion (a deep chain must not overflow the stack); a node met
    // again while it is still on the current path is a cycle. `path_` holds the names of the
    // nodes on the current path; leaving a node cuts it back to its parent's.
    void addTree(int root) {
        struct Step {
            int node;
            glm::dmat4 parentWorld;
            bool leave;
            size_t parentPathLength;
        };
        std::vector<Step> stack{{root, glm::dmat4(1.0), false, 0}};
        onPath_.resize(model_.nodes.size(), false);
        path_.clear();
        while (!stack.empty()) {
            Step step = stack.back();
            stack.pop_back();
            size_t n = size_t(step.node);
            if (step.leave) {
                onPath_[n] = false;
                path_.resize(step.parentPathLength);
                continue;
            }
            if (onPath_[n])
                throw Bad("node cycle: node " + std::to_string(n) + " is its own ancestor");
            onPath_[n] = true;
            const tinygltf::Node& node = model_.nodes[n];
            const glm::dmat4 world = step.parentWorld * localTransform(node, n);
            if (!isFinite(world))
                throw Bad("node " + std::to_string(n) + " has a non-finite transform");
            const size_t parentPathLength = path_.size();
            const std::string name = nodeName(model_, n);
            path_ = joinPath(path_, name);
            if (node.mesh >= 0) addObject(node.mesh, world, n, name);
            stack.push_back({step.node, world, true, parentPathLength});
            for (auto it = node.children.rbegin(); it != node.children.rend(); ++it)
                stack.push_back({*it, world, false, 0});
        }
    }

    void addObject(int mesh, const glm::dmat4& world, size_t node, const std::string& name) {
        if (size_t(mesh) >= model_.meshes.size())
            throw Bad("node " + std::to_string(node) + " refers to missing mesh " +
                      std::to_string(mesh));
        int64_t geometry = geometryFor(mesh);
        if (geometry == kDropped) return;
        Scene& scene = result_.scene;
        uint64_t ids =
            uint64_t(scene.uniquePartCount()) + scene.geometries[size_t(geometry)].partCount;
        if (scene.objects.size() >= kMaxObjects || ids > std::numeric_limits<uint32_t>::max())
            throw Bad("too many objects or parts");
        scene::addObject(scene, uint32_t(geometry), materialForMesh_[size_t(mesh)], world, name,
                         clipPath(path_));
    }

    int64_t geometryFor(int mesh) {
        int64_t& slot = geometryOfMesh_[size_t(mesh)];
        if (slot != kUnbuilt) return slot;
        MeshBuilder builder;
        gltf::MeshInfo info =
            gltf::addMesh(model_, mesh, options_.parts, builder, result_.warnings);
        if (!info.hasTriangles) {
            result_.warnings.push_back("mesh " + std::to_string(mesh) +
                                       ": no triangles, dropped with its nodes");
            return slot = kDropped;
        }
        const std::string& name = model_.meshes[size_t(mesh)].name;
        slot = builder.finish(result_.scene, name.empty() ? "mesh " + std::to_string(mesh) : name);
        if (result_.scene.vertices.size() > std::numeric_limits<uint32_t>::max() ||
            result_.scene.indices.size() > std::numeric_limits<uint32_t>::max())
            throw Bad("too many vertices or triangles");
        materialForMesh_[size_t(mesh)] = material(info.material);
        return slot;
    }

    uint32_t material(int index) {
        if (index < 0) {
            if (defaultMaterial_ == kUnbuilt)
                defaultMaterial_ =
                    addMaterial(result_.scene, "default", glm::vec4(0.7f, 0.7f, 0.7f, 1));
            return uint32_t(defaultMaterial_);
        }
        int64_t& slot = materialOf_[size_t(index)];
        if (slot != kUnbuilt) return uint32_t(slot);
        const tinygltf::Material& m = model_.materials[size_t(index)];
        glm::vec4 color(1.0f);
        const auto& f = m.pbrMetallicRoughness.baseColorFactor;
        for (size_t i = 0; i < 4 && f.size() == 4; ++i)
            color[int(i)] = std::isfinite(f[i]) ? float(std::clamp(f[i], 0.0, 1.0)) : 1.0f;
        std::string name = m.name.empty() ? "material " + std::to_string(index) : m.name;
        slot = addMaterial(result_.scene, std::move(name), color);
        return uint32_t(slot);
    }

    const tinygltf::Model& model_;
    const LoadOptions& options_;
    LoadResult result_;
    std::vector<int64_t> geometryOfMesh_;
    std::vector<uint32_t> materialForMesh_;
    std::vector<int64_t> materialOf_;
    int64_t defaultMaterial_ = kUnbuilt;
    std::vector<int> parentCount_;
    std::vector<bool> onPath_;
    std::string path_;
};

} // namespace

const char* partModeName(PartMode mode) {
    return mode == PartMode::Components ? "components" : "primitives";
}

PartMode parsePartMode(const std::string& name) {
    if (name == "primitives") return PartMode::Primitives;
    if (name == "components") return PartMode::Components;
    throw std::invalid_argument("unknown part mode '" + name + "'");
}

LoadResult loadGltfFromMemory(std::span<const unsigned char> bytes, const std::string& name,
                              const LoadOptions& options) {
    try {
        std::vector<std::string> warnings;
        tinygltf::Model model = parse(bytes, name, warnings);
        checkRequiredExtensions(model.extensionsRequired);
        return Builder(model, options).build(std::move(warnings));
    } catch (const Bad& e) {
        throw ModelError(name + ": " + oneLine(e.what()));
    } catch (const std::bad_alloc&) {
        throw ModelError(name + ": out of memory");
    } catch (const std::exception& e) {
        // tinygltf's JSON parser may throw on input it cannot handle.
        throw ModelError(name + ": " + oneLine(e.what()));
    }
}

LoadResult loadGltf(const std::string& path, const LoadOptions& options) {
    std::vector<unsigned char> bytes;
    try {
        bytes = readFileBytes(path);
    } catch (const Bad& e) {
        throw ModelError(path + ": " + e.what());
    }
    return loadGltfFromMemory(bytes, path, options);
}

} // namespace scene
