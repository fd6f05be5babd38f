// pipeline_cache.cpp - lookups, builds and the driver's pipeline cache.
#include "render/pipeline_cache.h"

#include <chrono>

#include "render/pipeline.h"
#include "render/shader_variants.h"
#include "vk/check.h"

namespace render {

PipelineCache::PipelineCache(vk::Device& device, const vk::ShaderCompiler& compiler,
                             const std::filesystem::path& cacheFolder)
    : device_(device), compiler_(compiler), layout_(createScenePipelineLayout(device)),
      driverCache_(device, cacheFolder) {}

std::shared_ptr<const Pipeline> PipelineCache::get(const PipelineKey& key, const ScenePass& pass,
                                                   bool& cached) {
    if (uint32_t(pass.samples()) != key.msaa)
        throw vk::Error("a " + std::to_string(key.msaa) + "x pipeline asked of a " +
                        std::to_string(pass.samples()) + "x pass");
    for (const auto& pipeline : pipelines_)
        if (pipeline->key == key) {
            cached = true;
            return pipeline;
        }
    cached = false;
    auto pipeline = build(key, pass);
    pipelines_.push_back(pipeline);
    return pipeline;
}

void PipelineCache::clear() {
    pipelines_.clear();
    compiler_.forget();
}

std::shared_ptr<const Pipeline> PipelineCache::build(const PipelineKey& key,
                                                     const ScenePass& pass) const {
    const auto start = std::chrono::steady_clock::now();
    std::vector<ShaderStage> stages;
    for (const vk::ShaderRequest& request : shaderVariants(key))
        stages.push_back({request.stage, vk::createShaderModule(device_, compiler_.compile(request),
                                                                request.label())});
    ScenePipelineInfo info;
    info.layout = layout_.get();
    info.pass = pass.handle();
    info.samples = pass.samples();
    // Mesh pipelines have no vertex input: the mode's draw index arrives another way.
    info.mesh = key.technique->usesMeshShader();
    info.drawIndexAttribute = key.mode->drawIndexAttribute && !info.mesh;
    info.writeIds = !key.technique->isFloor();
    const std::string name = std::string(key.technique->name) + " + " + key.mode->name + " (" +
                             std::to_string(key.msaa) + "x)";
    auto pipeline = std::make_shared<Pipeline>();
    pipeline->key = key;
    pipeline->handle = createScenePipeline(driverCache_, info, stages, name);
    pipeline->buildMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return pipeline;
}

} // namespace render
