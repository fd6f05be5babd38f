// renderer.h - draws a scene into the scene pass as RenderSettings say. Pipelines come from a
// cache; draw lists, ID, per-draw and indirect buffers are built when the scene or what
// selects them changes, never per frame; record() only writes commands. A switch never waits
// for the GPU: what frames in flight still use stays alive in their slots.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>

#include <glm/glm.hpp>

#include "render/animator.h"
#include "render/clear_choice.h"
#include "render/compute_raster.h"
#include "render/culling.h"
#include "render/draw_buffers.h"
#include "render/draw_list.h"
#include "render/frame_slots.h"
#include "render/id_passes.h"
#include "render/pipeline_cache.h"
#include "render/primitive_buffers.h"
#include "render/resolve.h"
#include "render/scene_gpu.h"
#include "render/settings.h"
#include "render/targets.h"
#include "render/visibility.h"
#include "render/xray.h"
#include "vk/shader_compiler.h"

namespace render {

// What changes every frame (the settings do not).
// Everything the GPU gets is relative to `origin`, a point at the eye (render::eyeRelative):
// a model placed kilometres from the world's origin is drawn with the precision it has there.
struct FrameParams {
    glm::dvec3 origin{0.0};        // world coordinates; the objects' matrices are relative to it
    glm::mat4 viewProj{1.0f};      // from coordinates relative to `origin` to clip space
    glm::dmat4 worldViewProj{1.0}; // the same from world coordinates: the CPU's (measure, picks)
    glm::vec3 eye{0.0f};           // the camera's position relative to `origin`
    // Orthographic: the unit direction toward the viewer, the same at every point; none in
    // perspective, where it runs from each point to the eye (FrameData::eyePosition).
    std::optional<glm::vec3> orthoToViewer;
    float time = 0.0f; // seconds; drives the blink of the hovered part (render/blink.h)
    // The pixel (top-left origin) whose nearest part this frame picks, and hovers: the scene
    // pass's pick reaches FrameSlots::latestPick(), the composition's read of the ID image
    // FrameSlots::latestHover(), and the part there is highlighted in this frame's picture.
    std::optional<glm::uvec2> pickPixel;
    // Rectangles whose unique parts this frame collects from its ID image (box selection,
    // the visible parts); the result reaches FrameSlots::latestPartSets().
    std::vector<PartSetQuery> partSets;
    float explode = 0.0f; // exploded view, 0 (at rest) to 1; see render/animator.h
    // FrameSlots::latestHoveredTiles(): once the tiles of the last whole composition are
    // known, a step of the blink composes only them (Renderer::recordComposition).
    std::optional<HoveredTiles> hoveredTiles;

    // Takes the camera's part of `view` (a frame made by the camera, e.g. app::cameraFrame):
    // the origin, both matrices, the eye and the orthographic direction.
    void setView(const FrameParams& view) {
        origin = view.origin;
        viewProj = view.viewProj;
        worldViewProj = view.worldViewProj;
        eye = view.eye;
        orthoToViewer = view.orthoToViewer;
    }
};

// What the culling of a configuration leaves out, per frame (FrameSlots::cullStats() holds
// the GPU's counters; countsOf reads them).
struct CullCounts {
    uint64_t draws = 0;     // draws drawn (objects; parts for per-draw, batches for search)
    uint64_t meshlets = 0;  // meshlets drawn (mesh techniques)
    uint64_t triangles = 0; // triangles drawn
    // of which at each level of detail (full detail first)
    std::array<uint64_t, gpu::LOD_MAX_LEVELS> levelTriangles{};
    uint64_t computeTriangles = 0; // of which the compute rasterizer drew (visbuffer-compute)
};
CullCounts countsOf(const gpu::CullStats& stats, bool meshTechnique);

// How the last configure() or setScene() went, for the panel.
struct SwitchReport {
    double ms = 0.0;             // on the CPU, from the call to its return
    bool pipelineCached = false; // the pipeline came from the cache
    bool drawsKept = false;      // the draw list and its buffers were still right
};

class Renderer {
  public:
    // `pipelineCacheFolder`: where the driver's pipeline cache is kept between runs (empty:
    // in memory only); see render/disk_pipeline_cache.h.
    Renderer(vk::Device& device, const vk::ShaderCompiler& compiler,
             const std::filesystem::path& pipelineCacheFolder = {});

    // The scene pass for `msaa` samples per pixel, made on first use (the targets the
    // frames render into are made with it). Throws vk::Error naming the counts the device
    // offers when it has no such mode.
    const ScenePass& pass(uint32_t msaa);

