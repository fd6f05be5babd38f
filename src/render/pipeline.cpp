// pipeline.cpp - graphics pipeline state for the scene pass.
#include "render/pipeline.h"

#include <array>

#include "shared.h"
#include "vk/check.h"

namespace render {

VkShaderStageFlags pushStages(const vk::Device& device) {
    return VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT |
           VK_SHADER_STAGE_FRAGMENT_BIT |
           (device.info().meshShader
                ? VkShaderStageFlags(VK_SHADER_STAGE_MESH_BIT_EXT | VK_SHADER_STAGE_TASK_BIT_EXT)
                : 0u);
}

VkPipelineStageFlags sceneShaderStages(const vk::Device& device) {
    return VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_GEOMETRY_SHADER_BIT |
           VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT |
           (device.info().meshShader ? VkPipelineStageFlags(VK_PIPELINE_STAGE_MESH_SHADER_BIT_EXT |
                                                            VK_PIPELINE_STAGE_TASK_SHADER_BIT_EXT)
                                     : 0u);
}

vk::Handle<VkPipelineLayout> createScenePipelineLayout(vk::Device& device) {
    VkPushConstantRange range{pushStages(device), 0, sizeof(gpu::DrawPush)};
    auto info = vk::init<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
    info.pushConstantRangeCount = 1;
    info.pPushConstantRanges = &range;
    return vk::make(device, vkCreatePipelineLayout, info, "scene pipeline layout");
}

ComputePipeline
createComputePipeline(vk::Device& device, const vk::ShaderCompiler& compiler,
                      const DiskPipelineCache& cache, const char* file, uint32_t pushBytes,
                      VkDescriptorSetLayout set, const std::string& name,
                      const std::vector<std::pair<std::string, std::string>>& defines) {
    ComputePipeline out;
    VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes};
    auto layoutInfo =
        vk::init<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
    layoutInfo.pushConstantRangeCount = 1;
    layoutInfo.pPushConstantRanges = &range;
    layoutInfo.setLayoutCount = set ? 1 : 0;
    layoutInfo.pSetLayouts = &set;
    out.layout = vk::make(device, vkCreatePipelineLayout, layoutInfo, name + " layout");

    const vk::ShaderRequest request{file, VK_SHADER_STAGE_COMPUTE_BIT, defines, {}};
    const vk::Handle<VkShaderModule> module =
        vk::createShaderModule(device, compiler.compile(request), request.label());
    auto info =
        vk::init<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
    info.stage = vk::init<VkPipelineShaderStageCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module.get();
    info.stage.pName = "main";
    info.layout = out.layout.get();
    out.pipeline = cache.create(info, name);
    return out;
}

namespace {

// What the vertex pipelines read per vertex (positions and normals), and mdi-attribute's draw
// index per instance. It points into itself, so it is made in place and never copied.
struct VertexInput {
    explicit VertexInput(bool drawIndexAttribute) {
        bindings = {{gpu::BINDING_VERTICES, sizeof(gpu::Vertex), VK_VERTEX_INPUT_RATE_VERTEX}};
        attributes = {{gpu::LOC_POSITION, gpu::BINDING_VERTICES, VK_FORMAT_R32G32B32_SFLOAT,
                       offsetof(gpu::Vertex, position)},
                      {gpu::LOC_NORMAL, gpu::BINDING_VERTICES, VK_FORMAT_R32G32B32_SFLOAT,
                       offsetof(gpu::Vertex, normal)}};
        if (drawIndexAttribute) {
            // One uint per instance; each indirect draw's firstInstance selects its element.
            bindings.push_back(
                {gpu::BINDING_DRAW_INDICES, sizeof(uint32_t), VK_VERTEX_INPUT_RATE_INSTANCE});
            attributes.push_back(
                {gpu::LOC_DRAW_INDEX, gpu::BINDING_DRAW_INDICES, VK_FORMAT_R32_UINT, 0});
        }
        info = vk::init<VkPipelineVertexInputStateCreateInfo>(
            VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
        info.vertexBindingDescriptionCount = static_cast<uint32_t>(bindings.size());
        info.pVertexBindingDescriptions = bindings.data();
        info.vertexAttributeDescriptionCount = static_cast<uint32_t>(attributes.size());
        info.pVertexAttributeDescriptions = attributes.data();
    }
    VertexInput(const VertexInput&) = delete;
    VertexInput& operator=(const VertexInput&) = delete;

    std::vector<VkVertexInputBindingDescription> bindings;
    std::vector<VkVertexInputAttributeDescription> attributes;
    VkPipelineVertexInputStateCreateInfo info;
};

// No culling of back faces: CAD exports often mix windings, and the shading is two-sided.
VkPipelineRasterizationStateCreateInfo rasterState() {
    auto raster = vk::init<VkPipelineRasterizationStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO);
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = VK_CULL_MODE_NONE;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;
    return raster;
}

VkPipelineDepthStencilStateCreateInfo depthState(bool translucent) {
    auto depth = vk::init<VkPipelineDepthStencilStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO);
    depth.depthTestEnable = VK_TRUE;
    // A translucent surface hides nothing behind it: depth stays the opaque parts'.
    depth.depthWriteEnable = translucent ? VK_FALSE : VK_TRUE;
    // Reversed depth (scene/camera.h): nearer is greater. Where two surfaces tie the one
    // drawn first stays, as LESS kept it.
    depth.depthCompareOp = VK_COMPARE_OP_GREATER;
    return depth;
}

