// disk_pipeline_cache.cpp - the pipeline cache read at start, written at exit, and pipelines
// created through it (disk_pipeline_cache.h).
#include "render/disk_pipeline_cache.h"

#include <optional>
#include <vector>

#include "render/pipeline_file.h"
#include "util/cache_file.h"
#include "vk/check.h"

namespace render {

DiskPipelineCache::DiskPipelineCache(const vk::Device& device, const std::filesystem::path& folder)
    : device_(device) {
    auto info = vk::init<VkPipelineCacheCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO);
    std::optional<std::string> bytes;
    std::optional<std::string_view> blob;
    if (folder.empty()) {
        status_ = "off";
    } else {
        const PipelineCacheIdentity identity = pipelineCacheIdentity(device.physical());
        file_ = folder / pipelineFileName(identity);
        std::error_code ec;
        if (!std::filesystem::exists(file_, ec)) {
            status_ = "miss";
        } else if (!(bytes = util::readWholeFile(file_))) {
            status_ = "rejected: unreadable";
        } else {
            std::string why;
            blob = decodePipelineFile(*bytes, identity, why);
            status_ = blob ? "hit" : "rejected: " + why;
        }
    }
    if (blob) {
        info.initialDataSize = blob->size();
        info.pInitialData = blob->data();
    }
    cache_ = vk::make(device, vkCreatePipelineCache, info, "pipeline cache");
}

std::string DiskPipelineCache::save() const {
    if (file_.empty()) return {};
    const VkDevice device = device_.handle();
    size_t size = 0;
    std::string blob;
    VkResult result = VK_INCOMPLETE;
    // A pipeline built on a worker between the two calls can grow the data (VK_INCOMPLETE:
    // `size` bytes were written, not all): ask again.
    while (result == VK_INCOMPLETE) {
        result = vkGetPipelineCacheData(device, cache_.get(), &size, nullptr);
        blob.assign(size, '\0');
        if (result == VK_SUCCESS)
            result = vkGetPipelineCacheData(device, cache_.get(), &size, blob.data());
    }
    if (result != VK_SUCCESS)
        return std::string("vkGetPipelineCacheData failed: ") + vk::resultName(result);
    blob.resize(size);
    const std::string file = encodePipelineFile(pipelineCacheIdentity(device_.physical()), blob);
    return util::writeFileAtomically(file_, {file});
}

template <typename Info, typename Create>
vk::Handle<VkPipeline> DiskPipelineCache::createWith(Info& info, uint32_t stages, Create create,
                                                     const std::string& name) const {
    // Feedback for the whole pipeline and (as older validation layers ask) for each stage.
    VkPipelineCreationFeedbackEXT whole{};
    std::vector<VkPipelineCreationFeedbackEXT> perStage(stages);
    auto feedback = vk::init<VkPipelineCreationFeedbackCreateInfoEXT>(
        VK_STRUCTURE_TYPE_PIPELINE_CREATION_FEEDBACK_CREATE_INFO_EXT);
    feedback.pPipelineCreationFeedback = &whole;
    feedback.pipelineStageCreationFeedbackCount = stages;
    feedback.pPipelineStageCreationFeedbacks = perStage.data();
    if (device_.info().pipelineCreationFeedback) {
        feedback.pNext = info.pNext;
        info.pNext = &feedback;
    }
    vk::faultPoint(name.c_str());
    VkPipeline pipeline = VK_NULL_HANDLE;
    vk::check(create(device_.handle(), cache_.get(), 1, &info, nullptr, &pipeline),
              ("creating pipeline '" + name + "'").c_str());
    vk::Handle<VkPipeline> owned(device_.handle(), pipeline);
    device_.name(VK_OBJECT_TYPE_PIPELINE, pipeline, name);
    ++created_;
    if ((whole.flags & VK_PIPELINE_CREATION_FEEDBACK_VALID_BIT_EXT) &&
        (whole.flags & VK_PIPELINE_CREATION_FEEDBACK_APPLICATION_PIPELINE_CACHE_HIT_BIT_EXT))
        ++hits_;
    return owned;
}

vk::Handle<VkPipeline> DiskPipelineCache::create(VkGraphicsPipelineCreateInfo info,
                                                 const std::string& name) const {
    return createWith(info, info.stageCount, vkCreateGraphicsPipelines, name);
}

vk::Handle<VkPipeline> DiskPipelineCache::create(VkComputePipelineCreateInfo info,
                                                 const std::string& name) const {
    return createWith(info, 1, vkCreateComputePipelines, name);
}

} // namespace render
