// gltf_mesh.cpp - turns the primitives of one glTF mesh into parts of a geometry: triangle
// lists from strips and fans, normals where the file has none, and one part per primitive or
// per connected component. Parts share a vertex only where the file does: primitives of one
// mesh that use the same POSITION and NORMAL accessors share the vertices they both index.
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "scene/gltf/gltf_detail.h"
#include "scene/mesh_builder.h"

namespace scene::gltf {
namespace {

// One primitive as a triangle list over its own vertex array.
struct Triangles {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<uint32_t> corners; // 3 per triangle
};

std::string primitiveName(int mesh, size_t primitive) {
    return "mesh " + std::to_string(mesh) + " primitive " + std::to_string(primitive);
}

bool isFinite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::vector<uint32_t> toTriangleList(int mode, const std::vector<uint32_t>& v) {
    std::vector<uint32_t> out;
    size_t n = v.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        out.assign(v.begin(), v.begin() + ptrdiff_t(n - n % 3));
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        // Every other triangle is flipped so that the whole strip keeps one winding.
        for (size_t i = 0; i + 2 < n; ++i)
            out.insert(out.end(), {v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]});
    } else {
        for (size_t i = 1; i + 1 < n; ++i) out.insert(out.end(), {v[0], v[i], v[i + 1]});
    }
    return out;
}

// Uses the file's normals where they are usable (finite, non-zero), computed ones elsewhere.
void fillNormals(const tinygltf::Model& model, int normalAccessor, Triangles& t,
                 const std::string& name) {
    std::vector<glm::vec3> computed = areaWeightedNormals(t.positions, t.corners);
    if (normalAccessor < 0) {
        t.normals = std::move(computed);
        return;
    }
    t.normals = readVec3(model, normalAccessor, name + " NORMAL");
    if (t.normals.size() != t.positions.size())
        throw Bad(name + " has " + std::to_string(t.normals.size()) + " normals for " +
                  std::to_string(t.positions.size()) + " positions");
    for (size_t i = 0; i < t.normals.size(); ++i) {
        float len = glm::length(t.normals[i]);
        t.normals[i] = (std::isfinite(len) && len > 1e-12f) ? t.normals[i] / len : computed[i];
    }
}

int attribute(const tinygltf::Primitive& p, const char* name) {
    auto it = p.attributes.find(name);
    return it == p.attributes.end() ? -1 : it->second;
}

std::vector<uint32_t> readCorners(const tinygltf::Model& model, const tinygltf::Primitive& p,
                                  size_t vertexCount, const std::string& name) {
    std::vector<uint32_t> indices;
    if (p.indices >= 0) {
        indices = readIndices(model, p.indices);
        for (uint32_t i : indices)
            if (i >= vertexCount)
                throw Bad(name + " index " + std::to_string(i) + " is >= the vertex count " +
                          std::to_string(vertexCount));
    } else {
        indices.resize(vertexCount);
        std::iota(indices.begin(), indices.end(), 0u);
    }
    return indices;
}

// Reads a triangle primitive; false (with a warning) for points, lines and empty ones.
bool readPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& p,
                   const std::string& name, Triangles& t, std::vector<std::string>& warnings) {
    int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
    if (mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE ||
        mode == TINYGLTF_MODE_LINE_LOOP || mode == TINYGLTF_MODE_LINE_STRIP) {
        warnings.push_back(name + ": " + (mode == TINYGLTF_MODE_POINTS ? "points" : "lines") +
                           " skipped");
        return false;
    }
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN)
        throw Bad(name + " has the invalid mode " + std::to_string(mode));
    int position = attribute(p, "POSITION");
    if (position < 0) {
        warnings.push_back(name + ": no POSITION, skipped");
        return false;
    }
    t.positions = readVec3(model, position, name + " POSITION");
    for (const auto& v : t.positions)
        if (!isFinite(v)) throw Bad(name + " has a NaN or infinite POSITION");
    t.corners = toTriangleList(mode, readCorners(model, p, t.positions.size(), name));
    if (t.corners.empty()) {
        warnings.push_back(name + ": no triangles, skipped");
        return false;
    }
    fillNormals(model, attribute(p, "NORMAL"), t, name);
    return true;
}

