// pipeline_cache.h - every scene pipeline built so far, kept by its effective key
// (PipelineKey::effective), so that switching back to a technique, mode or MSAA setting used
// before costs a lookup. Below it, the shader compiler remembers SPIR-V per request and the
// driver's VkPipelineCache, kept on disk between runs (render/disk_pipeline_cache.h), lets the
// driver reuse what it compiled, in this run or an earlier one. clear() forgets the first two
// levels (shaders edited on disk); the driver's cache stays, as its entries are keyed by the
// shaders' code, so an edited shader never finds a stale one. Pipelines still drawing in
// frames in flight live on in those frames (FrameSlot::keep).
//
// Two ways in: get() builds on the caller's thread and returns the pipeline (headless, the
// benchmark, the tests: what they render is decided before they render), and request()
// starts the build on a worker and returns at once (the viewer, which goes on drawing what
// it has meanwhile). A worker only reads: it builds a Pipeline from its key and hands it back
// through a future; the list is touched by the owner's thread alone (collect()).
#pragma once

#include <chrono>
#include <condition_variable>
#include <exception>
#include <filesystem>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
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

// A pipeline being built on a worker: what it is ("tri-fs + mdi (4x), hiding") and for how long.
struct PipelineBuild {
    std::string name;
    double seconds = 0.0;
};

// "basic + indirect (4x)", with the variants the renderer chose (hiding, section, culling).
std::string describePipeline(const PipelineKey& key);

class PipelineCache {
  public:
    // `cacheFolder`: where the driver's cache is kept between runs (empty: memory only).
    PipelineCache(vk::Device& device, const vk::ShaderCompiler& compiler,
                  const std::filesystem::path& cacheFolder);
    // Lets held builds go and waits for every worker: they use this cache's members.
    ~PipelineCache();
    PipelineCache(const PipelineCache&) = delete;
    PipelineCache& operator=(const PipelineCache&) = delete;

    // The pipeline for an effective key, rendering into `pass` (whose sample count is the
    // key's). Built on first use, on this thread; a build of it already running on a worker
    // is waited for. A compile error throws vk::ShaderError and keeps nothing. `cached` says
    // whether it was there already.
    std::shared_ptr<const Pipeline> get(const PipelineKey& key, const ScenePass& pass,
                                        bool& cached);
    // The non-blocking way: the pipeline if it is built; else null, and its build runs on a
    // worker (started now unless one runs for this key). A build that failed throws its error
    // here, once: asking again starts it again. Finished builds of other keys (a wish the
    // user changed meanwhile) are kept too, ready for a switch back.
    std::shared_ptr<const Pipeline> request(const PipelineKey& key, const ScenePass& pass);
    // The build of `key` running on a worker, if any.
    std::optional<PipelineBuild> progress(const PipelineKey& key) const;
    // Whether any worker's result is not collected yet.
    bool building() const { return !builds_.empty(); }
    // Moves the finished builds' pipelines into the list and their errors aside (for the next
    // request of their key). get() and request() do it first; an owner that asks for nothing
    // calls it to take in builds nobody waits for any more.
    void collect();
    // Called on the worker once each build is done (successful or not) and its result can be
    // collected: the viewer passes glfwPostEmptyEvent to wake its event wait. Must be
    // thread-safe; set it before asking for builds.
    void onBuilt(std::function<void()> wake) { wake_ = std::move(wake); }
    // For tests: builds started while held wait on their worker, before compiling anything,
    // until released, so "a build is pending" is a state a test can hold as long as it likes.
    // get() and clear() of a held build would wait for ever: release first.
    void holdBuilds(bool hold);

    // Waits for the builds running (compiled from the shaders before the edit) and drops
    // them with the rest.
    void clear();

    VkPipelineLayout layout() const { return layout_.get(); }
    size_t size() const { return pipelines_.size(); }
    // Every pipeline of the renderer, compute passes included, is created through it.
    const DiskPipelineCache& driverCache() const { return driverCache_; }
    DiskPipelineCache& driverCache() { return driverCache_; }

  private:
    // Reads only members that stay as they are while the cache lives (device, compiler,
    // layout, driver cache), so a worker may run it: see request() in the .cpp.
    std::shared_ptr<const Pipeline> build(const PipelineKey& key, VkRenderPass pass,
                                          VkSampleCountFlagBits samples) const;
    std::shared_ptr<const Pipeline> find(const PipelineKey& key) const;
    void checkPass(const PipelineKey& key, const ScenePass& pass) const;

    struct Gate { // holdBuilds()
        std::mutex mutex;
        std::condition_variable released;
        bool held = false;
    };
    struct Build {
        PipelineKey key;
        std::chrono::steady_clock::time_point start;
        std::future<std::shared_ptr<const Pipeline>> result; // set by the worker
        std::future<void> worker;                            // its end: waited for
    };
    struct Failure {
        PipelineKey key;
        std::exception_ptr error;
    };

    vk::Device& device_;
    const vk::ShaderCompiler& compiler_;
    vk::Handle<VkPipelineLayout> layout_;
    DiskPipelineCache driverCache_;
    std::vector<std::shared_ptr<const Pipeline>> pipelines_; // a few dozen at most: a list
    std::vector<Build> builds_;                              // running, or done and not collected
    std::vector<Failure> failed_;                            // collected, not yet reported
    std::function<void()> wake_;
    std::shared_ptr<Gate> gate_ = std::make_shared<Gate>();
};

} // namespace render
