// renderer.h - draws a scene into the scene pass with one part-ID technique and per-draw
// mode. Pipelines and draw lists are built when the scene or technique changes, never per
// frame; record() only writes commands.
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "render/frame_slots.h"
#include "render/scene_gpu.h"
#include "render/targets.h"
#include "render/technique.h"
#include "vk/shader_compiler.h"

namespace render {

struct FrameParams {
    glm::mat4 viewProj{1.0f};
    glm::vec3 eye{0.0f};
    float partColorWeight = 0.5f;
    bool colorizeDraws = false;
};

class Renderer {
  public:
    Renderer(vk::Device& device, const vk::ShaderCompiler& compiler, const ScenePass& pass);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Uploads the scene (the Renderer keeps no reference to it) and rebuilds the draw list.
    void setScene(const scene::Scene& scene);
    // Compiles the technique's pipeline; on a compile error the previous one stays.
    void setTechnique(const Technique& technique, const DrawMode& mode, const scene::Scene& scene);

    // Records the scene pass with timestamps around it into the slot's command buffer.
    void record(FrameSlot& slot, const SceneTargets& targets, const FrameParams& params) const;

    size_t drawCount() const { return draws_.size(); }
    const Technique* technique() const { return technique_; }
    const DrawMode* mode() const { return mode_; }

  private:
    VkPipeline buildPipeline(const Technique& technique, const DrawMode& mode) const;
    void recordDraws(VkCommandBuffer cmd) const;

    vk::Device& device_;
    const vk::ShaderCompiler& compiler_;
    const ScenePass& pass_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    const Technique* technique_ = nullptr;
    const DrawMode* mode_ = nullptr;
    std::unique_ptr<SceneGpu> sceneGpu_;
    std::vector<DrawItem> draws_;
};

} // namespace render
