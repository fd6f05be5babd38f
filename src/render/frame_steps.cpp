// frame_steps.cpp - the steps Renderer::record's recipe is made of: the frame's constants,
// its culling decisions on the CPU, the scene pass's begin and draws, the culling counters,
// the pick's reset and copies, and the passes over the ID image.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstring>

#include <glm/gtc/packing.hpp>

#include "render/blink.h"
#include "render/renderer.h"
#include "vk/barrier.h"
#include "vk/check.h"

namespace render {
namespace {

// Whether two compositions over the same images give the same picture but for the hovered
// part's pixels: everything but the blink's weight is equal (where the hovered part is read
// back to differs per frame slot and changes no pixel).
bool differsInBlinkOnly(const gpu::ComposePush& a, const gpu::ComposePush& b) {
    return a.lineColor == b.lineColor && a.selectColor == b.selectColor &&
           a.hoverColor == b.hoverColor && a.selectedAddress == b.selectedAddress &&
           a.tintAddress == b.tintAddress && a.extent == b.extent && a.hoverPixel == b.hoverPixel &&
           a.width == b.width && a.flags == b.flags;
}

} // namespace

CullCounts countsOf(const gpu::CullStats& stats, bool meshTechnique) {
    CullCounts counts;
    // The draws with something in the early (or only) list, and those of the late list that
    // the early one had not: the draws' count buffer counts commands, which for cluster runs
    // are runs, and the mesh tasks' late list holds every draw that may show.
    counts.draws = uint64_t(stats.listed) + stats.lateNew;
    counts.meshlets = stats.meshlets;
    counts.triangles = meshTechnique ? stats.meshletTriangles : stats.triangles;
    counts.computeTriangles = stats.rasterTriangles;
    for (uint32_t l = 0; l < gpu::LOD_MAX_LEVELS; ++l)
        counts.levelTriangles[l] =
            meshTechnique ? stats.levelMeshletTriangles[l] : stats.levelTriangles[l];
    return counts;
}

Renderer::FrameCulling Renderer::planFrame(const FrameParams& params, const SceneTargets& targets) {
    FrameCulling c;
    c.plan = cullingPlan();
    // Freezing draws the lists of the last culled frame; until there is one, it culls.
    const bool culledBefore = culledLists_.lock() == draws_->cull;
    c.frozen = settings_.culling.freeze && c.plan.culls() && culledBefore;
    if (c.plan.culls() && !c.frozen) culledLists_ = draws_->cull;
    std::optional<CulledView> view;
    if (c.plan.twoPasses && !c.frozen)
        view = CulledView{params.viewProj,
                          params.origin,
                          params.explode,
                          hiddenVersion_,
                          targets.extent().width,
                          targets.extent().height,
                          uint32_t(targets.pass().samples()),
                          settings_.lod.errorPixels,
                          settings_.section};
    c.viewUnchanged = view && culledBefore && view == lastCulledView_;
    lastCulledView_ = view;
    // A late pass writes the slot the early pass does not read; the next frame reads it.
    c.history = historySlot_;
    if (c.plan.twoPasses && !c.frozen) historySlot_.early = c.history.late();
    if (!c.plan.cpuFrustum) return c;
    if (c.frozen) {
        c.objectShown = frozenObjects_;
        return c;
    }
    // Push mode: the CPU tests each object's box, placed as the animation places it.
    c.objectShown.assign(objectParts_.size(), 0);
    for (size_t o = 0; o < objectParts_.size(); ++o)
        c.objectShown[o] =
            !objectHidden_[o] &&
            !outsideFrustum(params.viewProj,
                            sceneGpu_->worldAt(uint32_t(o), params.explode, params.origin),
                            params.eye, draws_->objectBoxes[o]);
    frozenObjects_ = c.objectShown;
    return c;
}

gpu::FrameData Renderer::frameData(const SceneTargets& targets, const FrameParams& params,
                                   const FrameCulling& culling) const {
    const Shading& shading = settings_.shading;
    gpu::FrameData frame{};
    frame.viewProj = params.viewProj;
    frame.eyePosition =
        params.orthoToViewer ? glm::vec4(*params.orthoToViewer, 0.0f) : glm::vec4(params.eye, 1.0f);
    frame.eyeReach = glm::length(params.eye);
    frame.viewport = {targets.extent().width, targets.extent().height};
    frame.partColorWeight = shading.partWeight;
    frame.flags = (shading.colorizeDraws ? gpu::FRAME_COLORIZE_DRAWS : 0u) |
                  (shading.tintLevels ? gpu::FRAME_TINT_LEVELS : 0u) |
                  (shading.ignoreMaterials ? gpu::FRAME_IGNORE_MATERIALS : 0u) |
                  (pipeline_->key.hiding ? gpu::FRAME_HIDING : 0u) |
                  (culling.viewUnchanged ? gpu::FRAME_VIEW_UNCHANGED : 0u);
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
        frame.meshletBoxesAddress = draws_->meshlets->boxes.address();
    }
    frame.visibilityDrawsAddress = draws_->visibilityDraws.address();
    frame.visibilityBlocksAddress = draws_->visibilityBlocks.address();
    if (draws_->key.technique->computeRaster) {
        frame.rasterListAddress = draws_->rasterList.address();
        frame.rasterSamplesAddress = rasterSamplesAddress();
        frame.rasterCapacity = draws_->rasterCapacity;
        // X-ray's layers depth-test against the attachment alone: under them, the hardware
        // draws everything.
        const bool xray = translucent_ && !translucent_->empty();
        const uint32_t samples = uint32_t(targets.pass().samples());
        if (raster_->runsAt(samples) && !xray)
            frame.rasterTrianglePixels = settings_.raster.all
                                             ? gpu::RASTER_ALL
                                             : settings_.raster.trianglePixels / float(samples);
    }
    frame.selectedAddress = selected_->address();
    frame.hiddenAddress = hidden_->address();
    const CullBuffers& cull = *draws_->cull;
    frame.pyramidAddress = targets.pyramid().address();
    frame.drawCullAddress = cull.draws.address();
    frame.meshletHistoryAddress = cull.meshletHistory.address();
    frame.cullStatsAddress = cull.stats.address();
    if (culling.plan.gpuLists) frame.cullStateAddress = cull.state.address();
    // Where cull.comp lists mesh draws it tests the late pass's meshlets; in push mode the
    // task shader does.
    if (culling.plan.gpuLists && draws_->meshlets)
        frame.lateMeshletsAddress = cull.lateMeshlets.address();
    if (culling.plan.levels) frame.lodErrorPixels = settings_.lod.errorPixels;
    for (uint32_t p = 0; p < gpu::SECTION_PLANES_MAX; ++p)
        frame.sectionPlanes[p] = glm::vec4(settings_.section.planes[p].equation(params.origin));
    if (settings_.section.any())
        frame.sectionTolerance = float(sceneGpu_->sectionTolerance(params.origin));
    frame.pickPixel = params.pickPixel.value_or(glm::uvec2(gpu::NO_PICK));
    frame.time = params.time;
    return frame;
}

