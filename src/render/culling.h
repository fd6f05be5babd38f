// culling.h - drawing only what can show, with images unchanged. shaders/shared_cull.h holds
// the design as one table (phases, steps, state bits, history); this header records it.
//
// In the mdi modes a compute pass (shaders/cull.comp) writes each frame's indirect draws and
// their count: runs of clusters (up to 64 triangles of one part) for the vertex pipelines,
// whole draws for the mesh techniques, whose task shader (shaders/scene.task) culls meshlets;
// in push mode the CPU skips objects outside the view frustum. Occlusion culling is
// two-phase: the first half of the scene pass draws what passed the last frame's test (the
// history of every cluster and meshlet), a depth pyramid is built from that depth (the
// farthest sample of every pixel), and the second half draws the rest that the pyramid does
// not hide, testing again what the first half drew so that the history follows the view.
// Every technique culls alike, the floors included. Levels of detail are a step of the same
// pass wherever it lists the draws (mdi modes, culling on or off). Every test is
// conservative and each list keeps the draw order, so the ID and colour images are byte for
// byte those drawn without culling, but for one case: where two surfaces tie exactly in
// depth, the one drawn first wins, and the halves can change which that is. An object's
// clusters keep their order (its early clusters are its first ones), so ties between parts
// of one object are safe; a tie between two objects, or two meshlets of one draw, that one
// of them has just come into view for can still go the other way (docs/benchmarks.md says
// how often it was seen).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/pipeline.h"
#include "render/settings.h"
#include "render/targets.h"
#include "scene/scene.h"
#include "shared.h"
#include "vk/resources.h"
#include "vk/upload.h"

