// renderer.cpp - pipeline (re)building and the recording of the scene pass.
#include "render/renderer.h"

#include <algorithm>
#include <array>

#include "render/pipeline.h"
#include "render/shader_variants.h"
#include "vk/check.h"
#include "vk/debug.h"

namespace render {

Renderer::Renderer(vk::Device& device, const vk::ShaderCompiler& compiler, const ScenePass& pass)
    : device_(device), compiler_(compiler), pass_(pass) {
    layout_ = createScenePipelineLayout(device);
}

Renderer::~Renderer() {
    sceneGpu_.reset();
    if (pipeline_) vkDestroyPipeline(device_.handle(), pipeline_, nullptr);
    vkDestroyPipelineLayout(device_.handle(), layout_, nullptr);
}

void Renderer::setScene(const scene::Scene& scene) {
    auto uploaded = std::make_unique<SceneGpu>(device_, scene);
    // The old buffers may still be read by frames in flight.
    vk::check(vkDeviceWaitIdle(device_.handle()), "vkDeviceWaitIdle");
    sceneGpu_ = std::move(uploaded);
    if (technique_) draws_ = technique_->buildDrawList(scene);
}

void Renderer::setTechnique(const Technique& technique, const DrawMode& mode,
                            const scene::Scene& scene) {
    VkPipeline pipeline = buildPipeline(technique, mode); // throws before anything changes
    vk::check(vkDeviceWaitIdle(device_.handle()), "vkDeviceWaitIdle");
    if (pipeline_) vkDestroyPipeline(device_.handle(), pipeline_, nullptr);
    pipeline_ = pipeline;
    technique_ = &technique;
    mode_ = &mode;
    draws_ = technique.buildDrawList(scene);
}

VkPipeline Renderer::buildPipeline(const Technique& technique, const DrawMode& mode) const {
    std::vector<ShaderStage> stages;
    auto destroyModules = [&] {
        for (auto& s : stages) vkDestroyShaderModule(device_.handle(), s.module, nullptr);
    };
    try {
        for (const auto& request : shaderVariants(technique, mode)) {
            auto spirv = compiler_.compile(request);
            stages.push_back({request.stage, vk::createShaderModule(device_.handle(), spirv)});
            device_.name(VK_OBJECT_TYPE_SHADER_MODULE, stages.back().module, request.label());
        }
        const std::string name = std::string(technique.name) + " + " + mode.name;
        VkPipeline pipeline = createScenePipeline(device_, layout_, pass_.handle(), stages, name);
        destroyModules();
        return pipeline;
    } catch (...) {
        destroyModules();
        throw;
    }
}

void Renderer::record(FrameSlot& slot, const SceneTargets& targets,
                      const FrameParams& params) const {
    if (!pipeline_ || !sceneGpu_) throw vk::Error("Renderer::record before scene and technique");
    VkCommandBuffer cmd = slot.cmd;
    vk::CmdLabel label(device_.debug(), cmd, "scene pass");

    gpu::FrameData frame{};
    frame.viewProj = params.viewProj;
    frame.eyePosition = glm::vec4(params.eye, 1.0f);
    frame.viewport = {targets.extent().width, targets.extent().height};
    frame.partColorWeight = params.partColorWeight;
    frame.flags = params.colorizeDraws ? gpu::FRAME_COLORIZE_DRAWS : 0u;
    frame.objectsAddress = sceneGpu_->objectsAddress();
    frame.materialsAddress = sceneGpu_->materialsAddress();
    vkCmdUpdateBuffer(cmd, slot.frameData.buffer, 0, sizeof frame, &frame);

    auto toShaders = vk::init<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    toShaders.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toShaders.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_VERTEX_SHADER_BIT |
                             VK_PIPELINE_STAGE_GEOMETRY_SHADER_BIT |
                             VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                         0, 1, &toShaders, 0, nullptr, 0, nullptr);

    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, slot.timestamps, 0);
    std::array<VkClearValue, 3> clears{};
    clears[0].color = {{0.16f, 0.17f, 0.19f, 1.0f}};
    clears[1].color.uint32[0] = gpu::BACKGROUND_ID;
    clears[2].depthStencil = {1.0f, 0};
    auto begin = vk::init<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO);
    begin.renderPass = pass_.handle();
    begin.framebuffer = targets.framebuffer();
    begin.renderArea = {{0, 0}, targets.extent()};
    begin.clearValueCount = static_cast<uint32_t>(clears.size());
    begin.pClearValues = clears.data();
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);

    VkViewport viewport{0, 0, float(targets.extent().width), float(targets.extent().height), 0, 1};
    VkRect2D scissor{{0, 0}, targets.extent()};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, gpu::BINDING_VERTICES, 1, &sceneGpu_->vertices().buffer, &zero);
    vkCmdBindIndexBuffer(cmd, sceneGpu_->indices().buffer, 0, VK_INDEX_TYPE_UINT32);

    // The whole block once per frame (frame address, zeroed draw fields); draws change the tail.
    gpu::DrawPush push{};
    push.frameAddress = slot.frameData.address;
    vkCmdPushConstants(cmd, layout_, pushStages, 0, sizeof push, &push);
    recordDraws(cmd);

    vkCmdEndRenderPass(cmd);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, slot.timestamps, 1);
}

// `push` mode: per draw, push only the span of DrawPush fields that differ from the last draw.
void Renderer::recordDraws(VkCommandBuffer cmd) const {
    constexpr uint32_t fieldCount = 3; // objectIndex, partIndex, drawIndex, as pushed zeroed
    std::array<uint32_t, fieldCount> last{0, 0, 0};
    for (uint32_t i = 0; i < draws_.size(); ++i) {
        const DrawItem& draw = draws_[i];
        const std::array<uint32_t, fieldCount> now{draw.object, draw.firstPart, i};
        uint32_t first = fieldCount, end = 0;
        for (uint32_t f = 0; f < fieldCount; ++f)
            if (now[f] != last[f]) {
                first = std::min(first, f);
                end = f + 1;
            }
        if (first < end)
            vkCmdPushConstants(cmd, layout_, pushStages,
                               gpu::DRAW_PUSH_TAIL_OFFSET + first * sizeof(uint32_t),
                               (end - first) * sizeof(uint32_t), &now[first]);
        last = now;
        vkCmdDrawIndexed(cmd, draw.indexCount, 1, draw.firstIndex, draw.vertexOffset, 0);
    }
}

} // namespace render
