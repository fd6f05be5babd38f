// renderer.cpp - configuring (scene, pipeline, draw buffers) and recording the scene pass.
#include "render/renderer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstring>

#include "render/pipeline.h"
#include "vk/check.h"
#include "vk/debug.h"

namespace render {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::shared_ptr<const vk::Buffer> partSetBuffer(vk::UploadBatch& upload, const scene::PartSet& set,
                                                const char* name) {
    // At least one word: an empty scene still gets a buffer with an address.
    std::vector<uint32_t> words = set.words();
    if (words.empty()) words.push_back(0);
    auto buffer = std::make_shared<vk::Buffer>(upload.add(
        words, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
        name));
    upload.keep(buffer);
    return buffer;
}

} // namespace

Renderer::Renderer(vk::Device& device, const vk::ShaderCompiler& compiler)
    : device_(device), compiler_(compiler), pushStages_(pushStages(device)),
      pipelines_(device, compiler), animator_(std::make_shared<Animator>(device, compiler)),
      idPasses_(std::make_shared<IdPasses>(device, compiler)) {
    const gpu::PickData none{gpu::PICK_NONE, gpu::PICK_NONE};
    vk::UploadBatch upload(device);
    pick_ = std::make_shared<vk::Buffer>(upload.add(&none, sizeof none,
                                                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                                        VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
                                                        VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                                    "pick"));
    upload.keep(pick_);
    upload.submit();
}

const ScenePass& Renderer::pass(uint32_t msaa) {
    auto found = passes_.find(msaa);
    if (found == passes_.end())
        found = passes_
                    .emplace(msaa, std::make_unique<ScenePass>(device_,
                                                               checkedSampleCount(device_, msaa)))
                    .first;
    return *found->second;
}

void Renderer::setScene(const scene::Scene& scene, const RenderSettings& settings) {
    apply(scene, settings, true);
}

void Renderer::configure(const scene::Scene& scene, const RenderSettings& settings) {
    if (!sceneGpu_) throw vk::Error("Renderer::configure before setScene");
    apply(scene, settings, false);
}

// Everything new is built (and its uploads submitted, in one batch) before anything is
// replaced, so a throw leaves the previous configuration whole.
void Renderer::apply(const scene::Scene& scene, const RenderSettings& settings, bool newScene) {
    const auto start = Clock::now();
    PipelineKey wanted = settings.pipeline;
    wanted.hiding = !newScene && !hiddenSet_.empty(); // a new scene starts with none hidden
    const PipelineKey key = wanted.effective(device_.info().geometryShaderPassthrough);
    const Technique& technique = *key.technique;
    if (const std::string why = unavailableReason(technique, device_.info()); !why.empty())
        throw vk::Error(std::string(technique.name) + " is unavailable here: " + why);
    bool cached = false;
    auto pipeline = pipelines_.get(key, pass(key.msaa), cached);
    const bool keepDraws = !newScene && drawsStillRight(key, settings.draws);
    vk::UploadBatch upload(device_);
    auto sceneGpu = newScene ? std::make_shared<SceneGpu>(scene, upload) : sceneGpu_;
    auto partVertices = newScene ? nullptr : partVertices_;
    auto meshlets = newScene ? nullptr : meshlets_;
    if (technique.primitives == Primitives::PartVertices && !partVertices)
        partVertices = std::make_shared<PartVertexBuffers>(scene, upload);
    if (technique.primitives == Primitives::Meshlets && !meshlets)
        meshlets = std::make_shared<MeshletBuffers>(scene, upload);
    auto draws =
        keepDraws ? draws_ : buildDraws(scene, key, settings.draws, partVertices, meshlets, upload);
    upload.keep(sceneGpu);
    upload.keep(partVertices);
    upload.keep(meshlets);
    upload.keep(draws);
    const scene::PartSet none(scene.uniquePartCount());
    auto selected = newScene ? partSetBuffer(upload, none, "selection") : selected_;
    auto hidden = newScene ? partSetBuffer(upload, none, "hidden parts") : hidden_;
    upload.submit(); // nothing when nothing was added
    pipeline_ = std::move(pipeline);
    sceneGpu_ = std::move(sceneGpu);
    partVertices_ = std::move(partVertices);
    meshlets_ = std::move(meshlets);
    draws_ = std::move(draws);
    selected_ = std::move(selected);
    hidden_ = std::move(hidden);
    if (newScene) {
        partCount_ = scene.uniquePartCount();
        hiddenSet_ = none;
    }
    settings_ = settings;
    stats_ = statsFor(draws_->list, *key.mode,
                      derivedPrimitives(draws_->partVertices.get(), draws_->meshlets.get()));
    stats_.gsPassthrough = key.gsPassthrough;
    lastSwitch_ = {msSince(start), cached, keepDraws};
}

