// renderer.cpp - configuring (scene, pipeline, draw buffers) and recording the scene pass.
#include "render/renderer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstring>

#include "render/pipeline.h"
#include "vk/barrier.h"
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

Renderer::Renderer(vk::Device& device, const vk::ShaderCompiler& compiler,
                   const std::filesystem::path& pipelineCacheFolder)
    : device_(device), compiler_(compiler), pushStages_(pushStages(device)),
      pipelines_(device, compiler, pipelineCacheFolder),
      animator_(std::make_shared<Animator>(device, compiler, pipelines_.driverCache())),
      idPasses_(std::make_shared<IdPasses>(device, compiler, pipelines_.driverCache())),
      culler_(std::make_shared<CullPasses>(device, compiler, pipelines_.driverCache())),
      resolver_(std::make_shared<Resolver>(device, compiler, pipelines_.driverCache())),
      visibility_(std::make_shared<VisibilityShading>(device, compiler, pipelines_.driverCache())),
      raster_(std::make_shared<ComputeRaster>(device, compiler, pipelines_.driverCache())) {
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

std::optional<ClearTiming> Renderer::clearTiming(uint32_t msaa) const {
    auto found = clearTimings_.find(msaa);
    if (found == clearTimings_.end()) return std::nullopt;
    return found->second;
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
    ++changes_;
    const auto start = Clock::now();
    const PipelineKey key = keyFor(scene, settings, newScene);
    const Technique& technique = *key.technique;
    bool cached = false;
    auto pipeline = pipelines_.get(key, pass(key.msaa), cached);
    // X-ray's pipeline follows the MSAA setting and the section; a new scene has no X-ray.
    auto translucentPipeline = translucentPipeline_;
    if (newScene) {
        translucentPipeline.reset();
    } else if (translucentPipeline && translucentPipeline->key != translucentKey(key)) {
        bool found = false;
        translucentPipeline = pipelines_.get(translucentKey(key), pass(key.msaa), found);
    }
    const bool levels = settings.lod.errorPixels > 0.0f;
    const bool keepDraws = !newScene && drawsStillRight(key, settings.draws, levels);
    vk::UploadBatch upload(device_);
    auto sceneGpu = newScene ? std::make_shared<SceneGpu>(scene, upload) : sceneGpu_;
    auto partVertices = newScene ? nullptr : partVertices_;
    auto meshlets = newScene ? nullptr : meshlets_;
    if (technique.primitives == Primitives::PartVertices && !partVertices)
        partVertices = std::make_shared<PartVertexBuffers>(scene, upload);
    if (technique.primitives == Primitives::Meshlets && !meshlets)
        meshlets = std::make_shared<MeshletBuffers>(scene, upload);
    auto draws = keepDraws ? draws_
                           : buildDrawBuffers(device_, scene, *sceneGpu, key, settings.draws,
                                              partVertices, meshlets, levels, upload);
    upload.keep(sceneGpu);
    upload.keep(partVertices);
    upload.keep(meshlets);
    upload.keep(draws);
    const scene::PartSet none(scene.uniquePartCount());
    auto selected = newScene ? partSetBuffer(upload, none, "selection") : selected_;
    auto hidden = newScene ? partSetBuffer(upload, none, "hidden parts") : hidden_;
    upload.submit(); // nothing when nothing was added
    pipeline_ = std::move(pipeline);
    translucentPipeline_ = std::move(translucentPipeline);
    clearPath_ = clearPathFor(settings.clear, key.msaa, technique);
    if (newScene) {
        translucent_.reset();
        translucentSet_.reset();
        tint_.reset();
    }
    sceneGpu_ = std::move(sceneGpu);
    partVertices_ = std::move(partVertices);
    meshlets_ = std::move(meshlets);
    draws_ = std::move(draws);
    selected_ = std::move(selected);
    hidden_ = std::move(hidden);
    if (newScene) {
        partCount_ = scene.uniquePartCount();
        hiddenSet_ = none;
        objectParts_.clear();
        for (const scene::Object& o : scene.objects)
            objectParts_.push_back({o.uniquePartOffset, scene.geometries[o.geometry].partCount});
        objectHidden_.assign(scene.objects.size(), 0);
    }
    settings_ = settings;
    stats_ = draws_->stats;
    stats_.gsPassthrough = key.gsPassthrough;
    lastSwitch_ = {msSince(start), cached, keepDraws};
}

PipelineKey Renderer::keyFor(const scene::Scene& scene, const RenderSettings& settings,
                             bool newScene) {
    PipelineKey wanted = settings.pipeline;
    wanted.clear = clearPathFor(settings.clear, wanted.msaa, *wanted.technique);
    wanted.hiding = !newScene && !hiddenSet_.empty(); // a new scene starts with none hidden
    const CullPlan plan = cullPlan(*wanted.technique, *wanted.mode, settings.culling.mode,
                                   settings.lod.errorPixels > 0.0f);
    wanted.taskCulling = plan.taskShader;
    wanted.runOffsets = plan.clusterRuns;
    wanted.section = settings.section.any();
    const PipelineKey key = wanted.effective(device_.info().geometryShaderPassthrough);
    const Technique& technique = *key.technique;
    if (const std::string why = unavailableReason(technique, device_.info()); !why.empty())
        throw vk::Error(std::string(technique.name) + " is unavailable here: " + why);
    // The GPU's lists are drawn in one indirect call each.
    if (plan.gpuLists && scene.uniquePartCount() > device_.info().maxDrawIndirectCount)
        throw vk::Error("culling in " + std::string(key.mode->name) + " needs up to " +
                        std::to_string(scene.uniquePartCount()) + " draws in one indirect call, " +
                        device_.info().name + " allows " +
                        std::to_string(device_.info().maxDrawIndirectCount) +
                        ": use --culling off or push mode");
    return key;
}

std::optional<PipelineBuild> Renderer::prepare(const scene::Scene& scene,
                                               const RenderSettings& settings) {
    if (!sceneGpu_) throw vk::Error("Renderer::prepare before setScene");
    const PipelineKey key = keyFor(scene, settings, false);
    if (!pipelines_.request(key, pass(key.msaa))) return pipelines_.progress(key);
    // Under X-ray its pipeline follows the MSAA setting and section too: built on a worker.
    if (translucentPipeline_) {
        const PipelineKey xray = translucentKey(key);
        if (!pipelines_.request(xray, pass(xray.msaa))) return pipelines_.progress(xray);
    }
    return std::nullopt;
}

PipelineKey Renderer::hidingKey(bool hiding) const {
    PipelineKey key = pipeline_->key;
    key.hiding = hiding;
    return key.effective(device_.info().geometryShaderPassthrough);
}

std::optional<PipelineBuild> Renderer::prepareHidden(const scene::PartSet& hidden) {
    if (!pipeline_ || hidden.empty() == hiddenSet_.empty()) return std::nullopt;
    const PipelineKey key = hidingKey(!hidden.empty());
    if (pipelines_.request(key, pass(key.msaa))) return std::nullopt;
    return pipelines_.progress(key);
}

void Renderer::reloadShaders() {
    if (!pipeline_) return; // nothing configured yet
    ++changes_;
    const PipelineKey key = pipeline_->key;
    pipelines_.clear();
    const DiskPipelineCache& cache = pipelines_.driverCache();
    auto animator = std::make_shared<Animator>(device_, compiler_, cache);
    auto idPasses = std::make_shared<IdPasses>(device_, compiler_, cache);
    auto culler = std::make_shared<CullPasses>(device_, compiler_, cache);
    auto resolver = std::make_shared<Resolver>(device_, compiler_, cache);
    auto visibility = std::make_shared<VisibilityShading>(device_, compiler_, cache);
    auto raster = std::make_shared<ComputeRaster>(device_, compiler_, cache);
    bool cached = false;
    pipeline_ = pipelines_.get(key, pass(key.msaa), cached);
    if (translucentPipeline_)
        translucentPipeline_ = pipelines_.get(translucentKey(key), pass(key.msaa), cached);
    animator_ = std::move(animator);
    idPasses_ = std::move(idPasses);
    composed_.reset(); // their box of the hovered part's tiles is not written yet
    culler_ = std::move(culler);
    resolver_ = std::move(resolver);
    visibility_ = std::move(visibility);
    raster_ = std::move(raster);
    lastCulledView_.reset(); // the history is of what the old shaders found
}

void Renderer::setSelection(const scene::PartSet& selected) {
    if (!sceneGpu_ || selected.partCount() != partCount_)
        throw vk::Error("Renderer::setSelection: not a set over the current scene's parts");
    vk::UploadBatch upload(device_);
    auto buffer = partSetBuffer(upload, selected, "selection");
    upload.submit();
    selected_ = std::move(buffer);
    composed_.reset();
}

void Renderer::setTint(const std::vector<uint32_t>& rgba) {
    if (!rgba.empty() && (!sceneGpu_ || rgba.size() != partCount_))
        throw vk::Error("Renderer::setTint: not one colour per part of the current scene");
    std::shared_ptr<const vk::Buffer> buffer;
    if (!rgba.empty()) {
        vk::UploadBatch upload(device_);
        auto tint = std::make_shared<vk::Buffer>(upload.add(
            rgba, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
            "tint by visibility"));
        upload.keep(tint);
        upload.submit();
        buffer = std::move(tint);
    }
    tint_ = std::move(buffer);
    composed_.reset();
}

void Renderer::setHidden(const scene::PartSet& hidden) {
    if (!sceneGpu_ || hidden.partCount() != partCount_)
        throw vk::Error("Renderer::setHidden: not a set over the current scene's parts");
    ++hiddenVersion_;
    ++changes_;
    auto pipeline = pipeline_;
    if (hidden.empty() != hiddenSet_.empty()) {
        const PipelineKey key = hidingKey(!hidden.empty());
        bool cached = false;
        pipeline = pipelines_.get(key, pass(key.msaa), cached);
    }
    vk::UploadBatch upload(device_);
    auto buffer = partSetBuffer(upload, hidden, "hidden parts");
    upload.submit();
    pipeline_ = std::move(pipeline);
    hidden_ = std::move(buffer);
    hiddenSet_ = hidden;
    // Objects with every part hidden are left out by the CPU's culling too (push mode).
    for (size_t o = 0; o < objectParts_.size(); ++o) {
        const auto [first, count] = objectParts_[o];
        bool all = count > 0;
        for (uint32_t id = first; all && id < first + count; ++id) all = hidden.contains(id);
        objectHidden_[o] = all ? 1 : 0;
    }
}

void Renderer::setTranslucent(const scene::Scene& scene, const scene::PartSet& parts) {
    if (!sceneGpu_ || parts.partCount() != partCount_ || scene.uniquePartCount() != partCount_)
        throw vk::Error("Renderer::setTranslucent: not a set over the current scene's parts");
    if (translucent_ ? parts == *translucentSet_ : parts.empty()) return; // a redraw for nothing
    ++changes_;
    auto pipeline = translucentPipeline_;
    if (!parts.empty() && !pipeline) {
        const PipelineKey key = translucentKey(pipeline_->key);
        bool cached = false;
        pipeline = pipelines_.get(key, pass(key.msaa), cached);
    }
    translucent_ =
        parts.empty()
            ? nullptr
            : std::make_shared<const std::vector<TranslucentDraw>>(translucentDraws(scene, parts));
    translucentSet_ = parts.empty() ? nullptr : std::make_shared<const scene::PartSet>(parts);
    translucentPipeline_ = std::move(pipeline);
}

// The draw list depends on the technique's split, ID data and primitives, whether it numbers
// payloads, the search batch it reads, the mode's buffers, the draw settings and whether levels
// of detail are on; a switch that changes none of them keeps it.
bool Renderer::drawsStillRight(const PipelineKey& key, const DrawSettings& draws,
                               bool levels) const {
    if (!draws_) return false;
    const PipelineKey& built = draws_->key;
    return built.technique->split == key.technique->split &&
           built.technique->ids == key.technique->ids &&
           built.technique->primitives == key.technique->primitives &&
           // The visibility buffer's lists number the payloads too.
           built.technique->isVisibilityBuffer() == key.technique->isVisibilityBuffer() &&
           built.technique->computeRaster == key.technique->computeRaster && // its lists
           built.searchBatch == key.searchBatch && built.mode == key.mode &&
           built.taskCulling == key.taskCulling && draws_->inputs == draws &&
           draws_->levels == levels;
}

CullPlan Renderer::cullingPlan() const {
    const PipelineKey& key = draws_->key;
    return cullPlan(*key.technique, *key.mode, settings_.culling.mode, draws_->levels);
}

CullCounts Renderer::cullTotals() const {
    return {stats_.draws, draws_->meshletTotal, stats_.triangles};
}

// The frame, step by step. Culling (render/culling.h) may split the scene pass in two halves
// around the depth pyramid; every step writes its timestamp, steps left out included.
void Renderer::record(FrameSlot& slot, const std::shared_ptr<const SceneTargets>& target,
                      const FrameParams& params) {
    if (!pipeline_ || !sceneGpu_) throw vk::Error("Renderer::record before setScene");
    const SceneTargets& targets = *target;
    if (uint32_t(targets.pass().samples()) != pipeline_->key.msaa)
        throw vk::Error("Renderer::record: targets of another MSAA setting than configured");
    VkCommandBuffer cmd = slot.cmd;
    for (const std::shared_ptr<const void>& used :
         std::initializer_list<std::shared_ptr<const void>>{
             pipeline_, sceneGpu_, draws_, pick_, animator_, idPasses_, culler_, resolver_,
             visibility_, raster_, selected_, hidden_, tint_, target, translucentPipeline_})
        slot.keep(used);
    slot.scenePass = true;
    if (draws_->key.technique->computeRaster) {
        const VkDeviceSize bytes = rasterSampleBytes(targets);
        if (!rasterSamples_ || rasterSamples_->size() != bytes)
            rasterSamples_ = std::make_shared<vk::Buffer>(
                device_, bytes,
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
                    VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                0, "compute raster samples");
        slot.keep(rasterSamples_);
    }
    composed_.reset(); // the images the composition reads are drawn again
    vk::CmdLabel label(device_.debug(), cmd, "scene pass");

    FrameCulling culling = planFrame(params, targets);
    const gpu::FrameData frame = frameData(targets, params, culling);
    vkCmdUpdateBuffer(cmd, slot.frameData.handle(), 0, sizeof frame, &frame);
    slot.pickPixel = params.pickPixel;
    recordPickReset(cmd);
    // Frame data and the pick reset (this frame), `last` (the previous frame's copy, which the
    // edge pass reads too).
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      sceneShaderStages(device_) | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    animator_->record(cmd, *sceneGpu_, params.explode, params.origin);
    recordScene(slot, targets, culling);
    recordIdPasses(cmd, slot, targets, params);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, slot.timestamps.get(),
                        StampIdPasses);
    recordPickCopies(cmd, slot);
}

