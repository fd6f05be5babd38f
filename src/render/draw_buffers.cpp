// draw_buffers.cpp - uploading a draw list, and recording its draws.
#include "render/draw_buffers.h"

#include "render/compute_raster.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>

#include "scene/bounds.h"
#include "scene/lod.h"
#include "vk/check.h"

namespace render {
namespace {

// Each draw's box; for mesh tasks where its meshlet bits start: on a word, so each task
// workgroup's 32 meshlets have one word to themselves; for draws of several clusters (every
// draw, for cluster runs), a (draw, cluster) pair per cluster in `pairs`, holding the draw; for
// mesh tasks instead a (draw, meshlet) pair per meshlet bit, padding included. Returns the bits
// needed.
uint32_t cullBoxes(const scene::Scene& scene, const SceneGpu& sceneGpu, const DrawList& list,
                   bool runs, std::vector<gpu::DrawCull>& out, std::vector<uint32_t>& pairs) {
    uint32_t bits = 0;
    out.reserve(list.ranges.size());
    // The box around each object's own geometry (full detail, or the level the scene was
    // forced to), whose sphere all its draws choose their level by.
    std::vector<std::optional<scene::Bounds>> wholeBoxes(scene.geometries.size());
    auto whole = [&](uint32_t g) {
        if (!wholeBoxes[g])
            wholeBoxes[g] = scene::partRangeBounds(scene, sceneGpu.partBounds(), g, 0,
                                                   scene.geometries[g].partCount);
        return *wholeBoxes[g];
    };
    for (size_t i = 0; i < list.ranges.size(); ++i) {
        const DrawItem& d = list.ranges[i];
        const uint32_t g = d.geometry;
        const scene::Bounds box =
            scene::partRangeBounds(scene, sceneGpu.partBounds(), g, d.firstPart, d.partCount);
        // An empty box would reach the GPU as infinities that no test can be sure to cull.
        if (scene::isEmpty(box))
            throw std::logic_error("a draw of geometry '" + scene.geometries[g].name +
                                   "' has no triangles");
        gpu::DrawCull cull{};
        cull.boxMin = box.min;
        cull.boxMax = box.max;
        const uint32_t firstPart = scene.geometries[g].firstPart + d.firstPart;
        cull.firstCluster = sceneGpu.clusterStart()[firstPart];
        cull.clusterCount = sceneGpu.clusterStart()[firstPart + d.partCount] - cull.firstCluster;
        cull.firstPair = static_cast<uint32_t>(pairs.size());
        // The box around the object's own geometry, and the errors the level choice weighs.
        const uint32_t full = scene.objects[d.object].geometry;
        cull.lodBoxMin = whole(full).min;
        cull.lodBoxMax = whole(full).max;
        cull.lodError = g == full ? -1.0f : scene.geometries[g].lodError;
        const uint32_t next = scene::geometryAtLevel(scene, full, d.level + 1);
        cull.lodNextError =
            next == g ? std::numeric_limits<float>::max() : scene.geometries[next].lodError;
        if (!list.meshletCounts.empty()) {
            cull.meshletBit = bits;
            cull.meshletCount = list.meshletCounts[i];
            bits += (cull.meshletCount + 31) / 32 * 32;
            pairs.resize(bits, static_cast<uint32_t>(i));
        } else if (cull.clusterCount > 1 || runs) {
            pairs.insert(pairs.end(), cull.clusterCount, static_cast<uint32_t>(i));
        }
        out.push_back(cull);
    }
    return bits;
}

// Lets go of what the GPU alone reads once it is uploaded: the ID data always; the ranges, data
// and meshlet counts of an indirect list too (its frames draw by commands on the GPU), which
// for the per-part modes of a large scene are tens of bytes per part.
void keepOnlyWhatFramesRead(DrawList& list, bool indirect) {
    std::vector<uint8_t>().swap(list.idBytes);
    std::vector<gpu::VisibilityDraw>().swap(list.visibilityDraws);
    std::vector<uint32_t>().swap(list.visibilityBlocks);
    if (!indirect) return;
    std::vector<DrawItem>().swap(list.ranges);
    std::vector<gpu::DrawData>().swap(list.data);
    std::vector<uint32_t>().swap(list.meshletCounts);
}

uint32_t taskGroups(uint32_t meshlets) {
    return (meshlets + gpu::TASK_GROUP_SIZE - 1) / gpu::TASK_GROUP_SIZE;
}

} // namespace

std::shared_ptr<DrawBuffers> buildDrawBuffers(vk::Device& device, const scene::Scene& scene,
                                              const SceneGpu& sceneGpu, const PipelineKey& key,
                                              const DrawSettings& draws,
                                              std::shared_ptr<const PartVertexBuffers> partVertices,
                                              std::shared_ptr<const MeshletBuffers> meshlets,
                                              bool levels, vk::UploadBatch& upload) {
    auto b = std::make_shared<DrawBuffers>();
    // Only what this technique draws is held (and counted in its stats).
    if (key.technique->primitives == Primitives::PartVertices) b->partVertices = partVertices;
    if (key.technique->usesMeshShader()) b->meshlets = meshlets;
    const DerivedPrimitives derived = derivedPrimitives(b->partVertices.get(), b->meshlets.get());
    b->list = buildDrawList(scene, key, draws, derived, levels);
    b->stats = statsFor(b->list, *key.mode, derived);
    b->key = key;
    b->inputs = draws;
    b->levels = levels;
    const DrawList& list = b->list;
    for (size_t i = 0; i < list.fullDetailDraws && i < list.meshletCounts.size(); ++i)
        b->meshletTotal += list.meshletCounts[i];
    const VkBufferUsageFlags shaderRead =
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
    if (!list.idBytes.empty()) b->ids = upload.add(list.idBytes, shaderRead, "technique ID data");
    if (!list.visibilityDraws.empty()) {
        b->visibilityDraws = upload.add(list.visibilityDraws, shaderRead, "visibility draws");
        b->visibilityBlocks = upload.add(list.visibilityBlocks, shaderRead, "visibility blocks");
    }

    if (key.technique->computeRaster) {
        for (uint32_t count : list.meshletCounts) b->rasterCapacity += count;
        b->rasterList = vk::Buffer(device, rasterListBytes(b->rasterCapacity),
                                   shaderRead | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                                       VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                   0, "compute raster lists");
    }

    const bool indirect = key.mode->indirect && !list.data.empty();
    // TRANSFER_SRC: tests read the draws' objects back (test_cull_history.cpp).
    if (indirect)
        b->draws =
            upload.add(list.data, shaderRead | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "per-draw data");
    // The commands are read by the indirect draws and, with culling, by cull.comp.
    const VkBufferUsageFlags commandUse = VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | shaderRead;
    if (indirect && b->meshlets && key.taskCulling) {
        // Task workgroups of TASK_GROUP_SIZE meshlets, and the draw they belong to.
        std::vector<gpu::MeshTaskCommand> commands;
        for (uint32_t i = 0; i < list.meshletCounts.size(); ++i)
            commands.push_back({taskGroups(list.meshletCounts[i]), 1, 1, i});
        b->indirect = upload.add(commands, commandUse, "indirect draws");
        b->commandBytes = sizeof(gpu::MeshTaskCommand);
    } else if (indirect && b->meshlets) {
        std::vector<VkDrawMeshTasksIndirectCommandEXT> commands;
        // One workgroup per meshlet; the draw index is the command's (gl_DrawID).
        for (uint32_t count : list.meshletCounts) commands.push_back({count, 1, 1});
        b->indirect = upload.add(commands, commandUse, "indirect draws");
        b->commandBytes = sizeof(VkDrawMeshTasksIndirectCommandEXT);
    } else if (indirect) {
        std::vector<VkDrawIndexedIndirectCommand> commands;
        commands.reserve(list.ranges.size());
        for (uint32_t i = 0; i < list.ranges.size(); ++i) {
            const DrawItem& d = list.ranges[i];
            // firstInstance carries the draw index (gl_InstanceIndex, or the attribute's row).
            commands.push_back({d.indexCount, 1, d.firstIndex, d.vertexOffset, i});
        }
        b->indirect = upload.add(commands, commandUse, "indirect draws");
        b->commandBytes = sizeof(VkDrawIndexedIndirectCommand);
    }
    if (indirect && key.mode->drawIndexAttribute) {
        std::vector<uint32_t> rows(list.ranges.size());
        for (uint32_t i = 0; i < rows.size(); ++i) rows[i] = i;
        // Mesh shaders have no vertex input: they read the rows by address instead.
        const VkBufferUsageFlags rowUse =
            b->meshlets ? shaderRead : VkBufferUsageFlags(VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        b->drawIndices = upload.add(rows, rowUse, "draw index attribute");
    }

    // Culling reads each draw's box on the GPU where a shader culls (mdi lists, mesh tasks).
    std::vector<gpu::DrawCull> boxes;
    std::vector<uint32_t> pairs;
    const bool gpuCulling = indirect || key.taskCulling;
    const bool runs = indirect && key.technique->drawsClusterRuns();
    const uint32_t bits = gpuCulling ? cullBoxes(scene, sceneGpu, list, runs, boxes, pairs) : 0;
    // Part by part only where cull.comp makes the lists.
    if (!indirect) pairs.clear();
    b->cull = std::make_shared<CullBuffers>(device, upload, boxes, pairs, bits,
                                            indirect ? b->commandBytes : 0, runs,
                                            static_cast<uint32_t>(scene.objects.size()));
    if (!key.mode->indirect) {
        b->objectBoxes.reserve(scene.objects.size());
        for (const scene::Object& o : scene.objects)
            b->objectBoxes.push_back(
                scene::partRangeBounds(scene, sceneGpu.partBounds(), o.geometry, 0,
                                       scene.geometries[o.geometry].partCount));
    }
    keepOnlyWhatFramesRead(b->list, indirect);
    return b;
}

// `push` mode: per draw, push only the span of DrawData fields that differ from the last draw.
// `shown` (null: all) says which objects are drawn.
static Issued pushDraws(const DrawContext& c, const std::vector<uint8_t>* shown) {
    constexpr uint32_t fieldCount = sizeof(gpu::DrawData) / sizeof(uint32_t);
    std::array<uint32_t, fieldCount> last{}; // as pushed, zeroed, at the start of the frame
    const DrawList& list = c.buffers.list;
    const bool mesh = c.buffers.meshlets != nullptr;
    const bool task = c.buffers.key.taskCulling;
    Issued issued;
    // Full detail only: without the cull pass no level is chosen.
    for (size_t i = 0; i < list.fullDetailDraws; ++i) {
        const DrawItem& d = list.ranges[i];
        if (shown && !(*shown)[d.object]) continue;
        std::array<uint32_t, fieldCount> now;
        std::memcpy(now.data(), &list.data[i], sizeof(gpu::DrawData));
        uint32_t first = fieldCount, end = 0;
        for (uint32_t f = 0; f < fieldCount; ++f)
            if (now[f] != last[f]) {
                first = std::min(first, f);
                end = f + 1;
            }
        if (first < end)
            vkCmdPushConstants(c.cmd, c.layout, c.pushStages,
                               gpu::DRAW_PUSH_DRAW_OFFSET + first * sizeof(uint32_t),
                               (end - first) * sizeof(uint32_t), &now[first]);
        last = now;
        if (mesh)
            c.device.meshCommands().draw(
                c.cmd, task ? taskGroups(list.meshletCounts[i]) : list.meshletCounts[i], 1, 1);
        else
            vkCmdDrawIndexed(c.cmd, d.indexCount, 1, d.firstIndex, d.vertexOffset, 0);
        ++issued.draws;
        issued.triangles += d.indexCount / 3;
    }
    return issued;
}

// Pushes the phase the task shader culls by, and the commands it reads its draws from.
static void pushPhase(const DrawContext& c, VkDeviceAddress commands, uint32_t phase) {
    struct {
        uint64_t commandsAddress;
        uint32_t cullPhase;
    } block{commands, phase};
    vkCmdPushConstants(c.cmd, c.layout, c.pushStages, gpu::DRAW_PUSH_CULL_OFFSET, 12, &block);
}

void recordAllDraws(const DrawContext& c) {
    const DrawBuffers& b = c.buffers;
    if (!b.key.mode->indirect) {
        pushDraws(c, nullptr);
        return;
    }
    // Full detail only: without the cull pass no level is chosen. A task shader reads the
    // draw of each command from the commands themselves.
    const uint32_t total = static_cast<uint32_t>(b.list.fullDetailDraws);
    const uint32_t limit = std::max(1u, c.device.info().maxDrawIndirectCount);
    if (b.meshlets && b.key.taskCulling) pushPhase(c, b.indirect.address(), gpu::CULL_PHASE_NONE);
    for (uint32_t first = 0; first < total; first += limit) {
        const uint32_t count = std::min(limit, total - first);
        if (b.meshlets) {
            // gl_DrawID restarts at 0 in every call: each call pushes the index of its first
            // draw (DrawData::drawIndex of the push block) for the shader to add.
            vkCmdPushConstants(c.cmd, c.layout, c.pushStages,
                               gpu::DRAW_PUSH_DRAW_OFFSET + offsetof(gpu::DrawData, drawIndex),
                               sizeof(uint32_t), &first);
            c.device.meshCommands().drawIndirect(c.cmd, b.indirect.handle(),
                                                 VkDeviceSize(first) * b.commandBytes, count,
                                                 b.commandBytes);
        } else {
            vkCmdDrawIndexedIndirect(c.cmd, b.indirect.handle(),
                                     VkDeviceSize(first) * b.commandBytes, count, b.commandBytes);
        }
    }
}

Issued recordPushDraws(const DrawContext& c, const std::vector<uint8_t>& objectShown,
                       uint32_t phase) {
    if (c.buffers.key.taskCulling) pushPhase(c, 0, phase);
    return pushDraws(c, &objectShown);
}

void recordCulledDraws(const DrawContext& c, uint32_t which, uint32_t phase, bool runs) {
    const DrawBuffers& b = c.buffers;
    const CullBuffers& cull = *b.cull;
    const uint32_t maxDraws = cull.listCapacity;
    if (maxDraws == 0) return; // nothing to draw (--visible 0): no commands either
    const VkDeviceSize countOffset = offsetof(gpu::CullStats, draws) + which * sizeof(uint32_t);
    if (b.meshlets) {
        const uint32_t first = 0; // one call: gl_DrawID indexes the whole compacted list
        vkCmdPushConstants(c.cmd, c.layout, c.pushStages,
                           gpu::DRAW_PUSH_DRAW_OFFSET + offsetof(gpu::DrawData, drawIndex),
                           sizeof(uint32_t), &first);
        pushPhase(c, cull.lists[which].address(), phase);
        c.device.meshCommands().drawIndirectCount(c.cmd, cull.lists[which].handle(), 0,
                                                  cull.stats.handle(), countOffset, maxDraws,
                                                  cull.listCommandBytes(false));
    } else {
        // gl_DrawID indexes the list: the techniques that read gl_PrimitiveID find where
        // their run starts (RunCommand::runOffset).
        runs = runs && cull.clusterRuns;
        if (runs) pushPhase(c, cull.lists[which].address(), phase);
        vkCmdDrawIndexedIndirectCount(c.cmd, cull.lists[which].handle(), 0, cull.stats.handle(),
                                      countOffset, maxDraws, cull.listCommandBytes(runs));
    }
}

} // namespace render
