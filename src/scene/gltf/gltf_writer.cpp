// gltf_writer.cpp - Scene to .glb through tinygltf. Each part with triangles gets its own
// accessors over the vertex range it uses, so parts stay separate primitives and indices can
// often be 16-bit.
#include "scene/gltf/gltf_writer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include <tiny_gltf.h>

namespace scene {
namespace {

class GlbBuilder {
  public:
    explicit GlbBuilder(const Scene& scene) : scene_(scene) {
        model_.asset.version = "2.0";
        model_.asset.generator = "idview";
        model_.buffers.emplace_back();
        for (const Material& m : scene.materials) addMaterial(m);
    }

    tinygltf::Model build() {
        // One root node per object, in object order, so that the file loads back with the same
        // unique part IDs; the node is named after the object. idview scenes are z-up, glTF is
        // y-up: each node's matrix turns its object.
        tinygltf::Scene root;
        const glm::dmat4 up = zUpToYUp();
        for (const Object& object : scene_.objects) {
            tinygltf::Node node;
            node.name = object.name;
            // glTF has no mesh without primitives: an object without triangles is a bare node.
            if (scene_.geometries[object.geometry].triangleCount > 0)
                node.mesh = meshFor(object.geometry, object.material);
            const glm::dmat4 world = up * object.world;
            const double* m = &world[0][0];
            node.matrix.assign(m, m + 16); // both column-major
            root.nodes.push_back(int(model_.nodes.size()));
            model_.nodes.push_back(std::move(node));
        }
        model_.scenes.push_back(std::move(root));
        model_.defaultScene = 0;
        return std::move(model_);
    }

  private:
    struct GeometryViews {
        int vertices = -1, indices = -1;
        bool shortIndices = false;
        std::vector<int> positions, normals, indexAccessors; // per part with triangles
    };

    void addMaterial(const Material& m) {
        tinygltf::Material material;
        material.name = m.name;
        material.pbrMetallicRoughness.baseColorFactor = {m.color.r, m.color.g, m.color.b,
                                                         m.color.a};
        material.pbrMetallicRoughness.metallicFactor = 0.0;
        model_.materials.push_back(std::move(material));
    }

    int appendView(const void* data, size_t bytes, int stride, int target) {
        auto& buffer = model_.buffers[0].data;
        buffer.resize((buffer.size() + 3) & ~size_t(3)); // 4-byte aligned views
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = buffer.size();
        view.byteLength = bytes;
        view.byteStride = size_t(stride);
        view.target = target;
        const auto* p = static_cast<const uint8_t*>(data);
        buffer.insert(buffer.end(), p, p + bytes);
        model_.bufferViews.push_back(view);
        return int(model_.bufferViews.size() - 1);
    }

    int addAccessor(int view, size_t byteOffset, size_t count, int componentType, int type) {
        tinygltf::Accessor a;
        a.bufferView = view;
        a.byteOffset = byteOffset;
        a.count = count;
        a.componentType = componentType;
        a.type = type;
        model_.accessors.push_back(std::move(a));
        return int(model_.accessors.size() - 1);
    }

    // Vertex range [first, last] each part's triangles use, geometry-local.
    std::pair<uint32_t, uint32_t> vertexRange(const Geometry& g, const Part& part) const {
        const uint32_t* idx = &scene_.indices[g.firstIndex + 3 * part.firstTriangle];
        auto [lo, hi] = std::minmax_element(idx, idx + 3 * part.triangleCount);
        return {*lo, *hi};
    }