void Renderer::recordComposition(FrameSlot& slot, const std::shared_ptr<const SceneTargets>& target,
                                 const FrameParams& params) {
    if (!sceneGpu_) throw vk::Error("Renderer::recordComposition before setScene");
    for (const std::shared_ptr<const void>& used :
         std::initializer_list<std::shared_ptr<const void>>{idPasses_, selected_, tint_, target,
                                                            rasterSamples_})
        slot.keep(used);
    vk::CmdLabel label(device_.debug(), slot.cmd, "composition");
    recordIdPasses(slot.cmd, slot, *target, params);
}

// Culling, and the scene pass, whole or in two halves around the depth pyramid.
void Renderer::recordScene(FrameSlot& slot, const SceneTargets& targets,
                           FrameCulling& culling) const {
    VkCommandBuffer cmd = slot.cmd;
    const VkDeviceAddress frame = slot.frameData.address();
    const CullPlan& plan = culling.plan;
    const CullBuffers& cull = *draws_->cull;
    const bool listOnGpu = plan.gpuLists && !culling.frozen;
    const bool split = plan.twoPasses && !culling.frozen;
    auto stamp = [&](Stamp s) {
        // Once every earlier command has finished (bottom of the pipe), so neither the
        // animation's dispatch nor the previous frame's tail counts as the frame's work.
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, slot.timestamps.get(), s);
    };
    stamp(StampStart);
    recordCounters(cmd, culling, true);
    if (draws_->key.technique->computeRaster)
        raster_->recordClear(cmd, *rasterSamples_, draws_->rasterList);
    const uint32_t firstPhase = culling.frozen ? gpu::CULL_PHASE_FROZEN : plan.firstPhase;
    const CullPasses::CullInputs inputs{frame, draws_->draws.address(), draws_->indirect.address(),
                                        sceneGpu_->clusterBoxesAddress()};
    if (listOnGpu) culler_->recordCull(cmd, cull, inputs, plan, firstPhase, culling.history);
    stamp(StampEarlyCulled);
    // The compute path clears colour in the pass only under X-ray, which blends over it.
    const bool compute = clearPath_ == ClearPath::Compute;
    const bool clearColor = translucent_ && !translucent_->empty();
    beginPass(cmd, targets, split ? PassPart::First : PassPart::Whole, frame, clearColor);
    drawPhase(cmd, culling, firstPhase);
    // A frozen frame draws the late list too, in the same pass (push mode has none: its task
    // shader drew every meshlet with history in the first).
    if (culling.frozen && plan.twoPasses && plan.gpuLists)
        drawPhase(cmd, culling, gpu::CULL_PHASE_FROZEN_LATE);
    if (!split) recordTranslucent(cmd);
    vkCmdEndRenderPass(cmd);
    // A frozen frame's one pass listed meshlets for both.
    recordComputeRaster(cmd, frame, targets, 0, split ? 0 : 1);
    stamp(StampEarlyDrawn);
    if (split) culler_->recordPyramid(cmd, targets, rasterSamplesAddress());
    stamp(StampPyramid);
    if (split && plan.gpuLists)
        culler_->recordCull(cmd, cull, inputs, plan, gpu::CULL_PHASE_LATE, culling.history);
    stamp(StampLateCulled);
    if (split) {
        beginPass(cmd, targets, PassPart::Second, frame, clearColor);
        drawPhase(cmd, culling, gpu::CULL_PHASE_LATE);
        recordTranslucent(cmd);
        vkCmdEndRenderPass(cmd);
        recordComputeRaster(cmd, frame, targets, 1, 1);
    }
    if (draws_->key.technique->isVisibilityBuffer())
        visibility_->record(cmd, targets, visibilityPush(frame, clearColor));
    else if (compute)
        resolver_->record(cmd, targets,
                          (clearColor ? gpu::RESOLVE_KEEP_COLOR : 0u) |
                              (draws_->key.technique->isFloor() ? gpu::RESOLVE_NO_IDS : 0u));
    stamp(StampDrawn);
    recordCounters(cmd, culling, false);
}

void Renderer::recordComputeRaster(VkCommandBuffer cmd, VkDeviceAddress frame,
                                   const SceneTargets& targets, uint32_t first,
                                   uint32_t last) const {
    if (!draws_->key.technique->computeRaster) return;
    for (uint32_t list = first; list <= last; ++list)
        raster_->recordPass(cmd, frame, draws_->rasterList, list,
                            uint32_t(targets.pass().samples()));
}

VkDeviceAddress Renderer::rasterSamplesAddress() const {
    return draws_ && draws_->key.technique->computeRaster && rasterSamples_
               ? rasterSamples_->address()
               : 0;
}

} // namespace render
