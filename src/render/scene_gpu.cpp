// scene_gpu.cpp - uploads a scene once, when it is loaded.
#include "render/scene_gpu.h"

#include <vector>

#include "shared.h"
#include "vk/check.h"

namespace render {

SceneGpu::SceneGpu(vk::Device& device, const scene::Scene& scene) : device_(device) {
    if (scene.objects.empty() || scene.indices.empty())
        throw vk::Error("the scene is empty: nothing to draw");

    std::vector<gpu::ObjectData> objects;
    objects.reserve(scene.objects.size());
    for (const auto& o : scene.objects) {
        gpu::ObjectData data{};
        data.world = o.world;
        data.normalMatrix = glm::transpose(glm::inverse(o.world));
        data.materialIndex = o.material;
        data.uniquePartOffset = o.uniquePartOffset;
        data.geometryIndex = o.geometry;
        objects.push_back(data);
    }
    std::vector<gpu::Material> materials;
    for (const auto& m : scene.materials) materials.push_back({m.color});

    const VkBufferUsageFlags shaderRead =
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
    try {
        vertices_ = vk::createBufferWithData(device, scene.vertices.data(),
                                             scene.vertices.size() * sizeof(gpu::Vertex),
                                             VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "scene vertices");
        indices_ = vk::createBufferWithData(device, scene.indices.data(),
                                            scene.indices.size() * sizeof(uint32_t),
                                            VK_BUFFER_USAGE_INDEX_BUFFER_BIT, "scene indices");
        objects_ = vk::createBufferWithData(device, objects.data(),
                                            objects.size() * sizeof(gpu::ObjectData), shaderRead,
                                            "scene objects");
        materials_ = vk::createBufferWithData(device, materials.data(),
                                              materials.size() * sizeof(gpu::Material), shaderRead,
                                              "scene materials");
    } catch (...) {
        release();
        throw;
    }
}

SceneGpu::~SceneGpu() {
    release();
}

void SceneGpu::release() {
    vk::destroyBuffer(device_, vertices_);
    vk::destroyBuffer(device_, indices_);
    vk::destroyBuffer(device_, objects_);
    vk::destroyBuffer(device_, materials_);
}

} // namespace render
