// pipeline_cache.cpp - lookups, builds (here or on a worker) and the driver's pipeline cache.
#include "render/pipeline_cache.h"

#include <algorithm>

#include "render/pipeline.h"
#include "render/shader_variants.h"
#include "vk/check.h"

namespace render {
namespace {

using Clock = std::chrono::steady_clock;

// The pipeline's debug name: technique, mode and samples.
std::string baseName(const PipelineKey& key) {
    return std::string(key.technique->name) + " + " + key.mode->name + " (" +
           std::to_string(key.msaa) + "x)";
}

} // namespace

std::string describePipeline(const PipelineKey& key) {
    std::string text = baseName(key);
    if (key.hiding) text += ", hiding parts";
    if (key.section) text += ", section";
    if (key.translucent) text += ", translucent";
    if (key.overVisibility) text += " over a visibility buffer";
    if (key.clear == ClearPath::Compute) text += ", compute resolve"; // MSAA's other pass
    if (key.taskCulling || key.runOffsets) text += ", culling";
    return text;
}

PipelineCache::PipelineCache(vk::Device& device, const vk::ShaderCompiler& compiler,
                             const std::filesystem::path& cacheFolder)
    : device_(device), compiler_(compiler), layout_(createScenePipelineLayout(device)),
      driverCache_(device, cacheFolder) {}

PipelineCache::~PipelineCache() {
    holdBuilds(false);
    for (Build& b : builds_) b.worker.wait();
}

void PipelineCache::checkPass(const PipelineKey& key, const ScenePass& pass) const {
    if (uint32_t(pass.samples()) != key.msaa)
        throw vk::Error("a " + std::to_string(key.msaa) + "x pipeline asked of a " +
                        std::to_string(pass.samples()) + "x pass");
}

std::shared_ptr<const Pipeline> PipelineCache::find(const PipelineKey& key) const {
    for (const auto& pipeline : pipelines_)
        if (pipeline->key == key) return pipeline;
    return nullptr;
}

std::shared_ptr<const Pipeline> PipelineCache::get(const PipelineKey& key, const ScenePass& pass,
                                                   bool& cached) {
    checkPass(key, pass);
    collect();
    std::erase_if(failed_, [&](const Failure& f) { return f.key == key; }); // tried again here
    if (auto found = find(key)) {
        cached = true;
        return found;
    }
    cached = false;
    auto running =
        std::find_if(builds_.begin(), builds_.end(), [&](const Build& b) { return b.key == key; });
    std::shared_ptr<const Pipeline> pipeline;
    if (running != builds_.end()) {
        Build pending = std::move(*running);
        builds_.erase(running);
        pending.worker.wait();
        pipeline = pending.result.get(); // a failed build throws its error
    } else {
        pipeline = build(key, pass.handle(PassPart::Whole, key.clear), pass.samples());
    }
    pipelines_.push_back(pipeline);
    return pipeline;
}

// Why a worker may build while the owner's thread goes on drawing and asking:
// - build() reads members that are made before any worker starts and are left alone until
//   every worker has ended (the destructor and clear() wait for them); the list, builds_
//   and failed_ are touched by the owner's thread only, the result comes back in a future.
// - glslang: ShaderCompiler set up its process-wide state (InitializeProcess) in its
//   constructor, before any worker; it serialises its memo and its glslang runs itself.
// - vkCreateShaderModule and vkCreateGraphicsPipelines take the device without external
//   synchronisation, and the driver's VkPipelineCache is made without
//   VK_PIPELINE_CACHE_CREATE_EXTERNALLY_SYNCHRONIZED_BIT, so the driver synchronises its use
//   by several threads at once (the specification's vkCreatePipelineCache). The debug name
//   goes on the new pipeline, which no other thread knows yet.
// - The pass is passed as its handle: render passes live as long as the renderer, longer
//   than the workers.
std::shared_ptr<const Pipeline> PipelineCache::request(const PipelineKey& key,
                                                       const ScenePass& pass) {
    checkPass(key, pass);
    collect();
    if (auto found = find(key)) return found;
    if (auto failed = std::find_if(failed_.begin(), failed_.end(),
                                   [&](const Failure& f) { return f.key == key; });
        failed != failed_.end()) {
        const std::exception_ptr error = failed->error;
        failed_.erase(failed);
        std::rethrow_exception(error);
    }
    if (progress(key)) return nullptr; // its worker is on it
    std::promise<std::shared_ptr<const Pipeline>> promise;
    Build pending{key, Clock::now(), promise.get_future(), {}};
    pending.worker =
        std::async(std::launch::async, [this, key, pass = pass.handle(PassPart::Whole, key.clear),
                                        samples = pass.samples(), gate = gate_, wake = wake_,
                                        promise = std::move(promise)]() mutable {
            {
                std::unique_lock lock(gate->mutex);
                gate->released.wait(lock, [&] { return !gate->held; });
            }
            try {
                promise.set_value(this->build(key, pass, samples));
            } catch (...) {
                promise.set_exception(std::current_exception());
            }
            // After the result is set: a loop woken now finds it ready.
            if (wake) wake();
        });
    builds_.push_back(std::move(pending));
    return nullptr;
}

std::optional<PipelineBuild> PipelineCache::progress(const PipelineKey& key) const {
    for (const Build& b : builds_)
        if (b.key == key)
            return PipelineBuild{describePipeline(key),
                                 std::chrono::duration<double>(Clock::now() - b.start).count()};
    return std::nullopt;
}

void PipelineCache::collect() {
    using namespace std::chrono_literals;
    for (auto b = builds_.begin(); b != builds_.end();) {
        if (b->result.wait_for(0s) != std::future_status::ready) {
            ++b;
            continue;
        }
        try {
            auto pipeline = b->result.get();
            if (!find(pipeline->key)) pipelines_.push_back(std::move(pipeline));
        } catch (...) {
            failed_.push_back({b->key, std::current_exception()});
        }
        b->worker.wait(); // returns at once: the result was its last work but the wake
        b = builds_.erase(b);
    }
}

void PipelineCache::holdBuilds(bool hold) {
    {
        std::lock_guard lock(gate_->mutex);
        gate_->held = hold;
    }
    if (!hold) gate_->released.notify_all();
}

void PipelineCache::clear() {
    for (Build& b : builds_) b.worker.wait();
    builds_.clear();
    failed_.clear();
    pipelines_.clear();
    compiler_.forget();
}

std::shared_ptr<const Pipeline> PipelineCache::build(const PipelineKey& key, VkRenderPass pass,
                                                     VkSampleCountFlagBits samples) const {
    const auto start = Clock::now();
    std::vector<ShaderStage> stages;
    for (const vk::ShaderRequest& request : shaderVariants(key))
        stages.push_back({request.stage, vk::createShaderModule(device_, compiler_.compile(request),
                                                                request.label())});
    ScenePipelineInfo info;
    info.layout = layout_.get();
    info.pass = pass;
    info.samples = samples;
    // Mesh pipelines have no vertex input: the mode's draw index arrives another way.
    info.mesh = key.technique->usesMeshShader();
    info.drawIndexAttribute = key.mode->drawIndexAttribute && !info.mesh;
    info.writeIds = !key.technique->isFloor();
    info.translucent = key.translucent;
    info.writeColor = !key.technique->isVisibilityBuffer();
    info.accumulate = key.overVisibility;
    auto pipeline = std::make_shared<Pipeline>();
    pipeline->key = key;
    pipeline->handle = createScenePipeline(driverCache_, info, stages, baseName(key));
    pipeline->buildMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    return pipeline;
}

} // namespace render