void Renderer::beginPass(VkCommandBuffer cmd, const SceneTargets& targets, PassPart part,
                         VkDeviceAddress frame, bool clearColor) const {
    // The compute path's pass ignores the values of what it does not clear. X-ray's layers
    // over a visibility buffer add up over black, with alpha for what shows through of the
    // picture its shading pass draws under them.
    std::array<VkClearValue, 3> clears{};
    const glm::vec4 under = pipeline_->key.technique->isVisibilityBuffer()
                                ? glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)
                                : backgroundColor;
    clears[0].color = {{under.r, under.g, under.b, under.a}};
    clears[1].color.uint32[0] = gpu::BACKGROUND_ID;
    clears[2].depthStencil = {0.0f, 0}; // reversed depth: 0 is the far plane
    auto begin = vk::init<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO);
    begin.renderPass = targets.pass().handle(part, clearPath_, clearColor);
    begin.framebuffer = targets.framebuffer(part, clearPath_);
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
    // The whole block once per pass (frame address, zeroed draw); draws change parts of it.
    gpu::DrawPush push{};
    push.frameAddress = frame;
    vkCmdPushConstants(cmd, pipelines_.layout(), pushStages_, 0, sizeof push, &push);
}

// The draws of one phase: the whole list, the GPU's list, or push mode's shown objects.
void Renderer::drawPhase(VkCommandBuffer cmd, FrameCulling& culling, uint32_t phase) const {
    const DrawContext context{cmd, device_, pipelines_.layout(), pushStages_, *draws_};
    const bool late = (gpu::CULL_PHASES[phase].pass & gpu::CULL_PASS_LATE) != 0;
    if (!culling.plan.on()) {
        recordAllDraws(context);
    } else if (culling.plan.gpuLists) {
        recordCulledDraws(context, late ? 1 : 0, phase, culling.plan.clusterRuns);
    } else {
        const Issued issued = recordPushDraws(context, culling.objectShown, phase);
        if (!late) culling.issued = issued;
    }
}

