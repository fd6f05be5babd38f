// pipeline_cache.h - every scene pipeline built so far, kept by its effective key
// (PipelineKey::effective), so that switching back to a technique, mode or MSAA setting used
// before costs a lookup. Below it, the shader compiler remembers SPIR-V per request and a
// VkPipelineCache lets the driver reuse what it compiled. clear() forgets all three levels
// (shaders edited on disk); pipelines still drawing in frames in flight live on in those
// frames (FrameSlot::keep).
#pragma once

#include <memory>
#include <vector>

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
    PipelineCache(vk::Device& device, const vk::ShaderCompiler& compiler);

    // The pipeline for an effective key, rendering into `pass` (whose sample count is the
    // key's). Built on first use; a compile error throws vk::ShaderError and keeps nothing.
    // `cached` says whether it was there already.
    std::shared_ptr<const Pipeline> get(const PipelineKey& key, const ScenePass& pass,
                                        bool& cached);
    void clear();

    VkPipelineLayout layout() const { return layout_.get(); }
    size_t size() const { return pipelines_.size(); }

  private:
    std::shared_ptr<const Pipeline> build(const PipelineKey& key, const ScenePass& pass) const;
    void createDriverCache();

    vk::Device& device_;
    const vk::ShaderCompiler& compiler_;
    vk::Handle<VkPipelineLayout> layout_;
    vk::Handle<VkPipelineCache> driverCache_;
    std::vector<std::shared_ptr<const Pipeline>> pipelines_; // a few dozen at most: a list
};

} // namespace render