    // Uploads `scene` and builds what `settings` needs for it: one staging submit for all of
    // it. A failure (thrown) leaves the previous scene and configuration drawing.
    void setScene(const scene::Scene& scene, const RenderSettings& settings);
    // What `settings` needs for the scene last set (passed again, as the renderer keeps no
    // copy): the pipeline from the cache (built on a miss), the draw list only if what it
    // depends on changed. A compile error throws vk::ShaderError; a failure leaves the
    // previous configuration drawing.
    void configure(const scene::Scene& scene, const RenderSettings& settings);
    // The non-blocking path (the viewer, which keeps drawing meanwhile): whether configure()
    // with these arguments would find its pipeline (and X-ray's, while on) built. nullopt: it
    // would, and costs no compile; else the build it needs, started on a worker unless it runs
    // already (ask again, a frame later: the newest wish is the one asked for). Throws what
    // configure() would refuse, and once the error of a build that failed (the next ask starts
    // it again).
    std::optional<PipelineBuild> prepare(const scene::Scene& scene, const RenderSettings& settings);
    // The same for setHidden(hidden), which switches to the variant that discards hidden parts
    // (or back) when `hidden` is the first set hidden (or the last shown).
    std::optional<PipelineBuild> prepareHidden(const scene::PartSet& hidden);
    // Whether a pipeline is being built on a worker (or done and not collected yet by
    // prepare, configure or collectBuilds).
    bool building() const { return pipelines_.building(); }
    // Takes in the builds done (PipelineCache::collect), those nobody waits for any more too.
    void collectBuilds() { pipelines_.collect(); }
    // Called on the worker when a build is done (glfwPostEmptyEvent wakes the viewer's wait).
    void onPipelineBuilt(std::function<void()> wake) { pipelines_.onBuilt(std::move(wake)); }
    // For tests: builds started while held wait until released (PipelineCache::holdBuilds).
    void holdPipelineBuilds(bool hold) { pipelines_.holdBuilds(hold); }

    // The parts drawn with the selection's highlight (and outline, with edges), and the parts
    // not drawn at all: never in the ID image, never picked, a pick finds what is behind them.
    // Sets over the scene last set (setScene empties both). Each is uploaded once, without
    // waiting; while any part is hidden the pipeline is the variant that discards them
    // (built on first use, cached like the others), so with nothing hidden nothing changes.
    void setSelection(const scene::PartSet& selected);
    void setHidden(const scene::PartSet& hidden);
    // Per unique part of the scene last set, a display-encoded RGBA8 (glm::packUnorm4x8) the
    // composition mixes its pixels towards by the alpha; 0 leaves a part as it is, and an
    // empty vector turns the tint off (setScene does too). The colour image alone changes:
    // IDs, picks and counts never do. Uploaded once, without waiting.
    void setTint(const std::vector<uint32_t>& rgba);
    const scene::PartSet& hidden() const { return hiddenSet_; }
    // X-ray's translucent parts (render/xray.h, xrayParts): drawn over the picture after the
    // scene pass's draws, never in the ID image, the depth or a pick; hide them with
    // setHidden too. Over the scene last set (setScene empties it); the first non-empty set
    // builds X-ray's pipeline (once per MSAA setting and section variant, then cached).
    void setTranslucent(const scene::Scene& scene, const scene::PartSet& parts);

    // Forgets every cached pipeline and SPIR-V (shaders edited on disk) and rebuilds the
    // current pipeline and the compute passes. A compile error throws vk::ShaderError and the
    // last good pipeline keeps drawing.
    void reloadShaders();

    // Records the scene pass, with timestamps around only it, into the slot's command
    // buffer; the slot keeps what the commands use, `targets` included. They must be made
    // with pass(settings().pipeline.msaa).
    void record(FrameSlot& slot, const std::shared_ptr<const SceneTargets>& targets,
                const FrameParams& params);

    // Composes the picture again from the images the last scene pass left in `targets`
    // (recorded before in submission order, with the settings drawn then): the hovered part
    // at params.pickPixel, the selection and edges as they are now, and params.partSets. No
    // scene pass, pick, culling or timestamps: what a viewer at rest records. When only the
    // blink's weight (params.time) changed since the last composition into `targets` and
    // params.hoveredTiles holds what the last whole one found, only those are composed again.
    void recordComposition(FrameSlot& slot, const std::shared_ptr<const SceneTargets>& targets,
                           const FrameParams& params);
    // The tiles the last composition made again; nullopt: it made the whole picture.
    const std::optional<HoveredTiles>& lastComposedTiles() const { return lastTiles_; }