// Union-find over vertex indices: triangles sharing a vertex end up in one component.
std::vector<uint32_t> componentOfTriangle(const Triangles& t) {
    std::vector<uint32_t> parent(t.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    for (size_t i = 0; i < t.corners.size(); ++i) {
        uint32_t a = find(t.corners[i - i % 3]), b = find(t.corners[i]);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
    // Number the components in the order of their first triangle, so parts follow the file.
    std::vector<uint32_t> number(t.positions.size(), UINT32_MAX);
    std::vector<uint32_t> component(t.corners.size() / 3);
    uint32_t next = 0;
    for (size_t tri = 0; tri < component.size(); ++tri) {
        uint32_t root = find(t.corners[3 * tri]);
        if (number[root] == UINT32_MAX) number[root] = next++;
        component[tri] = number[root];
    }
    return component;
}

// Emits the triangles in `order`, starting a new part wherever `group` changes. `emitted`
// maps the primitive's vertices to the builder's (UINT32_MAX: not emitted yet); it outlives
// the primitive where later primitives index the same accessors. Components share no vertex
// by construction, so only such primitives ever share one.
void emitParts(const Triangles& t, const std::vector<uint32_t>& order,
               const std::vector<uint32_t>& group, std::vector<uint32_t>& emitted,
               MeshBuilder& builder) {
    for (size_t k = 0; k < order.size(); ++k) {
        uint32_t tri = order[k], g = group[tri];
        if (k == 0 || g != group[order[k - 1]]) builder.beginPart();
        uint32_t v[3];
        for (int c = 0; c < 3; ++c) {
            uint32_t src = t.corners[3 * tri + uint32_t(c)];
            if (emitted[src] == UINT32_MAX)
                emitted[src] = builder.addVertex(t.positions[src], t.normals[src]);
            v[c] = emitted[src];
        }
        builder.addTriangle(v[0], v[1], v[2]);
    }
}

void addParts(const Triangles& t, PartMode mode, std::vector<uint32_t>& emitted,
              MeshBuilder& builder) {
    size_t triangles = t.corners.size() / 3;
    std::vector<uint32_t> group(triangles, 0);
    if (mode == PartMode::Components) group = componentOfTriangle(t);
    std::vector<uint32_t> order(triangles);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return group[a] < group[b]; });
    emitParts(t, order, group, emitted, builder);
}

} // namespace

MeshInfo addMesh(const tinygltf::Model& model, int mesh, PartMode mode, MeshBuilder& builder,
                 std::vector<std::string>& warnings) {
    MeshInfo info;
    const tinygltf::Mesh& m = model.meshes[size_t(mesh)];
    // Emitted vertices per (POSITION, NORMAL) accessor pair. Computed normals depend on the
    // primitive's own triangles, so without a NORMAL accessor nothing is shared.
    std::map<std::pair<int, int>, std::vector<uint32_t>> emittedByAccessors;
    for (size_t i = 0; i < m.primitives.size(); ++i) {
        const tinygltf::Primitive& p = m.primitives[i];
        const std::string name = primitiveName(mesh, i);
        Triangles t;
        if (!readPrimitive(model, p, name, t, warnings)) continue;
        if (p.material >= 0 && size_t(p.material) >= model.materials.size())
            throw Bad(name + " refers to missing material " + std::to_string(p.material));
        if (!info.hasTriangles) info.material = p.material;
        info.hasTriangles = true;
        const int normals = attribute(p, "NORMAL");
        std::vector<uint32_t> own;
        std::vector<uint32_t>& emitted =
            normals < 0 ? own : emittedByAccessors[{attribute(p, "POSITION"), normals}];
        emitted.resize(t.positions.size(), UINT32_MAX);
        addParts(t, mode, emitted, builder);
    }
    return info;
}

} // namespace scene::gltf
