// pipeline.h - the fixed-function state every scene pipeline shares (vertex layout from
// shared.h, depth test, two colour outputs) with the shader stages a technique brings.
#pragma once

#include <string>
#include <vector>

#include "vk/context.h"

namespace render {

struct ShaderStage {
    VkShaderStageFlagBits stage;
    VkShaderModule module;
};

// Push constants are visible to every stage a technique may use, so one range serves all.
constexpr VkShaderStageFlags pushStages =
    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

VkPipelineLayout createScenePipelineLayout(vk::Device& device);

// drawIndexAttribute adds the instanced uint attribute LOC_DRAW_INDEX (mdi-attribute mode).
VkPipeline createScenePipeline(vk::Device& device, VkPipelineLayout layout, VkRenderPass pass,
                               VkSampleCountFlagBits samples,
                               const std::vector<ShaderStage>& stages, bool drawIndexAttribute,
                               bool writeIds, const std::string& name);

} // namespace render
