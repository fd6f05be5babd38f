// animator.h - the exploded-view animation on the GPU: a compute shader writes every object's
// world matrix from its rest matrix and its offset (scene::explodeOffsets) before the scene
// pass, so every technique draws moving objects and the pick sees them where they are drawn.
#pragma once

#include <cstdint>

#include "scene/scene.h"
#include "vk/resources.h"
#include "vk/shader_compiler.h"

namespace render {

class Animator {
  public:
    // `objectsAddress` is the scene's ObjectData[] (SceneGpu), uploaded with the rest
    // matrices. Computes the offsets, uploads them with the rest matrices and builds the
    // compute pipeline (shaders/animate.comp). Throws vk::Error / vk::ShaderError.
    Animator(vk::Device& device, const vk::ShaderCompiler& compiler, const scene::Scene& scene,
             VkDeviceAddress objectsAddress);
    ~Animator();
    Animator(const Animator&) = delete;
    Animator& operator=(const Animator&) = delete;

    // Outside a render pass, before the scene pass: records the dispatch that writes the
    // world matrices for `explode` (clamped to 0..1), with the barriers around it. Records
    // nothing when explode is 0 and the objects already hold their rest matrices, so a scene
    // that is not animated pays nothing. Assumes the command buffer is submitted.
    void record(VkCommandBuffer cmd, float explode);

    // What the objects' world matrices hold once the recorded work has run.
    float written() const { return written_; }

  private:
    void release();

    vk::Device& device_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    vk::Buffer rest_, offsets_; // mat4 and vec4 per object
    VkDeviceAddress objects_ = 0;
    uint32_t count_ = 0;
    float written_ = 0.0f;
};

} // namespace render