void Renderer::reloadShaders() {
    if (!pipeline_) return; // nothing configured yet
    const PipelineKey key = pipeline_->key;
    pipelines_.clear();
    auto animator = std::make_shared<Animator>(device_, compiler_);
    auto idPasses = std::make_shared<IdPasses>(device_, compiler_);
    bool cached = false;
    pipeline_ = pipelines_.get(key, pass(key.msaa), cached);
    animator_ = std::move(animator);
    idPasses_ = std::move(idPasses);
}

void Renderer::setSelection(const scene::PartSet& selected) {
    if (!sceneGpu_ || selected.partCount() != partCount_)
        throw vk::Error("Renderer::setSelection: not a set over the current scene's parts");
    vk::UploadBatch upload(device_);
    auto buffer = partSetBuffer(upload, selected, "selection");
    upload.submit();
    selected_ = std::move(buffer);
}

void Renderer::setHidden(const scene::PartSet& hidden) {
    if (!sceneGpu_ || hidden.partCount() != partCount_)
        throw vk::Error("Renderer::setHidden: not a set over the current scene's parts");
    auto pipeline = pipeline_;
    if (hidden.empty() != hiddenSet_.empty()) {
        PipelineKey key = pipeline_->key;
        key.hiding = !hidden.empty();
        key = key.effective(device_.info().geometryShaderPassthrough);
        bool cached = false;
        pipeline = pipelines_.get(key, pass(key.msaa), cached);
    }
    vk::UploadBatch upload(device_);
    auto buffer = partSetBuffer(upload, hidden, "hidden parts");
    upload.submit();
    pipeline_ = std::move(pipeline);
    hidden_ = std::move(buffer);
    hiddenSet_ = hidden;
}

// The draw list depends on the technique's split and ID data, the search batch it reads, the
// mode's buffers and the draw settings; a switch that changes none of them keeps it.
bool Renderer::drawsStillRight(const PipelineKey& key, const DrawSettings& draws) const {
    if (!draws_) return false;
    const PipelineKey& built = draws_->key;
    return built.technique->split == key.technique->split &&
           built.technique->ids == key.technique->ids &&
           built.technique->primitives == key.technique->primitives &&
           built.searchBatch == key.searchBatch && built.mode == key.mode &&
           draws_->inputs == draws;
}

std::shared_ptr<const Renderer::DrawBuffers>
Renderer::buildDraws(const scene::Scene& scene, const PipelineKey& key, const DrawSettings& draws,
                     std::shared_ptr<const PartVertexBuffers> partVertices,
                     std::shared_ptr<const MeshletBuffers> meshlets,
                     vk::UploadBatch& upload) const {
    auto b = std::make_shared<DrawBuffers>();
    // Only what this technique draws is held (and counted in its stats).
    if (key.technique->primitives == Primitives::PartVertices) b->partVertices = partVertices;
    if (key.technique->usesMeshShader()) b->meshlets = meshlets;
    b->list = buildDrawList(scene, key, draws,
                            derivedPrimitives(b->partVertices.get(), b->meshlets.get()));
    b->key = key;
    b->inputs = draws;
    const DrawList& list = b->list;
    const VkBufferUsageFlags shaderRead =
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
    const VkBufferUsageFlags vertexRead = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
    if (!list.idBytes.empty()) b->ids = upload.add(list.idBytes, shaderRead, "technique ID data");
    if (!key.mode->indirect || list.data.empty()) return b;
    b->draws = upload.add(list.data, shaderRead, "per-draw data");
    if (b->meshlets) {
        std::vector<VkDrawMeshTasksIndirectCommandEXT> commands;
        commands.reserve(list.ranges.size());
        // One workgroup per meshlet; the draw index is the command's (gl_DrawID).
        for (uint32_t count : list.meshletCounts) commands.push_back({count, 1, 1});
        b->indirect = upload.add(commands, VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, "indirect draws");
    } else {
        std::vector<VkDrawIndexedIndirectCommand> commands;
        commands.reserve(list.ranges.size());
        for (uint32_t i = 0; i < list.ranges.size(); ++i) {
            const DrawItem& d = list.ranges[i];
            // firstInstance carries the draw index (gl_InstanceIndex, or the attribute's row).
            commands.push_back({d.indexCount, 1, d.firstIndex, d.vertexOffset, i});
        }
        b->indirect = upload.add(commands, VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, "indirect draws");
    }
    if (key.mode->drawIndexAttribute) {
        std::vector<uint32_t> rows(list.ranges.size());
        for (uint32_t i = 0; i < rows.size(); ++i) rows[i] = i;
        // Mesh shaders have no vertex input: they read the rows by address instead.
        b->drawIndices =
            upload.add(rows, b->meshlets ? shaderRead : vertexRead, "draw index attribute");
    }
    return b;
}

