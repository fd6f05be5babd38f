// scene_gpu.cpp - uploads a scene once, when it is loaded or its copies change.
#include "render/scene_gpu.h"

#include <vector>

#include "scene/explode.h"
#include "shared.h"
#include "vk/check.h"

namespace render {

SceneGpu::SceneGpu(const scene::Scene& scene, vk::UploadBatch& upload)
    : objectCount_(static_cast<uint32_t>(scene.objects.size())) {
    if (scene.objects.empty() || scene.indices.empty())
        throw vk::Error("the scene is empty: nothing to draw");

    std::vector<gpu::ObjectData> objects;
    std::vector<glm::mat4> rest;
    objects.reserve(scene.objects.size());
    rest.reserve(scene.objects.size());
    for (const auto& o : scene.objects) {
        gpu::ObjectData data{};
        data.world = o.world;
        data.normalMatrix = glm::transpose(glm::inverse(o.world));
        data.materialIndex = o.material;
        data.uniquePartOffset = o.uniquePartOffset;
        data.geometryIndex = o.geometry;
        data.firstPart = scene.geometries[o.geometry].firstPart;
        objects.push_back(data);
        rest.push_back(o.world);
    }
    std::vector<gpu::Material> materials;
    for (const auto& m : scene.materials) materials.push_back({m.color});

    const VkBufferUsageFlags shaderRead =
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
    vertices_ = upload.add(scene.vertices, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "scene vertices");
    indices_ = upload.add(scene.indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, "scene indices");
    objects_ = upload.add(objects, shaderRead, "scene objects");
    materials_ = upload.add(materials, shaderRead, "scene materials");
    rest_ = upload.add(rest, shaderRead, "animation rest matrices");
    offsets_ = upload.add(scene::explodeOffsets(scene), shaderRead, "animation offsets");
    // Part materials only where some part has one: other scenes read none.
    std::vector<uint32_t> partMaterials;
    for (const scene::Geometry& g : scene.geometries)
        if (!g.partMaterials.empty()) {
            partMaterials.assign(scene.parts.size(), gpu::OBJECT_MATERIAL);
            break;
        }
    if (!partMaterials.empty()) {
        for (const scene::Geometry& g : scene.geometries)
            for (uint32_t p = 0; p < g.partMaterials.size(); ++p)
                partMaterials[g.firstPart + p] = g.partMaterials[p];
        partMaterials_ = upload.add(partMaterials, shaderRead, "part materials");
    }
}

} // namespace render
