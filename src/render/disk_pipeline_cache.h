// disk_pipeline_cache.h - the driver's VkPipelineCache, kept on disk between runs, and every
// pipeline idview creates made through it. The file (render/pipeline_file.h) is read when the
// cache is made and written by save(), which the headless run and the viewer call at exit; one
// that does not match this device and driver, is cut short or damaged is ignored (the cache
// starts empty) and replaced by the next save. `--no-cache` keeps it in memory only.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <string>

#include "vk/context.h"
#include "vk/handle.h"

namespace render {

class DiskPipelineCache {
  public:
    // Reads `folder`/pipelineFileName(this device) if there is one; an empty `folder` keeps
    // the cache in memory only.
    DiskPipelineCache(const vk::Device& device, const std::filesystem::path& folder);

    VkPipelineCache handle() const { return cache_.get(); }
    // "hit" (the file was loaded), "miss" (no file), "off" (no folder) or "rejected: <why>".
    const std::string& status() const { return status_; }
    const std::filesystem::path& file() const { return file_; } // empty when off

    // Writes what the driver holds now over the file (atomically); returns "" or why not.
    // Does nothing when off.
    std::string save() const;

    // vkCreate*Pipelines with this cache: a checked result, a fault point, the debug name.
    vk::Handle<VkPipeline> create(VkGraphicsPipelineCreateInfo info, const std::string& name) const;
    vk::Handle<VkPipeline> create(VkComputePipelineCreateInfo info, const std::string& name) const;

    // Pipelines created so far, and those of them the driver found in the cache: it says so
    // through VK_EXT_pipeline_creation_feedback, where the device has it (0 hits without).
    uint32_t created() const { return created_; }
    uint32_t hits() const { return hits_; }

  private:
    template <typename Info, typename Create>
    vk::Handle<VkPipeline> createWith(Info& info, uint32_t stages, Create create,
                                      const std::string& name) const;

    const vk::Device& device_;
    std::filesystem::path file_;
    std::string status_;
    vk::Handle<VkPipelineCache> cache_;
    // Pipelines are created from const owners, and on the renderer's workers too.
    mutable std::atomic<uint32_t> created_ = 0, hits_ = 0;
};

} // namespace render