namespace render {

struct CullModeEntry {
    CullMode mode;
    const char* name;
    const char* description;
};
const std::vector<CullModeEntry>& cullModes();
const char* cullModeName(CullMode mode);
const CullModeEntry* findCullMode(const std::string& name);
std::string cullModeNames(); // "off, frustum, occlusion"

// What a technique in a per-draw mode gets of a culling mode, with levels of detail on or not.
struct CullPlan {
    // cull.comp writes the indirect draws: the mdi modes with culling or levels on.
    bool gpuLists = false;
    bool clusterRuns = false; // those lists are runs of clusters (vertex pipelines, culling on)
    bool levels = false;      // its levels step chooses each object's level of detail
    bool cpuFrustum = false;  // push mode with culling: the CPU skips objects out of view
    bool taskShader = false;  // mesh techniques: scene.task culls meshlets, or names the draw
    bool twoPasses = false;   // occlusion: early half, depth pyramid, late half
    uint32_t firstPhase = gpu::CULL_PHASE_NONE; // CULL_PHASE_* of the (first) pass
    bool culls() const { return firstPhase != gpu::CULL_PHASE_NONE; }
    // The draws are not all issued as the list holds them: the GPU lists them or the CPU
    // leaves objects out.
    bool on() const { return gpuLists || cpuFrustum; }
};
CullPlan cullPlan(const Technique& technique, const DrawMode& mode, CullMode culling,
                  bool levels = false);
// Whether levels of detail can be chosen in `mode`: only where cull.comp lists the draws.
bool levelsChosenIn(const DrawMode& mode);
// One line on what `technique` in `mode` gets with `culling`, for --list-renderers, the panel
// and the benchmark ("GPU-built draw lists: frustum and two-phase occlusion per draw, ...").
std::string describeCulling(const Technique& technique, const DrawMode& mode, CullMode culling);

// The CPU's frustum test of push mode: whether `box` (in the coordinates `world` places)
// lies outside the view frustum with the margins cull.glsl uses (CULL_RELATIVE_MARGIN). An
// empty box (scene::isEmpty: an object without triangles) always does.
bool outsideFrustum(const glm::mat4& viewProj, const glm::mat4& world, glm::vec3 eye,
                    const scene::Bounds& box);

// The culling state of one draw list on the GPU, shared by the frames in flight (the queue
// orders them, barriers keep their accesses apart): the boxes, per-draw state and counts,
// the two passes' compacted commands, the counters, and the histories, each in a buffer of
// its own with one writer per pass (shared_cull.h's History). Made with the draw list; nothing
// in it changes on the CPU afterwards.
struct CullBuffers {
    CullBuffers(vk::Device& device, vk::UploadBatch& upload,
                const std::vector<gpu::DrawCull>& draws, const std::vector<uint32_t>& pairs,
                uint32_t meshletBits, uint32_t commandBytes, bool clusterRuns,
                uint32_t objectCount);
    uint32_t drawCount = 0, groupCount = 0, commandBytes = 0;
    uint32_t pairCount = 0, pairGroupCount = 0; // (draw, cluster) or (draw, meshlet) pairs
    // The vertex pipelines' draws have a (draw, cluster) pair per cluster, and a list holds up
    // to a command per pair: with culling on their lists are runs of clusters
    // (CULL_CLUSTER_RUNS); with culling off (levels alone) whole draws.
    bool clusterRuns = false;
    uint32_t listCapacity = 0; // commands a list can hold
    vk::Buffer draws;          // gpu::DrawCull[]
    vk::Buffer pairs;          // uint per pair: its draw
    // uint per draw: CULL_* bits; for runs then per pair CULL_PAIR_* bits. A frame's own.
    vk::Buffer state;
    vk::Buffer groups;   // uint per cull.comp workgroup
    vk::Buffer lists[2]; // the early (or only) and the late pass's commands
    vk::Buffer stats;    // gpu::CullStats; draws[] are the indirect draw counts
    // The histories. Runs: a uint per pair (1: it has history), and the two slots of history
    // ends, a uint per object each. Mesh draws: a bit per meshlet; next to it, not a history,
    // the bits of the meshlets the late pass chose (FrameData::lateMeshletsAddress).
    vk::Buffer pairHistory, historyEnds;
    vk::Buffer meshletHistory, lateMeshlets;
    uint32_t meshletWords = 0; // of either meshlet bitset; 0 without meshlets
    uint32_t objectCount = 0;  // runs: the objects, a history end each per slot
    VkDeviceAddress historyEndsAddress(uint32_t slot) const {
        return historyEnds.address() + VkDeviceSize(slot) * objectCount * 4;
    }
    // The bytes of one command of a list: RunCommand for runs, else the draw list's own.
    uint32_t listCommandBytes(bool runs) const {
        return runs ? uint32_t(sizeof(gpu::RunCommand)) : commandBytes;
    }
};

// Which slot of the history ends the early pass reads; the late pass writes the other, and
// the frame zeroes that one before its first pass (Renderer flips the slot after a frame with
// a late pass).
struct HistorySlot {
    uint32_t early = 0;
    uint32_t late() const { return 1 - early; }
};

// The compute pipelines: the cull and the depth pyramid.
class CullPasses {
  public:
    CullPasses(vk::Device& device, const vk::ShaderCompiler& compiler,
               const DiskPipelineCache& cache);

    // One pass of cull.comp over the whole list, the steps shared_cull.h's table gives for
    // `phase` and the list (the levels step first where `plan.levels`), into
    // buffers.lists[phase == LATE]. `draws` and `source` are the list's DrawData and commands,
    // `clusterBoxes` the scene's (SceneGpu::clusterBoxesAddress).
    struct CullInputs {
        VkDeviceAddress frame, draws, source, clusterBoxes;
    };
    void recordCull(VkCommandBuffer cmd, const CullBuffers& buffers, const CullInputs& inputs,
                    const CullPlan& plan, uint32_t phase, HistorySlot slot) const;
    // Before the frame's first pass, with the counters' reset: zeroes the slot of history
    // ends the late pass will write, where one runs.
    static void recordHistoryReset(VkCommandBuffer cmd, const CullBuffers& buffers,
                                   HistorySlot slot);
    // The pyramid of `targets` from their depth, left in DEPTH_STENCIL_READ_ONLY_OPTIMAL by
    // the first half of the pass (its header is the targets'), and from the compute
    // rasterizer's samples at `rasterSamples` where that is not 0 (compute_raster.h).
    void recordPyramid(VkCommandBuffer cmd, const SceneTargets& targets,
                       VkDeviceAddress rasterSamples = 0) const;

  private:
    vk::Device& device_;
    ComputePipeline cull_;
    vk::Handle<VkDescriptorSetLayout> depthLayout_;
    vk::Handle<VkSampler> sampler_;
    ComputePipeline pyramid_[2]; // single-sampled depth, multisampled depth
};

} // namespace render
