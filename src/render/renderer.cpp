// renderer.cpp - pipeline and draw buffer (re)building, and the recording of the scene pass.
#include "render/renderer.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstring>

#include "render/pipeline.h"
#include "render/shader_variants.h"
#include "vk/check.h"
#include "vk/debug.h"

namespace render {

Renderer::Renderer(vk::Device& device, const vk::ShaderCompiler& compiler, const ScenePass& pass)
    : device_(device), compiler_(compiler), pass_(pass) {
    layout_ = createScenePipelineLayout(device);
    const gpu::PickData none{gpu::PICK_NONE, gpu::PICK_NONE};
    try {
        pick_ = vk::createBufferWithData(
            device, &none, sizeof none,
            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
                VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
            "pick");
    } catch (...) {
        vkDestroyPipelineLayout(device_.handle(), layout_, nullptr);
        throw;
    }
}

Renderer::~Renderer() {
    sceneGpu_.reset();
    destroyDraws(drawBuffers_);
    if (pipeline_) vkDestroyPipeline(device_.handle(), pipeline_, nullptr);
    vk::destroyBuffer(device_, pick_);
    vkDestroyPipelineLayout(device_.handle(), layout_, nullptr);
}

void Renderer::setScene(const scene::Scene& scene) {
    auto uploaded = std::make_unique<SceneGpu>(device_, scene);
    auto animator =
        std::make_unique<Animator>(device_, compiler_, scene, uploaded->objectsAddress());
    // The old buffers may still be read by frames in flight.
    vk::check(vkDeviceWaitIdle(device_.handle()), "vkDeviceWaitIdle");
    sceneGpu_ = std::move(uploaded);
    animator_ = std::move(animator);
}

void Renderer::configure(const scene::Scene& scene, const RenderConfig& config) {
    if (!config.technique || !config.mode) throw vk::Error("Renderer::configure without technique");
    const Technique& technique = *config.technique;
    Variant variant{&technique, config.mode,
                    technique.ids == IdBuffer::PartTriangleCounts ? config.searchBatch : 0u,
                    technique.stage == LookupStage::Geometry && config.gsPassthrough &&
                        device_.info().geometryShaderPassthrough,
                    technique.narySearch ? config.nsearch : NarySearch{}};
    // Build everything new first, so a failure leaves the current configuration intact.
    VkPipeline pipeline = variant == variant_ ? VK_NULL_HANDLE : buildPipeline(variant);
    DrawList list =
        buildDrawList(scene, technique, {config.searchBatch, config.sortDraws, config.visible});
    DrawBuffers buffers;
    try {
        buffers = uploadDraws(list, *config.mode);
    } catch (...) {
        if (pipeline) vkDestroyPipeline(device_.handle(), pipeline, nullptr);
        throw;
    }

    vk::check(vkDeviceWaitIdle(device_.handle()), "vkDeviceWaitIdle");
    if (pipeline) {
        if (pipeline_) vkDestroyPipeline(device_.handle(), pipeline_, nullptr);
        pipeline_ = pipeline;
        variant_ = variant;
    }
    destroyDraws(drawBuffers_);
    drawBuffers_ = buffers;
    drawList_ = std::move(list);

    stats_ = statsFor(drawList_, *config.mode);
    stats_.gsPassthrough = variant_.passthrough;
}

void Renderer::reloadShaders() {
    if (!variant_.technique) return; // nothing configured yet
    VkPipeline pipeline = buildPipeline(variant_);
    vk::check(vkDeviceWaitIdle(device_.handle()), "vkDeviceWaitIdle"); // frames in flight
    vkDestroyPipeline(device_.handle(), pipeline_, nullptr);
    pipeline_ = pipeline;
}

VkPipeline Renderer::buildPipeline(const Variant& variant) const {
    std::vector<ShaderStage> stages;
    auto destroyModules = [&] {
        for (auto& s : stages) vkDestroyShaderModule(device_.handle(), s.module, nullptr);
    };
    try {
        for (const auto& request :
             shaderVariants(*variant.technique, *variant.mode,
                            {variant.searchCount, variant.passthrough, variant.nsearch})) {
            auto spirv = compiler_.compile(request);
            stages.push_back({request.stage, vk::createShaderModule(device_.handle(), spirv)});
            device_.name(VK_OBJECT_TYPE_SHADER_MODULE, stages.back().module, request.label());
        }
        const std::string name = std::string(variant.technique->name) + " + " + variant.mode->name;
        VkPipeline pipeline = createScenePipeline(
            device_, layout_, pass_.handle(), pass_.samples(), stages,
            variant.mode->drawIndexAttribute, variant.technique->stage != LookupStage::None, name);
        destroyModules();
        return pipeline;
    } catch (...) {
        destroyModules();
        throw;
    }
}

Renderer::DrawBuffers Renderer::uploadDraws(const DrawList& list, const DrawMode& mode) const {
    DrawBuffers b;
    const VkBufferUsageFlags shaderRead =
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
    try {
        if (!list.idBytes.empty())
            b.ids = vk::createBufferWithData(device_, list.idBytes.data(), list.idBytes.size(),
                                             shaderRead, "technique ID data");
        if (mode.indirect && !list.data.empty()) {
            b.draws = vk::createBufferWithData(device_, list.data.data(),
                                               list.data.size() * sizeof(gpu::DrawData), shaderRead,
                                               "per-draw data");
            std::vector<VkDrawIndexedIndirectCommand> commands;
            commands.reserve(list.ranges.size());
            for (uint32_t i = 0; i < list.ranges.size(); ++i) {
                const DrawItem& d = list.ranges[i];
                // firstInstance carries the draw index (gl_InstanceIndex, or the attribute's row).
                commands.push_back({d.indexCount, 1, d.firstIndex, d.vertexOffset, i});
            }
            b.indirect = vk::createBufferWithData(
                device_, commands.data(), commands.size() * sizeof(VkDrawIndexedIndirectCommand),
                VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, "indirect draws");
            if (mode.drawIndexAttribute) {
                std::vector<uint32_t> rows(list.ranges.size());
                for (uint32_t i = 0; i < rows.size(); ++i) rows[i] = i;
                b.drawIndices = vk::createBufferWithData(
                    device_, rows.data(), rows.size() * sizeof(uint32_t),
                    VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "draw index attribute");
            }
        }
    } catch (...) {
        destroyDraws(b);
        throw;
    }
    return b;
}

void Renderer::destroyDraws(DrawBuffers& b) const {
    for (vk::Buffer* buffer : {&b.ids, &b.draws, &b.indirect, &b.drawIndices})
        vk::destroyBuffer(device_, *buffer);
}

void Renderer::record(FrameSlot& slot, const SceneTargets& targets,
                      const FrameParams& params) const {
    if (!pipeline_ || !sceneGpu_) throw vk::Error("Renderer::record before setScene and configure");
    VkCommandBuffer cmd = slot.cmd;
    vk::CmdLabel label(device_.debug(), cmd, "scene pass");

    gpu::FrameData frame{};
    frame.viewProj = params.viewProj;
    frame.eyePosition = glm::vec4(params.eye, 1.0f);
    frame.viewport = {targets.extent().width, targets.extent().height};
    frame.partColorWeight = params.partColorWeight;
    frame.flags = (params.colorizeDraws ? gpu::FRAME_COLORIZE_DRAWS : 0u) |
                  (params.ignoreMaterials ? gpu::FRAME_IGNORE_MATERIALS : 0u);
    frame.sampleZero = pass_.sampleZero();
    frame.objectsAddress = sceneGpu_->objectsAddress();
    frame.materialsAddress = sceneGpu_->materialsAddress();
    frame.idsAddress = drawBuffers_.ids.address;
    frame.drawsAddress = drawBuffers_.draws.address;
    frame.pickAddress = pick_.address;
    frame.pickPixel = params.pickPixel.value_or(glm::uvec2(gpu::NO_PICK));
    frame.selectedPart = params.selectedPart;
    frame.time = params.time;
    vkCmdUpdateBuffer(cmd, slot.frameData.buffer, 0, sizeof frame, &frame);
    slot.pickPixel = params.pickPixel;
    recordPickReset(cmd);

    // Frame data and the pick reset (this frame), `last` (the previous frame's copy).
    auto toShaders = vk::init<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    toShaders.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toShaders.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_VERTEX_SHADER_BIT |
                             VK_PIPELINE_STAGE_GEOMETRY_SHADER_BIT |
                             VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                         0, 1, &toShaders, 0, nullptr, 0, nullptr);

