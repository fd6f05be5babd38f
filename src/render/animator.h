// animator.h - the exploded-view animation on the GPU: a compute shader writes every object's
// world matrix from its rest matrix and its offset (scene::explodeOffsets, uploaded by
// SceneGpu) before the scene pass, so every technique draws moving objects and the pick sees
// them where they are drawn.
#pragma once

#include "render/scene_gpu.h"
#include "vk/handle.h"
#include "vk/shader_compiler.h"

namespace render {

class DiskPipelineCache;

class Animator {
  public:
    // Builds the compute pipeline (shaders/animate.comp). Throws vk::Error / vk::ShaderError.
    Animator(vk::Device& device, const vk::ShaderCompiler& compiler,
             const DiskPipelineCache& cache);

    // Outside a render pass, before the scene pass: records the dispatch that writes the
    // scene's world matrices for `explode` (clamped to 0..1), relative to `origin` (the
    // frame's, render::FrameParams), with the barriers around it. Records nothing when explode
    // is 0 and the objects already hold their rest matrices for that origin, so a still view
    // of a scene that is not animated pays nothing. Assumes the command buffer is submitted.
    void record(VkCommandBuffer cmd, SceneGpu& scene, float explode,
                const glm::dvec3& origin) const;

  private:
    vk::Device& device_;
    vk::Handle<VkPipelineLayout> layout_;
    vk::Handle<VkPipeline> pipeline_;
};

} // namespace render
