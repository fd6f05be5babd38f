// pipeline.h - the fixed-function state every scene pipeline shares (vertex layout from
// shared.h, depth test, two colour outputs) with the shader stages a technique brings.
#pragma once

#include <string>
#include <vector>

#include "render/disk_pipeline_cache.h"
#include "vk/context.h"
#include "vk/handle.h"
#include "vk/shader_compiler.h"

namespace render {

struct ShaderStage {
    VkShaderStageFlagBits stage;
    vk::Handle<VkShaderModule> module;
};

// Push constants are visible to every stage a technique may use, so one range serves all;
// the mesh stage only where the device has it (naming it elsewhere is invalid).
VkShaderStageFlags pushStages(const vk::Device& device);
// The pipeline stages whose shaders read scene data, for barriers.
VkPipelineStageFlags sceneShaderStages(const vk::Device& device);

vk::Handle<VkPipelineLayout> createScenePipelineLayout(vk::Device& device);

struct ScenePipelineInfo {
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkRenderPass pass = VK_NULL_HANDLE;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    bool drawIndexAttribute = false; // the instanced uint attribute LOC_DRAW_INDEX (mdi-attribute)
    bool mesh = false;               // a mesh shader: no vertex input at all
    bool writeIds = true;            // false masks the ID attachment (the floors)
    bool writeColor = true;          // false masks the colour attachment (the visibility buffer)
    // Blends its colour over the picture and writes no depth (X-ray's pass, render/xray.h).
    bool translucent = false;
    // With `translucent`: X-ray's colour adds up over black and alpha keeps what shows
    // through (PipelineKey::overVisibility).
    bool accumulate = false;
};

// A compute pipeline from one shader file (with `defines`), and the layout: `pushBytes` of push
// constants for the compute stage and, if given, one descriptor set layout.
struct ComputePipeline {
    vk::Handle<VkPipelineLayout> layout;
    vk::Handle<VkPipeline> pipeline;
};
ComputePipeline
createComputePipeline(vk::Device& device, const vk::ShaderCompiler& compiler,
                      const DiskPipelineCache& cache, const char* file, uint32_t pushBytes,
                      VkDescriptorSetLayout set, const std::string& name,
                      const std::vector<std::pair<std::string, std::string>>& defines = {});
// The set layout of a compute pass's push descriptors: binding i of type types[i].
vk::Handle<VkDescriptorSetLayout> pushDescriptorLayout(const vk::Device& device,
                                                       const std::vector<VkDescriptorType>& types,
                                                       const std::string& name);
// For shaders that read a sampled image with texelFetch only: no filtering is ever used.
vk::Handle<VkSampler> texelFetchSampler(const vk::Device& device, const std::string& name);
// Binds `pass` and pushes `image` as its binding 0 (a push descriptor set of one image).
void bindWithImage(const vk::Device& device, VkCommandBuffer cmd, const ComputePipeline& pass,
                   VkDescriptorType type, const VkDescriptorImageInfo& image);
// Binds `pass` and pushes each of `images` at its binding (a push descriptor set).
struct BoundImage {
    uint32_t binding;
    VkDescriptorType type;
    VkDescriptorImageInfo image;
};
void bindWithImages(const vk::Device& device, VkCommandBuffer cmd, const ComputePipeline& pass,
                    const std::vector<BoundImage>& images);

vk::Handle<VkPipeline> createScenePipeline(const DiskPipelineCache& cache,
                                           const ScenePipelineInfo& info,
                                           const std::vector<ShaderStage>& stages,
                                           const std::string& name);

} // namespace render