    animator_->record(cmd, params.explode); // outside the pass and its timestamps
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
    if (drawBuffers_.drawIndices.buffer)
        vkCmdBindVertexBuffers(cmd, gpu::BINDING_DRAW_INDICES, 1, &drawBuffers_.drawIndices.buffer,
                               &zero);
    vkCmdBindIndexBuffer(cmd, sceneGpu_->indices().buffer, 0, VK_INDEX_TYPE_UINT32);

    // The whole block once per frame (frame address, zeroed draw); push mode changes the draw.
    gpu::DrawPush push{};
    push.frameAddress = slot.frameData.address;
    vkCmdPushConstants(cmd, layout_, pushStages, 0, sizeof push, &push);
    if (variant_.mode->indirect)
        recordIndirectDraws(cmd);
    else
        recordPushDraws(cmd);

    vkCmdEndRenderPass(cmd);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, slot.timestamps, 1);
    recordPickCopies(cmd, slot);
}

// Before the pass: the previous frame's shaders and copies are done with the pick buffer
// (write-after-read and write-after-write across frames on the one queue), then reset it.
void Renderer::recordPickReset(VkCommandBuffer cmd) const {
    auto before = vk::init<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    before.srcAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT |
                           VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    before.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd,
                         VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &before, 0, nullptr, 0, nullptr);
    vkCmdFillBuffer(cmd, pick_.buffer, offsetof(gpu::PickData, current), sizeof(uint64_t),
                    0xFFFFFFFFu);
}

