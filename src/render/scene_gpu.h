// scene_gpu.h - a Scene's arrays in device-local buffers: vertices and indices for drawing,
// objects and materials for the shaders (read through buffer device addresses), and what the
// exploded-view animation writes the objects' matrices from.
#pragma once

#include <vector>

#include "scene/scene.h"
#include "vk/resources.h"
#include "vk/upload.h"

namespace render {

// `world` with its translation made relative to `origin` in double, then rounded to float once:
// what the GPU gets as an object's matrix (render::eyeRelative).
glm::mat4 relativeWorld(const glm::dmat4& world, const glm::dvec3& origin);

class SceneGpu {
  public:
    // The buffers are filled by `upload`'s submit (the caller's, with the rest of a switch).
    SceneGpu(const scene::Scene& scene, vk::UploadBatch& upload);

    const vk::Buffer& vertices() const { return vertices_; }
    const vk::Buffer& indices() const { return indices_; }
    VkDeviceAddress objectsAddress() const { return objects_.address(); }
    VkDeviceAddress materialsAddress() const { return materials_.address(); }
    // 0 when no part has a material of its own.
    VkDeviceAddress partMaterialsAddress() const { return partMaterials_.address(); }
    uint32_t objectCount() const { return objectCount_; }

    // The animation's inputs: each object's world matrix at rest (dmat4) and its offset at
    // explode 1 (vec4), see render/animator.h.
    VkDeviceAddress restAddress() const { return rest_.address(); }
    VkDeviceAddress offsetsAddress() const { return offsets_.address(); }
    // The explode value and the origin the objects' matrices hold once recorded work has run.
    float explodeWritten = 0.0f;
    glm::dvec3 originWritten{0.0};

    // For culling: each of the scene's parts' box in its geometry (scene/bounds.h), and the
    // objects' world matrices at an explode value relative to `origin`, as animate.comp
    // writes them.
    const std::vector<scene::Bounds>& partBounds() const { return partBounds_; }
    // FrameData::sectionTolerance for coordinates relative to `origin` (scene::inPlaneTolerance
    // of the largest magnitude the GPU meets placing a vertex there, exploded or not).
    double sectionTolerance(const glm::dvec3& origin) const;
    glm::mat4 worldAt(uint32_t object, float explode, const glm::dvec3& origin) const;
    // The parts' clusters (scene::partClusters): per entry of Scene::parts, and one more, the
    // first cluster; their boxes on the GPU (gpu::CullBox[], `part` the cluster's part in
    // its geometry), by which cull.comp tests the draws of several clusters one by one.
    const std::vector<uint32_t>& clusterStart() const { return clusterStart_; }
    VkDeviceAddress clusterBoxesAddress() const { return clusterBoxes_.address(); }

  private:
    void measureReach(const scene::Scene& scene);

    std::vector<scene::Bounds> partBounds_;
    // sectionTolerance's: the largest placed geometry's reach from its own origin, and the
    // world box of the scene, grown by the longest explode offset.
    double localReach_ = 0.0;
    scene::Bounds reachBox_;
    std::vector<uint32_t> clusterStart_;
    std::vector<glm::dmat4> restWorld_;
    std::vector<glm::vec4> explodeOffsets_;
    vk::Buffer vertices_, indices_, objects_, materials_, rest_, offsets_, clusterBoxes_;
    vk::Buffer partMaterials_; // empty (address 0) unless a part has its own material
    uint32_t objectCount_ = 0;
};

} // namespace render