void Renderer::record(FrameSlot& slot, const std::shared_ptr<const SceneTargets>& target,
                      const FrameParams& params) const {
    if (!pipeline_ || !sceneGpu_) throw vk::Error("Renderer::record before setScene");
    const SceneTargets& targets = *target;
    if (uint32_t(targets.pass().samples()) != pipeline_->key.msaa)
        throw vk::Error("Renderer::record: targets of another MSAA setting than configured");
    VkCommandBuffer cmd = slot.cmd;
    slot.keep(pipeline_);
    slot.keep(sceneGpu_);
    slot.keep(draws_);
    slot.keep(pick_);
    slot.keep(animator_);
    slot.keep(idPasses_);
    slot.keep(selected_);
    slot.keep(hidden_);
    slot.keep(target);
    vk::CmdLabel label(device_.debug(), cmd, "scene pass");

    const Shading& shading = settings_.shading;
    gpu::FrameData frame{};
    frame.viewProj = params.viewProj;
    frame.eyePosition = glm::vec4(params.eye, 1.0f);
    frame.viewport = {targets.extent().width, targets.extent().height};
    frame.partColorWeight = shading.partWeight;
    frame.flags = (shading.colorizeDraws ? gpu::FRAME_COLORIZE_DRAWS : 0u) |
                  (shading.ignoreMaterials ? gpu::FRAME_IGNORE_MATERIALS : 0u);
    frame.sampleZero = targets.pass().sampleZero();
    frame.objectsAddress = sceneGpu_->objectsAddress();
    frame.materialsAddress = sceneGpu_->materialsAddress();
    frame.partMaterialsAddress = sceneGpu_->partMaterialsAddress();
    frame.idsAddress = draws_->ids.address();
    frame.drawsAddress = draws_->draws.address();
    frame.pickAddress = pick_->address();
    if (draws_->meshlets) {
        frame.verticesAddress = draws_->meshlets->vertices.address();
        frame.meshletsAddress = draws_->meshlets->meshlets.address();
        frame.meshletDataAddress = draws_->meshlets->data.address();
        frame.drawIndicesAddress = draws_->drawIndices.address();
    }
    frame.selectedAddress = selected_->address();
    frame.hiddenAddress = hidden_->address();
    frame.pickPixel = params.pickPixel.value_or(glm::uvec2(gpu::NO_PICK));
    frame.time = params.time;
    vkCmdUpdateBuffer(cmd, slot.frameData.handle(), 0, sizeof frame, &frame);
    slot.pickPixel = params.pickPixel;
    recordPickReset(cmd);

    // Frame data and the pick reset (this frame), `last` (the previous frame's copy, which the
    // edge pass reads too).
    auto toShaders = vk::init<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    toShaders.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toShaders.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         sceneShaderStages(device_) | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1,
                         &toShaders, 0, nullptr, 0, nullptr);

    animator_->record(cmd, *sceneGpu_, params.explode);
    // The start is written once every earlier command has finished (bottom of the pipe), so
    // neither the animation's dispatch nor the previous frame's tail counts as the pass.
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, slot.timestamps.get(), 0);
    std::array<VkClearValue, 3> clears{};
    clears[0].color = {{0.16f, 0.17f, 0.19f, 1.0f}};
    clears[1].color.uint32[0] = gpu::BACKGROUND_ID;
    clears[2].depthStencil = {1.0f, 0};
    auto begin = vk::init<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO);
    begin.renderPass = targets.pass().handle();
    begin.framebuffer = targets.framebuffer();
    begin.renderArea = {{0, 0}, targets.extent()};
    begin.clearValueCount = static_cast<uint32_t>(clears.size());
    begin.pClearValues = clears.data();
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);

    VkViewport viewport{0, 0, float(targets.extent().width), float(targets.extent().height), 0, 1};
    VkRect2D scissor{{0, 0}, targets.extent()};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_->handle.get());
    bindGeometry(cmd);

    // The whole block once per frame (frame address, zeroed draw); push mode changes the draw.
    gpu::DrawPush push{};
    push.frameAddress = slot.frameData.address();
    vkCmdPushConstants(cmd, pipelines_.layout(), pushStages_, 0, sizeof push, &push);
    if (draws_->meshlets && pipeline_->key.mode->indirect)
        recordMeshDraws(cmd);
    else if (pipeline_->key.mode->indirect)
        recordIndirectDraws(cmd);
    else
        recordPushDraws(cmd);

    vkCmdEndRenderPass(cmd);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, slot.timestamps.get(), 1);
    recordIdPasses(cmd, slot, targets, params);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, slot.timestamps.get(), 2);
    recordPickCopies(cmd, slot);
}