// Colour and IDs with full write masks; no-id masks the ID attachment off entirely (its shader
// writes no ID), which needs the independentBlend feature; X-ray blends its colour over.
std::array<VkPipelineColorBlendAttachmentState, 2>
blendAttachments(const ScenePipelineInfo& scene) {
    std::array<VkPipelineColorBlendAttachmentState, 2> blend{};
    for (auto& attachment : blend)
        attachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                    VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    if (!scene.writeIds) blend[1].colorWriteMask = 0;
    if (!scene.writeColor) blend[0].colorWriteMask = 0;
    if (scene.translucent) {
        // Over: the fragment's alpha of its colour, the rest of what is there; the picture
        // keeps alpha 1.
        blend[0].blendEnable = VK_TRUE;
        blend[0].srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
        blend[0].dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
        blend[0].colorBlendOp = VK_BLEND_OP_ADD;
        blend[0].srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
        // Over the visibility buffer's black, alpha keeps what shows through of the picture
        // the shading pass draws later; over a picture, alpha stays 1.
        blend[0].dstAlphaBlendFactor =
            scene.accumulate ? VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA : VK_BLEND_FACTOR_ONE;
        blend[0].alphaBlendOp = VK_BLEND_OP_ADD;
    }
    return blend;
}

} // namespace

vk::Handle<VkPipeline> createScenePipeline(const DiskPipelineCache& cache,
                                           const ScenePipelineInfo& scene,
                                           const std::vector<ShaderStage>& stages,
                                           const std::string& name) {
    std::vector<VkPipelineShaderStageCreateInfo> stageInfos;
    for (const auto& s : stages) {
        auto info = vk::init<VkPipelineShaderStageCreateInfo>(
            VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
        info.stage = s.stage;
        info.module = s.module.get();
        info.pName = "main";
        stageInfos.push_back(info);
    }
    const VertexInput vertexInput(scene.drawIndexAttribute);
    auto assembly = vk::init<VkPipelineInputAssemblyStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO);
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    auto viewport = vk::init<VkPipelineViewportStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    const VkPipelineRasterizationStateCreateInfo raster = rasterState();
    auto multisample = vk::init<VkPipelineMultisampleStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
    multisample.rasterizationSamples = scene.samples;
    const VkPipelineDepthStencilStateCreateInfo depth = depthState(scene.translucent);
    const std::array<VkPipelineColorBlendAttachmentState, 2> blend = blendAttachments(scene);
    auto colorBlend = vk::init<VkPipelineColorBlendStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
    colorBlend.attachmentCount = static_cast<uint32_t>(blend.size());
    colorBlend.pAttachments = blend.data();
    const std::array<VkDynamicState, 2> dynamicStates = {VK_DYNAMIC_STATE_VIEWPORT,
                                                         VK_DYNAMIC_STATE_SCISSOR};
    auto dynamic = vk::init<VkPipelineDynamicStateCreateInfo>(
        VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO);
    dynamic.dynamicStateCount = static_cast<uint32_t>(dynamicStates.size());
    dynamic.pDynamicStates = dynamicStates.data();

    auto info =
        vk::init<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO);
    info.stageCount = static_cast<uint32_t>(stageInfos.size());
    info.pStages = stageInfos.data();
    // A mesh shader makes its own primitives: no vertex input, no input assembly.
    info.pVertexInputState = scene.mesh ? nullptr : &vertexInput.info;
    info.pInputAssemblyState = scene.mesh ? nullptr : &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &colorBlend;
    info.pDynamicState = &dynamic;
    info.layout = scene.layout;
    info.renderPass = scene.pass;
    info.subpass = 0;
    return cache.create(info, name);
}

vk::Handle<VkDescriptorSetLayout> pushDescriptorLayout(const vk::Device& device,
                                                       const std::vector<VkDescriptorType>& types,
                                                       const std::string& name) {
    std::vector<VkDescriptorSetLayoutBinding> bindings(types.size());
    for (uint32_t i = 0; i < bindings.size(); ++i)
        bindings[i] = {i, types[i], 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    auto info = vk::init<VkDescriptorSetLayoutCreateInfo>(
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
    info.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
    info.bindingCount = static_cast<uint32_t>(bindings.size());
    info.pBindings = bindings.data();
    return vk::make(device, vkCreateDescriptorSetLayout, info, name);
}

vk::Handle<VkSampler> texelFetchSampler(const vk::Device& device, const std::string& name) {
    auto sampler = vk::init<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    sampler.magFilter = sampler.minFilter = VK_FILTER_NEAREST;
    sampler.addressModeU = sampler.addressModeV = sampler.addressModeW =
        VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    return vk::make(device, vkCreateSampler, sampler, name);
}

void bindWithImage(const vk::Device& device, VkCommandBuffer cmd, const ComputePipeline& pass,
                   VkDescriptorType type, const VkDescriptorImageInfo& image) {
    bindWithImages(device, cmd, pass, {{0, type, image}});
}

void bindWithImages(const vk::Device& device, VkCommandBuffer cmd, const ComputePipeline& pass,
                    const std::vector<BoundImage>& images) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.pipeline.get());
    std::vector<VkWriteDescriptorSet> writes(images.size());
    for (size_t i = 0; i < images.size(); ++i) {
        writes[i] = vk::init<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        writes[i].dstBinding = images[i].binding;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = images[i].type;
        writes[i].pImageInfo = &images[i].image;
    }
    device.pushDescriptorSet()(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.layout.get(), 0,
                               static_cast<uint32_t>(writes.size()), writes.data());
}

} // namespace render
