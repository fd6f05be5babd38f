// culling.cpp - culling modes, what each technique and mode gets, the CPU frustum test, and
// recording the cull and depth pyramid passes (see culling.h).
#include "render/culling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "scene/bounds.h"
#include "vk/barrier.h"
#include "vk/check.h"
#include "vk/debug.h"

namespace render {
namespace {

uint32_t groupsOf(uint32_t count, uint32_t size) {
    return (count + size - 1) / size;
}

} // namespace

const std::vector<CullModeEntry>& cullModes() {
    static const std::vector<CullModeEntry> list = {
        {CullMode::Off, "off", "draw every object every frame"},
        {CullMode::Frustum, "frustum", "leave out what lies outside the view frustum"},
        {CullMode::Occlusion, "occlusion",
         "frustum, and two-phase occlusion: what passed the last frame's test first, then "
         "the rest against a depth pyramid of that"},
    };
    return list;
}

const char* cullModeName(CullMode mode) {
    for (const CullModeEntry& e : cullModes())
        if (e.mode == mode) return e.name;
    return "off";
}

const CullModeEntry* findCullMode(const std::string& name) {
    for (const CullModeEntry& e : cullModes())
        if (name == e.name) return &e;
    return nullptr;
}

std::string cullModeNames() {
    std::string text;
    for (const CullModeEntry& e : cullModes())
        text += (text.empty() ? "" : ", ") + std::string(e.name);
    return text;
}

CullPlan cullPlan(const Technique& technique, const DrawMode& mode, CullMode culling, bool levels) {
    CullPlan plan;
    const bool on = culling != CullMode::Off;
    plan.levels = levels && levelsChosenIn(mode);
    plan.gpuLists = mode.indirect && (on || plan.levels);
    plan.clusterRuns = plan.gpuLists && on && technique.drawsClusterRuns();
    plan.cpuFrustum = !mode.indirect && on;
    // Lists written by cull.comp name each mesh draw in a MeshTaskCommand, which the task
    // shader reads, culling or not; the compute rasterizer's task shader chooses each
    // meshlet's rasterizer, culling or not.
    plan.taskShader =
        technique.usesMeshShader() && (on || plan.gpuLists || technique.computeRaster);
    // Push mode draws from the CPU, which does not know what the GPU found occluded; the
    // task shader does, so push mode's mesh draws still get the two phases for meshlets.
    plan.twoPasses = culling == CullMode::Occlusion && (plan.gpuLists || plan.taskShader);
    plan.firstPhase = !on              ? gpu::CULL_PHASE_NONE
                      : plan.twoPasses ? gpu::CULL_PHASE_EARLY
                                       : gpu::CULL_PHASE_FRUSTUM;
    return plan;
}

bool levelsChosenIn(const DrawMode& mode) {
    return mode.indirect;
}

std::string describeCulling(const Technique& technique, const DrawMode& mode, CullMode culling) {
    const std::string levels = levelsChosenIn(mode)
                                   ? "; levels of detail chosen per object on the GPU (--lod-error)"
                                   : "; no levels of detail (they need an mdi mode)";
    if (culling == CullMode::Off) return "none" + levels;
    const bool occlusion = culling == CullMode::Occlusion;
    const bool meshTechnique = technique.usesMeshShader();
    const std::string tests =
        std::string("frustum") + (occlusion ? " and two-phase occlusion" : "") + " per draw";
    std::string text =
        !mode.indirect ? std::string("CPU: frustum per object") +
                             (occlusion && !meshTechnique ? " (occlusion needs an mdi mode)" : "")
        : technique.drawsClusterRuns()
            ? "GPU-built lists of cluster runs: " + tests + ", then per cluster of up to " +
                  std::to_string(gpu::CLUSTER_MAX_TRIANGLES) + " triangles of one part"
            : "GPU-built draw lists: " + tests;
    if (meshTechnique && occlusion && mode.indirect)
        text += "; meshlets: task shader by frustum, then cull pass by frustum and depth pyramid";
    else if (meshTechnique)
        text += std::string("; task shader: meshlets by frustum") +
                (occlusion ? " and depth pyramid" : "");
    return text + levels;
}

bool outsideFrustum(const glm::mat4& viewProj, const glm::mat4& world, glm::vec3 eye,
                    const scene::Bounds& box) {
    // Its infinite corners would make NaNs, which fail every plane's test.
    if (scene::isEmpty(box)) return true;
    // The same inflated box as cull.glsl's viewBox(), in its float arithmetic (geometry
    // coordinates: the box's double values are floats).
    const glm::vec3 boxMin(box.min), boxMax(box.max);
    const glm::vec3 center = (boxMin + boxMax) * 0.5f;
    glm::vec3 half = glm::max((boxMax - boxMin) * 0.5f, glm::vec3(0.0f));
    const glm::vec3 scales(glm::length(glm::vec3(world[0])), glm::length(glm::vec3(world[1])),
                           glm::length(glm::vec3(world[2])));
    const float largest = std::max({scales.x, scales.y, scales.z});
    const float smallest = std::max(std::min({scales.x, scales.y, scales.z}), 1e-30f);
    const float reach = glm::length(glm::vec3(world[3])) + glm::length(eye) +
                        (glm::length(center) + glm::length(half)) * largest;
    half += reach * gpu::CULL_RELATIVE_MARGIN / smallest;
    const glm::mat4 mvp = viewProj * world;
    uint32_t outsideAll = 63;
    for (uint32_t i = 0; i < 8; ++i) {
        const glm::vec3 corner =
            center +
            glm::vec3(i & 1 ? half.x : -half.x, i & 2 ? half.y : -half.y, i & 4 ? half.z : -half.z);
        const glm::vec4 p = mvp * glm::vec4(corner, 1.0f);
        outsideAll &= (p.x < -p.w ? 1u : 0u) | (p.x > p.w ? 2u : 0u) | (p.y < -p.w ? 4u : 0u) |
                      (p.y > p.w ? 8u : 0u) | (p.z < 0.0f ? 16u : 0u) | (p.z > p.w ? 32u : 0u);
    }
    return outsideAll != 0;
}

CullBuffers::CullBuffers(vk::Device& device, vk::UploadBatch& upload,
                         const std::vector<gpu::DrawCull>& cull,
                         const std::vector<uint32_t>& drawOfPair, uint32_t meshletBitCount,
                         uint32_t bytesPerCommand, bool runs, uint32_t objects)
    : drawCount(static_cast<uint32_t>(cull.size())),
      groupCount(groupsOf(static_cast<uint32_t>(cull.size()), gpu::CULL_GROUP_SIZE)),
      commandBytes(bytesPerCommand), pairCount(static_cast<uint32_t>(drawOfPair.size())),
      pairGroupCount(groupsOf(pairCount, gpu::CULL_GROUP_SIZE)),
      // Without a cluster (no triangles) the lists are whole draws, of nothing.
      clusterRuns(runs && pairCount != 0),
      listCapacity(clusterRuns ? std::max(drawCount, pairCount) : drawCount),
      objectCount(clusterRuns ? objects : 0) {
    const VkBufferUsageFlags shader =
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
    // What tests read back (tests/test_cull_history.cpp): the state, the histories and what
    // they are indexed by.
    const VkBufferUsageFlags readable = shader | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    draws = upload.add(cull.empty() ? std::vector<gpu::DrawCull>(1) : cull, readable, "cull boxes");
    pairs = upload.add(drawOfPair.empty() ? std::vector<uint32_t>(1) : drawOfPair, readable,
                       "cull pairs' draws");
    const size_t stateWords = std::max<size_t>(drawCount, 1) + (clusterRuns ? pairCount : 0);
    state = upload.add(std::vector<uint32_t>(stateWords, 0u), readable, "cull state");
    groups = vk::Buffer(device, std::max<VkDeviceSize>(std::max(groupCount, pairGroupCount), 1) * 4,
                        shader, 0, "cull workgroup counts");
    const uint32_t largestCommand = std::max(listCommandBytes(clusterRuns), commandBytes);
    const char* names[2] = {"culled draws (early or only pass)", "culled draws (late pass)"};
    for (int i = 0; i < 2; ++i)
        lists[i] = vk::Buffer(
            device, std::max<VkDeviceSize>(listCapacity, 1) * std::max(largestCommand, 4u),
            shader | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, 0, names[i]);
    stats = vk::Buffer(device, sizeof(gpu::CullStats),
                       shader | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                           VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                       0, "cull counters");
    // Zeros: no history yet, so the first early pass draws nothing and the late pass the
    // rest.
    if (clusterRuns) {
        pairHistory = upload.add(std::vector<uint32_t>(pairCount, 0u), readable, "pair history");
        historyEnds = upload.add(std::vector<uint32_t>(2 * std::max(objectCount, 1u), 0u), readable,
                                 "history ends"); // TRANSFER_DST: the frame's reset
    }
    meshletWords = (meshletBitCount + 31) / 32;
    if (meshletBitCount) {
        meshletHistory =
            upload.add(std::vector<uint32_t>(meshletWords, 0u), readable, "meshlet history");
        lateMeshlets = vk::Buffer(device, VkDeviceSize(meshletWords) * 4, readable, 0,
                                  "meshlets chosen by the late pass");
    }
}

CullPasses::CullPasses(vk::Device& device, const vk::ShaderCompiler& compiler,
                       const DiskPipelineCache& cache)
    : device_(device) {
    cull_ = createComputePipeline(device, compiler, cache, "cull.comp", sizeof(gpu::CullPush),
                                  VK_NULL_HANDLE, "cull draws");
    depthLayout_ = pushDescriptorLayout(device, {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                        "depth pyramid input");
    sampler_ = texelFetchSampler(device, "depth pyramid sampler");
    for (int msaa = 0; msaa < 2; ++msaa)
        pyramid_[msaa] = createComputePipeline(device, compiler, cache, "depth_pyramid.comp",
                                               sizeof(gpu::PyramidPush), depthLayout_.get(),
                                               msaa ? "depth pyramid (MSAA)" : "depth pyramid",
                                               {{"IDV_PYRAMID_MSAA", msaa ? "1" : "0"}});
}

namespace {

// The steps of one pass over a list: its row of shared_cull.h's table, in the steps' order.
std::vector<uint32_t> cullSteps(const CullPlan& plan, uint32_t phase, bool mesh, bool runs) {
    const gpu::CullPhase& row = gpu::CULL_PHASES[phase];
    uint32_t bits = runs ? row.runs : mesh ? row.meshDraws : row.vertexDraws;
    if (!plan.levels) bits &= ~gpu::CULL_L;
    std::vector<uint32_t> steps;
    steps.reserve(5); // the most a pass takes
    for (uint32_t step = 0; bits >> step; ++step)
        if (bits >> step & 1u) steps.push_back(step);
    return steps;
}

bool overPairs(uint32_t step) {
    return (gpu::CULL_STEPS_OVER_PAIRS >> step & 1u) != 0;
}

} // namespace

void CullPasses::recordHistoryReset(VkCommandBuffer cmd, const CullBuffers& buffers,
                                    HistorySlot slot) {
    if (!buffers.clusterRuns || buffers.objectCount == 0) return;
    const VkDeviceSize bytes = VkDeviceSize(buffers.objectCount) * 4;
    vkCmdFillBuffer(cmd, buffers.historyEnds.handle(), slot.late() * bytes, bytes, 0);
}

void CullPasses::recordCull(VkCommandBuffer cmd, const CullBuffers& buffers,
                            const CullInputs& inputs, const CullPlan& plan, uint32_t phase,
                            HistorySlot slot) const {
    const bool late = (gpu::CULL_PHASES[phase].pass & gpu::CULL_PASS_LATE) != 0;
    vk::CmdLabel label(device_.debug(), cmd, late ? "cull draws (late)" : "cull draws");
    // Earlier reads of what this pass writes (the last frame's draws of these lists, the
    // early pass's state) are done; the counters' reset and earlier passes' writes are seen.
    const VkPipelineStageFlags before = VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT |
                                        VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT |
                                        VK_PIPELINE_STAGE_TRANSFER_BIT;
    vk::memoryBarrier(cmd, before | VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT,
                      VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    const bool mesh = plan.taskShader;
    const bool runs = plan.clusterRuns && buffers.clusterRuns;
    gpu::CullPush push{};
    push.frameAddress = inputs.frame;
    push.drawsAddress = inputs.draws;
    push.cullAddress = buffers.draws.address();
    push.sourceAddress = inputs.source;
    push.pairsAddress = buffers.pairs.address();
    push.clusterBoxesAddress = inputs.clusterBoxes;
    push.pairCount = buffers.pairCount;
    if (runs) {
        push.pairHistoryAddress = buffers.pairHistory.address();
        push.historyEndsAddress = buffers.historyEndsAddress(late ? slot.late() : slot.early);
    }
    push.targetAddress = buffers.lists[late ? 1 : 0].address();
    push.stateAddress = buffers.state.address();
    push.groupsAddress = buffers.groups.address();
    push.statsAddress = buffers.stats.address();
    push.drawCount = buffers.drawCount;
    push.phase = phase;
    push.commandWords = buffers.commandBytes / 4;
    push.flags = (mesh ? gpu::CULL_MESH_DRAWS : 0u) | (runs ? gpu::CULL_CLUSTER_RUNS : 0u);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, cull_.pipeline.get());
    const std::vector<uint32_t> steps = cullSteps(plan, phase, mesh, runs);
    for (uint32_t step : steps) {
        push.step = step;
        vkCmdPushConstants(cmd, cull_.layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push,
                           &push);
        if (const uint32_t groups = overPairs(step) ? buffers.pairGroupCount : buffers.groupCount)
            vkCmdDispatch(cmd, groups, 1, 1);
        // Each step reads what the one before wrote.
        if (step != steps.back())
            vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                              VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                              VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    }
    // The draws read the commands and the count; the task shader the state.
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                      VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT |
                          VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                      VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_SHADER_READ_BIT);
}

void CullPasses::recordPyramid(VkCommandBuffer cmd, const SceneTargets& targets,
                               VkDeviceAddress rasterSamples) const {
    vk::CmdLabel label(device_.debug(), cmd, "depth pyramid");
    const gpu::PyramidHeader& header = targets.pyramidHeader();
    // Earlier readers of the pyramid (the last frame's late pass, in the cull and the task
    // shader) are done before it is rewritten. Its header was written with the targets.
    vk::memoryBarrier(cmd,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT,
                      VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    const bool msaa = targets.pass().samples() != VK_SAMPLE_COUNT_1_BIT;
    const ComputePipeline& pass = pyramid_[msaa ? 1 : 0];
    bindWithImage(
        device_, cmd, pass, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
        {sampler_.get(), targets.depth().view(), VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL});
    gpu::PyramidPush push{};
    push.pyramidAddress = targets.pyramid().address();
    push.extent = {targets.extent().width, targets.extent().height};
    push.samples = uint32_t(targets.pass().samples());
    push.rasterSamplesAddress = rasterSamples;
    for (uint32_t level = 0; level < header.levels; level += gpu::PYRAMID_LEVELS_PER_PASS) {
        push.level = level;
        vkCmdPushConstants(cmd, pass.layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push,
                           &push);
        vkCmdDispatch(cmd, groupsOf(header.level[level].width, gpu::PYRAMID_GROUP),
                      groupsOf(header.level[level].height, gpu::PYRAMID_GROUP), 1);
        // The next pass reads this one's last level; after the last, the cull and task
        // shaders read them all.
        vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                          VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT,
                          VK_ACCESS_SHADER_READ_BIT);
    }
}

} // namespace render