    const RenderSettings& settings() const { return settings_; }
    // The clear path the configured frames draw with (never Auto): RenderSettings::clear, or
    // with Auto the faster of the two on this device (render/clear_choice.h).
    ClearPath clearPath() const { return clearPath_; }
    // What timing the paths found for `msaa` samples, once Auto has needed them (timed in this
    // run, or read from the file beside the pipeline cache); nullopt before.
    std::optional<ClearTiming> clearTiming(uint32_t msaa) const;
    // Counts the calls that may change what the scene pass draws beyond settings(): a scene
    // set, a configuration applied, hidden parts, shaders reloaded (app/viewer/pacer.h).
    uint64_t changes() const { return changes_; }
    const RenderStats& stats() const { return stats_; }
    const SwitchReport& lastSwitch() const { return lastSwitch_; }
    size_t cachedPipelines() const { return pipelines_.size(); }
    // The driver's pipeline cache: its status and save() at exit.
    const DiskPipelineCache& driverCache() const { return pipelines_.driverCache(); }
    VkPipeline pipeline() const { return pipeline_ ? pipeline_->handle.get() : VK_NULL_HANDLE; }
    // describePipeline() of the pipeline drawn ("" before setScene).
    std::string pipelineName() const { return pipeline_ ? describePipeline(pipeline_->key) : ""; }

    // What culling the drawn configuration gets (cullPlan of its technique and mode).
    CullPlan cullingPlan() const;
    // The totals the culling counters are measured against: draws, meshlets, triangles.
    CullCounts cullTotals() const;
    // The drawn list on the GPU, and the slot of history ends the last late pass wrote: for
    // tests that read the culling state back (tests/test_cull_history.cpp).
    const DrawBuffers* drawBuffers() const { return draws_.get(); }
    HistorySlot historySlot() const { return historySlot_; }

  private:
    // One frame's culling as recorded (frame_steps.cpp's steps read it).
    struct FrameCulling {
        CullPlan plan;
        bool frozen = false;              // drawing the lists of the last culled frame
        bool viewUnchanged = false;       // FRAME_VIEW_UNCHANGED
        HistorySlot history;              // the history ends the passes use
        std::vector<uint8_t> objectShown; // push mode: the CPU's frustum test per object
        Issued issued;                    // push mode: the first pass's draws
    };
    void apply(const scene::Scene& scene, const RenderSettings& settings, bool newScene);
    // The effective key `settings` select; throws for what this device or scene cannot draw.
    PipelineKey keyFor(const scene::Scene& scene, const RenderSettings& settings, bool newScene);
    // `wanted`, or for Auto the faster path at `msaa` samples: timed on first need, or read
    // from the file beside the pipeline cache (clear_timer.cpp). The visibility buffer always
    // takes the compute path: its shading pass writes the background.
    ClearPath clearPathFor(ClearPath wanted, uint32_t msaa, const Technique& technique);
    // The drawn pipeline's key with parts hidden or not.
    PipelineKey hidingKey(bool hiding) const;
    void bindGeometry(VkCommandBuffer cmd) const;
    bool drawsStillRight(const PipelineKey& key, const DrawSettings& draws, bool levels) const;
    gpu::FrameData frameData(const SceneTargets& targets, const FrameParams& params,
                             const FrameCulling& culling) const;
    // This frame's culling; remembers what freezing needs (the lists culled, push mode's
    // objects shown).
    FrameCulling planFrame(const FrameParams& params, const SceneTargets& targets);
    void beginPass(VkCommandBuffer cmd, const SceneTargets& targets, PassPart part,
                   VkDeviceAddress frame, bool clearColor) const;
    void drawPhase(VkCommandBuffer cmd, FrameCulling& culling, uint32_t phase) const;
    void recordScene(FrameSlot& slot, const SceneTargets& targets, FrameCulling& culling) const;
    void recordCounters(VkCommandBuffer cmd, const FrameCulling& culling, bool before) const;
    void recordTranslucent(VkCommandBuffer cmd) const;
    // The compute rasterizer's pass over the lists of `first` to `last` (0: the early or only
    // pass's, 1: the late one's), where the technique has one.
    void recordComputeRaster(VkCommandBuffer cmd, VkDeviceAddress frame,
                             const SceneTargets& targets, uint32_t first, uint32_t last) const;
    VkDeviceAddress rasterSamplesAddress() const;
    // The visibility buffer's shading pass: the frame's and the draw list's addresses.
    gpu::VisibilityPush visibilityPush(VkDeviceAddress frame, bool xray) const;
    void recordPickReset(VkCommandBuffer cmd) const;
    void recordPickCopies(VkCommandBuffer cmd, const FrameSlot& slot) const;
    void recordIdPasses(VkCommandBuffer cmd, FrameSlot& slot, const SceneTargets& targets,
                        const FrameParams& params);