// Edges and outlines (when on), and the frame's part set queries, into the slot's buffers.
void Renderer::recordIdPasses(VkCommandBuffer cmd, FrameSlot& slot, const SceneTargets& targets,
                              const FrameParams& params) const {
    const EdgeSettings& e = settings_.edges;
    gpu::EdgePush edges{};
    edges.lineColor = glm::vec4(e.color, 1.0f);
    edges.selectColor = glm::vec4(e.selectColor, 1.0f);
    edges.hoverColor = glm::vec4(e.hoverColor, 1.0f);
    edges.selectedAddress = selected_->address();
    edges.pickAddress = pick_->address();
    edges.extent = {targets.extent().width, targets.extent().height};
    edges.width = std::clamp(e.width, edgeWidthRange.min, edgeWidthRange.max);
    edges.flags = gpu::EDGE_LINES | gpu::EDGE_SELECTED | gpu::EDGE_HOVERED;
    const uint32_t words = std::max(1u, (partCount_ + 31) / 32);
    if (!params.partSets.empty()) {
        const VkDeviceSize bytes =
            (sizeof(gpu::PartSetResult) + VkDeviceSize(words) * 4) * params.partSets.size();
        // The slot's fence has signalled, so its old buffers are free to go.
        if (slot.partSets.size() < bytes) {
            slot.partSets = vk::Buffer(
                device_, bytes,
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
                    VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                0, "part sets");
            slot.partSetsReadback = vk::hostBuffer(device_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                   "part sets readback");
        }
        slot.partSetQueries = params.partSets;
        slot.partSetWords = words;
        slot.partSetParts = partCount_;
    }
    idPasses_->record(cmd, targets, e.on ? &edges : nullptr, params.partSets, words, slot.partSets,
                      slot.partSetsReadback);
}

// The vertex and index buffers the draws read: the scene's, the part vertices, or none for
// a mesh shader (it reads the scene's vertices by address).
void Renderer::bindGeometry(VkCommandBuffer cmd) const {
    if (draws_->meshlets) return;
    const VkDeviceSize zero = 0;
    const PartVertexBuffers* partVertices = draws_->partVertices.get();
    const VkBuffer vertices =
        partVertices ? partVertices->vertices.handle() : sceneGpu_->vertices().handle();
    vkCmdBindVertexBuffers(cmd, gpu::BINDING_VERTICES, 1, &vertices, &zero);
    if (const VkBuffer rows = draws_->drawIndices.handle())
        vkCmdBindVertexBuffers(cmd, gpu::BINDING_DRAW_INDICES, 1, &rows, &zero);
    vkCmdBindIndexBuffer(
        cmd, partVertices ? partVertices->indices.handle() : sceneGpu_->indices().handle(), 0,
        VK_INDEX_TYPE_UINT32);
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
    vkCmdFillBuffer(cmd, pick_->handle(), offsetof(gpu::PickData, current), sizeof(uint64_t),
                    0xFFFFFFFFu);
}

