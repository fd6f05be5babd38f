// pipeline_cache.h - every scene pipeline built so far, kept by its effective key
// (PipelineKey::effective), so that switching back to a technique, mode or MSAA setting used
// before costs a lookup. Below it, the shader compiler remembers SPIR-V per request and the
// driver's VkPipelineCache, kept on disk between runs (render/disk_pipeline_cache.h), lets the
// driver reuse what it compiled, in this run or an earlier one. clear() forgets the first two
// levels (shaders edited on disk); the driver's cache stays, as its entries are keyed by the
// shaders' code, so an edited shader never finds a stale one. Pipelines still drawing in
// frames in flight live on in those frames (FrameSlot::keep).
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "render/disk_pipeline_cache.h"
#include "render/settings.h"
#include "render/targets.h"
#include "vk/handle.h"
#include "vk/shader_compiler.h"

namespace render {

struct Pipeline {
    PipelineKey key; // effective
    vk::Handle<VkPipeline> handle;
    double buildMs = 0.0; // compile and create, when it was built
};

class PipelineCache {
  public:
    // `cacheFolder`: where the driver's cache is kept between runs (empty: memory only).
    PipelineCache(vk::Device& device, const vk::ShaderCompiler& compiler,
                  const std::filesystem::path& cacheFolder);

    // The pipeline for an effective key, rendering into `pass` (whose sample count is the
    // key's). Built on first use; a compile error throws vk::ShaderError and keeps nothing.
    // `cached` says whether it was there already.
    std::shared_ptr<const Pipeline> get(const PipelineKey& key, const ScenePass& pass,
                                        bool& cached);
    void clear();

    VkPipelineLayout layout() const { return layout_.get(); }
    size_t size() const { return pipelines_.size(); }
    // Every pipeline of the renderer, compute passes included, is created through it.
    const DiskPipelineCache& driverCache() const { return driverCache_; }
    DiskPipelineCache& driverCache() { return driverCache_; }

  private:
    std::shared_ptr<const Pipeline> build(const PipelineKey& key, const ScenePass& pass) const;

    vk::Device& device_;
    const vk::ShaderCompiler& compiler_;
    vk::Handle<VkPipelineLayout> layout_;
    DiskPipelineCache driverCache_;
    std::vector<std::shared_ptr<const Pipeline>> pipelines_; // a few dozen at most: a list
};

} // namespace render
