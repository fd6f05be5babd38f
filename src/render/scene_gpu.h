// scene_gpu.h - a Scene's arrays in device-local buffers: vertices and indices for drawing,
// objects and materials for the shaders (read through buffer device addresses).
#pragma once

#include "scene/scene.h"
#include "vk/resources.h"

namespace render {

class SceneGpu {
  public:
    SceneGpu(vk::Device& device, const scene::Scene& scene);
    ~SceneGpu();
    SceneGpu(const SceneGpu&) = delete;
    SceneGpu& operator=(const SceneGpu&) = delete;

    const vk::Buffer& vertices() const { return vertices_; }
    const vk::Buffer& indices() const { return indices_; }
    VkDeviceAddress objectsAddress() const { return objects_.address; }
    VkDeviceAddress materialsAddress() const { return materials_.address; }

  private:
    void release();

    vk::Device& device_;
    vk::Buffer vertices_, indices_, objects_, materials_;
};

} // namespace render