// After the pass: `current` becomes `last` for the next frame's highlight and goes to the
// slot's host-visible readback, read when the slot's fence has signalled.
void Renderer::recordPickCopies(VkCommandBuffer cmd, const FrameSlot& slot) const {
    auto fromShaders = vk::init<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    fromShaders.srcAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    fromShaders.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         0, 1, &fromShaders, 0, nullptr, 0, nullptr);
    VkBufferCopy toLast{offsetof(gpu::PickData, current), offsetof(gpu::PickData, last),
                        sizeof(uint64_t)};
    vkCmdCopyBuffer(cmd, pick_.buffer, pick_.buffer, 1, &toLast);
    VkBufferCopy toHost{offsetof(gpu::PickData, current), 0, sizeof(uint64_t)};
    vkCmdCopyBuffer(cmd, pick_.buffer, slot.pickReadback.buffer, 1, &toHost);
    auto toHostRead = vk::init<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    toHostRead.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHostRead.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &toHostRead, 0, nullptr, 0, nullptr);
}

// `push` mode: per draw, push only the span of DrawData fields that differ from the last draw.
void Renderer::recordPushDraws(VkCommandBuffer cmd) const {
    constexpr uint32_t fieldCount = sizeof(gpu::DrawData) / sizeof(uint32_t);
    std::array<uint32_t, fieldCount> last{}; // as pushed, zeroed, at the start of the frame
    for (size_t i = 0; i < drawList_.ranges.size(); ++i) {
        std::array<uint32_t, fieldCount> now;
        std::memcpy(now.data(), &drawList_.data[i], sizeof(gpu::DrawData));
        uint32_t first = fieldCount, end = 0;
        for (uint32_t f = 0; f < fieldCount; ++f)
            if (now[f] != last[f]) {
                first = std::min(first, f);
                end = f + 1;
            }
        if (first < end)
            vkCmdPushConstants(cmd, layout_, pushStages,
                               gpu::DRAW_PUSH_DRAW_OFFSET + first * sizeof(uint32_t),
                               (end - first) * sizeof(uint32_t), &now[first]);
        last = now;
        const DrawItem& d = drawList_.ranges[i];
        vkCmdDrawIndexed(cmd, d.indexCount, 1, d.firstIndex, d.vertexOffset, 0);
    }
}

// mdi modes: the whole draw list in as few indirect calls as the device's limit allows.
void Renderer::recordIndirectDraws(VkCommandBuffer cmd) const {
    const uint32_t total = static_cast<uint32_t>(drawList_.ranges.size());
    const uint32_t limit = std::max(1u, device_.info().maxDrawIndirectCount);
    constexpr uint32_t stride = sizeof(VkDrawIndexedIndirectCommand);
    for (uint32_t first = 0; first < total; first += limit)
        vkCmdDrawIndexedIndirect(cmd, drawBuffers_.indirect.buffer, VkDeviceSize(first) * stride,
                                 std::min(limit, total - first), stride);
}

} // namespace render