// Before the scene pass (`before`): zero what the GPU counts this frame; a frozen list keeps
// its counts, which are the draws' count buffer. After it: what the CPU knows.
void Renderer::recordCounters(VkCommandBuffer cmd, const FrameCulling& culling, bool before) const {
    const vk::Buffer& stats = draws_->cull->stats;
    const bool mesh = draws_->meshlets != nullptr;
    if (before) {
        // The last frame's reads of the counters (indirect count, copies) are done, and what
        // it wrote for this frame to read (the history) is seen.
        vk::memoryBarrier(cmd,
                          VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT |
                              VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                          VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
        const bool all = culling.plan.gpuLists && !culling.frozen;
        const VkDeviceSize from = all ? 0 : offsetof(gpu::CullStats, meshlets);
        vkCmdFillBuffer(cmd, stats.handle(), from, sizeof(gpu::CullStats) - from, 0);
        if (all && culling.plan.twoPasses)
            CullPasses::recordHistoryReset(cmd, *draws_->cull, culling.history);
        vk::memoryBarrier(
            cmd, VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
            VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT,
            VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT |
                VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
            VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT |
                VK_ACCESS_INDIRECT_COMMAND_READ_BIT);
        return;
    }
    if (culling.plan.gpuLists) return; // the cull pass counted
    gpu::CullStats known{};
    const CullCounts totals = cullTotals();
    known.draws[0] = uint32_t(culling.plan.on() ? culling.issued.draws : totals.draws);
    known.listed = known.draws[0];
    known.triangles = uint32_t(culling.plan.on() ? culling.issued.triangles : totals.triangles);
    // Without culling the mesh shaders draw every meshlet; with it the task shader counts.
    known.meshlets = uint32_t(totals.meshlets);
    known.meshletTriangles = uint32_t(totals.triangles);
    // Only the cull pass chooses levels: everything else is full detail.
    known.levelTriangles[0] = known.triangles;
    known.levelMeshletTriangles[0] = known.meshletTriangles;
    const VkDeviceSize bytes = culling.plan.on() || !mesh
                                   ? offsetof(gpu::CullStats, meshlets)
                                   : offsetof(gpu::CullStats, rasterTriangles);
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    vkCmdUpdateBuffer(cmd, stats.handle(), 0, bytes, &known);
}

// The composition (highlights, edges and outlines when on, the part under the hovered
// pixel) and the frame's part set queries, into the slot's buffers.
void Renderer::recordIdPasses(VkCommandBuffer cmd, FrameSlot& slot, const SceneTargets& targets,
                              const FrameParams& params) {
    const EdgeSettings& e = settings_.edges;
    gpu::ComposePush compose{};
    compose.lineColor = glm::packUnorm4x8(glm::vec4(e.color, 1.0f));
    compose.selectColor = glm::packUnorm4x8(glm::vec4(e.selectColor, 1.0f));
    compose.hoverColor = glm::packUnorm4x8(glm::vec4(e.hoverColor, 1.0f));
    compose.selectedAddress = selected_->address();
    compose.tintAddress = tint_ ? tint_->address() : 0;
    compose.hoverAddress = slot.hoverReadback.address();
    compose.extent = {targets.extent().width, targets.extent().height};
    compose.hoverPixel = params.pickPixel.value_or(glm::uvec2(gpu::NO_PICK));
    compose.width = std::clamp(e.width, edgeWidthRange.min, edgeWidthRange.max);
    compose.flags = e.on ? gpu::EDGE_LINES | gpu::EDGE_SELECTED | gpu::EDGE_HOVERED : 0u;
    compose.blink = blinkWeight(params.time);
    compose.rasterSamplesAddress = rasterSamplesAddress();
    compose.samples = uint32_t(targets.pass().samples());
    slot.hoverPixel = params.pickPixel;
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
    // A step of the blink alone changes only the hovered part's pixels.
    const bool blinkOnly = composed_ && composed_->targets == &targets &&
                           differsInBlinkOnly(composed_->push, compose) && params.hoveredTiles &&
                           params.hoveredTiles->frame == composed_->wholeFrame;
    lastTiles_ = blinkOnly ? params.hoveredTiles : std::nullopt;
    if (!blinkOnly) {
        const gpu::HoverBox empty{glm::uvec2(~0u), glm::uvec2(0u)};
        std::memcpy(slot.hoverBoxReadback.mapped(), &empty, sizeof empty); // the fence signalled
        compose.boxAddress = slot.hoverBoxReadback.address();
        slot.composedWhole = true;
    }
    composed_ = Composed{&targets, compose, blinkOnly ? composed_->wholeFrame : slot.frameNumber};
    idPasses_->record(cmd, targets, compose, lastTiles_, params.partSets, words, slot.partSets,
                      slot.partSetsReadback);
    // The hovered part, written by the shader into the slot's host-visible buffer.
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                      VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
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

// X-ray's pass, last in the scene pass's last render pass: after every opaque draw, so that
// its blend sees the finished picture and its depth test the selection's depth. Its draws
// read the scene's vertices and indices, whatever the technique drew from.
void Renderer::recordTranslucent(VkCommandBuffer cmd) const {
    if (!translucent_ || !translucentPipeline_) return;
    vk::CmdLabel label(device_.debug(), cmd, "x-ray");
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, translucentPipeline_->handle.get());
    const VkDeviceSize zero = 0;
    const VkBuffer vertices = sceneGpu_->vertices().handle();
    vkCmdBindVertexBuffers(cmd, gpu::BINDING_VERTICES, 1, &vertices, &zero);
    vkCmdBindIndexBuffer(cmd, sceneGpu_->indices().handle(), 0, VK_INDEX_TYPE_UINT32);
    // The floor's shaders read the object of the pushed draw; the rest of it zero (full
    // detail, draw 0) in place of what the technique's draws left there.
    const gpu::DrawData none{};
    vkCmdPushConstants(cmd, pipelines_.layout(), pushStages_, gpu::DRAW_PUSH_DRAW_OFFSET,
                       sizeof none, &none);
    for (const TranslucentDraw& d : *translucent_) {
        vkCmdPushConstants(cmd, pipelines_.layout(), pushStages_,
                           gpu::DRAW_PUSH_DRAW_OFFSET + offsetof(gpu::DrawData, objectIndex),
                           sizeof d.object, &d.object);
        vkCmdDrawIndexed(cmd, d.indexCount, 1, d.firstIndex, d.vertexOffset, 0);
    }
}

// Before the pass: the previous frame's shaders and copies are done with the pick buffer
// (write-after-read and write-after-write across frames on the one queue), then reset it.
void Renderer::recordPickReset(VkCommandBuffer cmd) const {
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT |
                          VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    vkCmdFillBuffer(cmd, pick_->handle(), offsetof(gpu::PickData, current), sizeof(uint64_t),
                    0xFFFFFFFFu);
}

// After the pass: `current` becomes `last` for the next frame's highlight and goes to the
// slot's host-visible readback, read when the slot's fence has signalled; so do the culling
// counters.
void Renderer::recordPickCopies(VkCommandBuffer cmd, const FrameSlot& slot) const {
    // The edge pass reads `last`; the task shader and the cull pass write the counters.
    vk::memoryBarrier(
        cmd,
        VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT |
            VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
        VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT,
        VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT);
    VkBufferCopy toLast{offsetof(gpu::PickData, current), offsetof(gpu::PickData, last),
                        sizeof(uint64_t)};
    vkCmdCopyBuffer(cmd, pick_->handle(), pick_->handle(), 1, &toLast);
    VkBufferCopy toHost{offsetof(gpu::PickData, current), 0, sizeof(uint64_t)};
    vkCmdCopyBuffer(cmd, pick_->handle(), slot.pickReadback.handle(), 1, &toHost);
    const VkBufferCopy counters{0, 0, sizeof(gpu::CullStats)};
    vkCmdCopyBuffer(cmd, draws_->cull->stats.handle(), slot.cullReadback.handle(), 1, &counters);
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
}

gpu::VisibilityPush Renderer::visibilityPush(VkDeviceAddress frame, bool xray) const {
    gpu::VisibilityPush push{};
    push.frameAddress = frame;
    push.flags = (xray ? gpu::VIS_XRAY : 0u) | (settings_.section.any() ? gpu::VIS_SECTION : 0u);
    return push;
}

} // namespace render
