// culling.h - drawing only what can show, with images unchanged (shaders/cull.glsl).
//
// In the mdi modes a compute pass (shaders/cull.comp) writes each frame's indirect draws and
// their count from every draw's box; the mesh techniques' task shader (shaders/scene.task)
// culls meshlets; in push mode the CPU skips objects outside the view frustum. Occlusion
// culling is two-phase: the first half of the scene pass draws what the last ID image showed
// (the visible-part pass over it names exactly those parts; with MSAA those of every sample,
// not only of the resolved sample 0), a depth pyramid is built from
// that depth (the farthest sample of every pixel), and the second half draws the rest that
// the pyramid does not hide. The vertex pipelines' lists (Technique::drawsClusterRuns) hold
// just the runs of clusters (up to 64 triangles of one part) that passed, an object's first
// clusters first (CULL_CLUSTER_RUNS); a technique that reads gl_PrimitiveID adds the run's
// offset in its draw (PipelineKey::runOffsets). The mesh techniques' lists are whole draws,
// and their task shader culls meshlets. Every test is conservative and each list keeps the
// draw order, so the ID and colour images are byte for byte those drawn without culling,
// but for one case: where two surfaces tie exactly in
// depth, the one drawn first wins, and the halves can change which that is. An object's
// draws keep their order (every draw of an object up to the last one with a part the last
// image showed goes first), so ties between parts of one object are safe; a tie
// between two objects, or two meshlets of one draw, that one of them has just come into
// view for can still go the other way (docs/benchmarks.md says how often it was seen).
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

// What a technique in a per-draw mode gets of a culling mode.
struct CullPlan {
    bool gpuLists = false;   // cull.comp writes the indirect draws (mdi modes)
    bool cpuFrustum = false; // push mode: the CPU skips objects outside the frustum
    bool taskShader = false; // mesh techniques: scene.task culls meshlets
    bool twoPasses = false;  // occlusion: early half, depth pyramid, late half
    bool on() const { return gpuLists || cpuFrustum; }
};
CullPlan cullPlan(const Technique& technique, const DrawMode& mode, CullMode culling);
// One line on what `technique` in `mode` gets with `culling`, for --list-renderers, the panel
// and the benchmark ("GPU-built draw lists: frustum and two-phase occlusion per draw, ...").
std::string describeCulling(const Technique& technique, const DrawMode& mode, CullMode culling);

// The CPU's frustum test of push mode: whether `box` (in the coordinates `world` places)
// lies outside the view frustum with the margins cull.glsl uses.
bool outsideFrustum(const glm::mat4& viewProj, const glm::mat4& world, glm::vec3 eye,
                    const scene::Bounds& box);

// The culling state of one draw list on the GPU, shared by the frames in flight (the queue
// orders them, barriers keep their accesses apart): the boxes, per-draw state and counts,
// the two passes' compacted commands, the counters, and the meshlet bits.
struct CullBuffers {
    CullBuffers(vk::Device& device, vk::UploadBatch& upload,
                const std::vector<gpu::DrawCull>& draws, const std::vector<uint32_t>& pairs,
                uint32_t meshletBits, uint32_t commandBytes, bool clusterRuns,
                uint32_t objectCount);
    uint32_t drawCount = 0, groupCount = 0, commandBytes = 0;
    uint32_t pairCount = 0, pairGroupCount = 0; // (draw, cluster) or (draw, meshlet) pairs
    // The lists are runs of clusters (CULL_CLUSTER_RUNS): every draw has its pairs, and a
    // list holds up to a command per pair.
    bool clusterRuns = false;
    uint32_t listCommandBytes = 0; // commandBytes, or gpu::RunCommand's for cluster runs
    uint32_t listCapacity = 0;     // commands a list can hold
    vk::Buffer draws;              // gpu::DrawCull[]
    vk::Buffer pairs; // uint per (draw, cluster) pair of draws of several clusters: the draw
    // uint per draw: CULL_* bits; with cluster runs then per pair CULL_PAIR_* bits and per
    // object where its history ends (cull.comp)
    vk::Buffer state;
    vk::Buffer groups;      // uint per cull.comp workgroup
    vk::Buffer lists[2];    // the early (or only) and the late pass's commands
    vk::Buffer stats;       // gpu::CullStats; draws[] are the indirect draw counts
    vk::Buffer meshletBits; // uint words, empty without meshlets; as many drawn late, drawn early
    uint32_t meshletWords = 0;
    vk::Buffer dispatches; // gpu::CullDispatches: the late phase's, which it may skip
    // CPU side, changed while recording: whether the lists were ever written (a frozen list
    // needs one culled frame first), push mode's objects shown by the last culled frame, and
    // what placed the last frame culled in two passes (FRAME_VIEW_UNCHANGED when it recurs).
    bool culled = false;
    std::vector<uint8_t> frozenObjects;
    struct View {
        glm::mat4 viewProj;
        glm::dvec3 origin; // what viewProj and the objects' matrices are relative to
        float explode;
        uint64_t hiddenVersion;
        uint32_t width, height, samples; // of the targets
        float lodErrorPixels;            // which levels of detail are drawn
        scene::Section section;          // a cut shows what the view hid before
        bool operator==(const View&) const = default;
    };
    std::optional<View> lastView;
    // Frames culled in a row with FRAME_VIEW_UNCHANGED, how many frames have drawn the lists
    // of the last of them again since these buffers were made, and whether the last frame
    // did (Renderer::planFrame).
    uint32_t stillCulls = 0;
    uint64_t reusedFrames = 0;
    bool lastReused = false;
    uint32_t objectCount = 0; // cluster runs: the objects the state buffer has a word for
};

// The compute pipelines: the cull and the depth pyramid.
class CullPasses {
  public:
    CullPasses(vk::Device& device, const vk::ShaderCompiler& compiler,
               const DiskPipelineCache& cache);

    // One pass of cull.comp over the whole list: decide (then, in the frustum and late
    // phases, test the draws of several clusters cluster by cluster and count again), then
    // compact into buffers.lists[phase == LATE]. `draws` and `source` are the list's DrawData
    // and commands, `clusterBoxes` the scene's (SceneGpu::clusterBoxesAddress).
    // With `indirect`, the late pass dispatches by buffers.dispatches, which the early pass
    // empties when it leaves the late pass nothing to test.
    struct CullInputs {
        VkDeviceAddress frame, draws, source, clusterBoxes;
    };
    void recordCull(VkCommandBuffer cmd, const CullBuffers& buffers, const CullInputs& inputs,
                    uint32_t phase, bool meshDraws, bool indirect) const;
    // The pyramid of `targets` from their depth, left in DEPTH_STENCIL_READ_ONLY_OPTIMAL by
    // the first half of the pass (its header is the targets'). `dispatches`, if given, holds
    // its passes' sizes (recordCull may have emptied them).
    void recordPyramid(VkCommandBuffer cmd, const SceneTargets& targets,
                       const vk::Buffer* dispatches) const;
    // What buffers.dispatches holds before the early cull, for these targets.
    static gpu::CullDispatches fullDispatches(const SceneTargets& targets,
                                              const CullBuffers& buffers);

  private:
    vk::Device& device_;
    ComputePipeline cull_;
    vk::Handle<VkDescriptorSetLayout> depthLayout_;
    vk::Handle<VkSampler> sampler_;
    ComputePipeline pyramid_[2]; // single-sampled depth, multisampled depth
};

} // namespace render