    vk::Device& device_;
    const vk::ShaderCompiler& compiler_;
    VkShaderStageFlags pushStages_;
    std::map<uint32_t, std::unique_ptr<ScenePass>> passes_; // by sample count
    PipelineCache pipelines_;
    std::shared_ptr<const Animator> animator_;
    std::shared_ptr<const IdPasses> idPasses_;
    std::shared_ptr<const CullPasses> culler_;
    std::shared_ptr<const Resolver> resolver_;
    std::shared_ptr<const VisibilityShading> visibility_;
    std::shared_ptr<const ComputeRaster> raster_;
    // The compute rasterizer's 64-bit samples for the targets last drawn (compute_raster.h);
    // kept by the frames that write and read them.
    std::shared_ptr<vk::Buffer> rasterSamples_;
    // gpu::PickData, shared by all frames in flight (ordered by barriers).
    std::shared_ptr<const vk::Buffer> pick_;

    // The configuration drawn, each piece kept alive by the frames that record with it.
    RenderSettings settings_;
    std::shared_ptr<const Pipeline> pipeline_;
    std::shared_ptr<SceneGpu> sceneGpu_;
    // The scene's derived geometry, made the first time a technique draws it.
    std::shared_ptr<const PartVertexBuffers> partVertices_;
    std::shared_ptr<const MeshletBuffers> meshlets_;
    std::shared_ptr<const DrawBuffers> draws_;
    // The selection and hidden parts as the GPU reads them (bitsets, see scene/part_set.h).
    std::shared_ptr<const vk::Buffer> selected_, hidden_;
    std::shared_ptr<const vk::Buffer> tint_; // setTint's colours; null: no tint
    scene::PartSet hiddenSet_;
    // X-ray's pass: its draws (none: no pass) and its pipeline, made for the drawn key.
    std::shared_ptr<const std::vector<TranslucentDraw>> translucent_;
    std::shared_ptr<const scene::PartSet> translucentSet_; // what translucent_ was made of
    std::shared_ptr<const Pipeline> translucentPipeline_;
    // Freezing culling: the lists the last culled frame wrote (a frozen frame draws them
    // again once there are some), and the objects push mode's CPU test showed then.
    std::weak_ptr<const CullBuffers> culledLists_;
    std::vector<uint8_t> frozenObjects_;
    // What the last frame was drawn with, where it culled in two passes: a frame drawn with
    // the same is a still view (FRAME_VIEW_UNCHANGED).
    struct CulledView {
        glm::mat4 viewProj;
        glm::dvec3 origin; // what viewProj and the objects' matrices are relative to
        float explode;
        uint64_t hiddenVersion;
        uint32_t width, height, samples; // of the targets
        float lodErrorPixels;            // which levels of detail are drawn
        scene::Section section;          // a cut shows what the view hid before
        bool operator==(const CulledView&) const = default;
    };
    std::optional<CulledView> lastCulledView_;
    // The slot of history ends the next early pass reads: the last late pass's.
    HistorySlot historySlot_;
    uint64_t hiddenVersion_ = 0; // counts setHidden() calls
    uint64_t changes_ = 0;
    // What the composed image of `targets` was made from, blink aside, while nothing else
    // wrote to the images it reads: a scene pass, a new selection or new ID passes forget it.
    struct Composed {
        const SceneTargets* targets = nullptr;
        gpu::ComposePush push{};
        uint64_t wholeFrame = 0; // the frame slot's number of the last whole composition
    };
    std::optional<Composed> composed_;
    std::optional<HoveredTiles> lastTiles_;
    std::vector<uint8_t> objectHidden_;                      // per object: all its parts are hidden
    std::vector<std::pair<uint32_t, uint32_t>> objectParts_; // per object: first ID, count
    uint32_t partCount_ = 0;
    RenderStats stats_;
    SwitchReport lastSwitch_;
    ClearPath clearPath_ = ClearPath::Pass;
    std::map<uint32_t, ClearTiming> clearTimings_; // by sample count, with Auto
};

} // namespace render