    const GeometryViews& views(uint32_t geometry) {
        auto found = views_.find(geometry);
        if (found != views_.end()) return found->second;
        const Geometry& g = scene_.geometries[geometry];
        GeometryViews v;
        v.vertices = appendView(&scene_.vertices[g.firstVertex], g.vertexCount * sizeof(Vertex),
                                sizeof(Vertex), TINYGLTF_TARGET_ARRAY_BUFFER);
        // An empty part has no primitive (a glTF primitive has triangles), so the file holds
        // the parts with triangles alone.
        std::vector<const Part*> drawn;
        for (uint32_t p = 0; p < g.partCount; ++p)
            if (!scene_.parts[g.firstPart + p].empty())
                drawn.push_back(&scene_.parts[g.firstPart + p]);
        std::vector<std::pair<uint32_t, uint32_t>> ranges;
        v.shortIndices = true;
        for (const Part* part : drawn) {
            ranges.push_back(vertexRange(g, *part));
            v.shortIndices &= ranges.back().second - ranges.back().first < 0xFFFFu;
        }
        std::vector<uint8_t> indexBytes;
        std::vector<size_t> indexOffsets;
        const size_t width = v.shortIndices ? 2 : 4;
        for (size_t p = 0; p < drawn.size(); ++p) {
            const Part& part = *drawn[p];
            indexOffsets.push_back(indexBytes.size());
            for (uint32_t i = 0; i < 3 * part.triangleCount; ++i) {
                uint32_t local =
                    scene_.indices[g.firstIndex + 3 * part.firstTriangle + i] - ranges[p].first;
                indexBytes.insert(indexBytes.end(), reinterpret_cast<uint8_t*>(&local),
                                  reinterpret_cast<uint8_t*>(&local) + width); // little-endian host
            }
            indexBytes.resize((indexBytes.size() + 3) & ~size_t(3));
        }
        v.indices = appendView(indexBytes.data(), indexBytes.size(), 0,
                               TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        for (size_t p = 0; p < drawn.size(); ++p) {
            const auto [first, last] = ranges[p];
            const size_t count = last - first + 1;
            const size_t offset = first * sizeof(Vertex);
            int position = addAccessor(v.vertices, offset + offsetof(Vertex, position), count,
                                       TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3);
            glm::vec3 lo(std::numeric_limits<float>::max()),
                hi(std::numeric_limits<float>::lowest());
            for (uint32_t i = first; i <= last; ++i) {
                lo = glm::min(lo, scene_.vertices[g.firstVertex + i].position);
                hi = glm::max(hi, scene_.vertices[g.firstVertex + i].position);
            }
            model_.accessors[position].minValues = {lo.x, lo.y, lo.z};
            model_.accessors[position].maxValues = {hi.x, hi.y, hi.z};
            v.positions.push_back(position);
            v.normals.push_back(addAccessor(v.vertices, offset + offsetof(Vertex, normal), count,
                                            TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3));
            v.indexAccessors.push_back(
                addAccessor(v.indices, indexOffsets[p], 3 * drawn[p]->triangleCount,
                            v.shortIndices ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT
                                           : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                            TINYGLTF_TYPE_SCALAR));
        }
        return views_.emplace(geometry, std::move(v)).first->second;
    }

    int meshFor(uint32_t geometry, uint32_t material) {
        auto key = std::make_pair(geometry, material);
        if (auto found = meshes_.find(key); found != meshes_.end()) return found->second;
        const GeometryViews& v = views(geometry);
        tinygltf::Mesh mesh;
        mesh.name = scene_.geometries[geometry].name;
        for (size_t p = 0; p < v.positions.size(); ++p) {
            tinygltf::Primitive primitive;
            primitive.attributes["POSITION"] = v.positions[p];
            primitive.attributes["NORMAL"] = v.normals[p];
            primitive.indices = v.indexAccessors[p];
            primitive.material = int(material);
            primitive.mode = TINYGLTF_MODE_TRIANGLES;
            mesh.primitives.push_back(std::move(primitive));
        }
        model_.meshes.push_back(std::move(mesh));
        return meshes_[key] = int(model_.meshes.size() - 1);
    }

    const Scene& scene_;
    tinygltf::Model model_;
    std::map<uint32_t, GeometryViews> views_;
    std::map<std::pair<uint32_t, uint32_t>, int> meshes_;
};

} // namespace

glm::dmat4 zUpToYUp() {
    // Columns: x stays x, y becomes -z, z becomes y.
    return glm::dmat4(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 0, -1, 0), glm::dvec4(0, 1, 0, 0),
                      glm::dvec4(0, 0, 0, 1));
}

void writeGlb(const Scene& scene, const std::string& path) {
    tinygltf::Model model = GlbBuilder(scene).build();
    // Written beside it, then renamed: the file appears whole or not at all, as a STEP
    // export does (a full disk or a failed write leaves what was there before).
    const std::string partial = path + ".part";
    bool written = false;
    {
        std::ofstream out(partial, std::ios::binary);
        written = out && tinygltf::TinyGLTF().WriteGltfSceneToStream(&model, out, false, true);
        out.close();
        written = written && !out.fail();
    }
    std::error_code error;
    if (written) std::filesystem::rename(partial, path, error);
    if (!written || error) {
        std::filesystem::remove(partial, error);
        throw std::runtime_error("cannot write glTF binary '" + path + "'");
    }
}

} // namespace scene