// After the pass: `current` becomes `last` for the next frame's highlight and goes to the
// slot's host-visible readback, read when the slot's fence has signalled.
void Renderer::recordPickCopies(VkCommandBuffer cmd, const FrameSlot& slot) const {
    auto fromShaders = vk::init<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    fromShaders.srcAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    fromShaders.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd,
                         VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT |
                             VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, // the edge pass reads `last`
                         VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &fromShaders, 0, nullptr, 0,
                         nullptr);
    VkBufferCopy toLast{offsetof(gpu::PickData, current), offsetof(gpu::PickData, last),
                        sizeof(uint64_t)};
    vkCmdCopyBuffer(cmd, pick_->handle(), pick_->handle(), 1, &toLast);
    VkBufferCopy toHost{offsetof(gpu::PickData, current), 0, sizeof(uint64_t)};
    vkCmdCopyBuffer(cmd, pick_->handle(), slot.pickReadback.handle(), 1, &toHost);
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
    const DrawList& list = draws_->list;
    for (size_t i = 0; i < list.ranges.size(); ++i) {
        std::array<uint32_t, fieldCount> now;
        std::memcpy(now.data(), &list.data[i], sizeof(gpu::DrawData));
        uint32_t first = fieldCount, end = 0;
        for (uint32_t f = 0; f < fieldCount; ++f)
            if (now[f] != last[f]) {
                first = std::min(first, f);
                end = f + 1;
            }
        if (first < end)
            vkCmdPushConstants(cmd, pipelines_.layout(), pushStages_,
                               gpu::DRAW_PUSH_DRAW_OFFSET + first * sizeof(uint32_t),
                               (end - first) * sizeof(uint32_t), &now[first]);
        last = now;
        const DrawItem& d = list.ranges[i];
        if (draws_->meshlets)
            device_.meshCommands().draw(cmd, list.meshletCounts[i], 1, 1);
        else
            vkCmdDrawIndexed(cmd, d.indexCount, 1, d.firstIndex, d.vertexOffset, 0);
    }
}

// mdi modes with a mesh shader: gl_DrawID restarts at 0 in every call, so each call pushes
// the index of its first draw (DrawData::drawIndex of the push block) for the shader to add.
void Renderer::recordMeshDraws(VkCommandBuffer cmd) const {
    const uint32_t total = static_cast<uint32_t>(draws_->list.ranges.size());
    const uint32_t limit = std::max(1u, device_.info().maxDrawIndirectCount);
    constexpr uint32_t stride = sizeof(VkDrawMeshTasksIndirectCommandEXT);
    for (uint32_t first = 0; first < total; first += limit) {
        vkCmdPushConstants(cmd, pipelines_.layout(), pushStages_,
                           gpu::DRAW_PUSH_DRAW_OFFSET + offsetof(gpu::DrawData, drawIndex),
                           sizeof(uint32_t), &first);
        device_.meshCommands().drawIndirect(cmd, draws_->indirect.handle(),
                                            VkDeviceSize(first) * stride,
                                            std::min(limit, total - first), stride);
    }
}

// mdi modes: the whole draw list in as few indirect calls as the device's limit allows.
void Renderer::recordIndirectDraws(VkCommandBuffer cmd) const {
    const uint32_t total = static_cast<uint32_t>(draws_->list.ranges.size());
    const uint32_t limit = std::max(1u, device_.info().maxDrawIndirectCount);
    constexpr uint32_t stride = sizeof(VkDrawIndexedIndirectCommand);
    for (uint32_t first = 0; first < total; first += limit)
        vkCmdDrawIndexedIndirect(cmd, draws_->indirect.handle(), VkDeviceSize(first) * stride,
                                 std::min(limit, total - first), stride);
}

} // namespace render
