// animator.cpp - the compute pipeline and the recording of the animation.
#include "render/animator.h"

#include <algorithm>
#include <vector>

#include "render/disk_pipeline_cache.h"
#include "render/pipeline.h"
#include "shared.h"
#include "vk/check.h"
#include "vk/debug.h"

namespace render {
namespace {

// The dispatch shares the frame's command buffer, so the queue the scene pass uses must run
// compute too; Vulkan does not promise that of every graphics queue family.
void requireCompute(const vk::Device& device) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device.physical(), &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device.physical(), &count, families.data());
    if (device.queueFamily() >= count ||
        !(families[device.queueFamily()].queueFlags & VK_QUEUE_COMPUTE_BIT))
        throw vk::Error("the animation needs compute shaders on the graphics queue, which " +
                        device.info().name + " does not offer");
}

} // namespace

Animator::Animator(vk::Device& device, const vk::ShaderCompiler& compiler,
                   const DiskPipelineCache& cache)
    : device_(device) {
    requireCompute(device);
    ComputePipeline built =
        createComputePipeline(device, compiler, cache, "animate.comp", sizeof(gpu::AnimationPush),
                              VK_NULL_HANDLE, "animate objects");
    layout_ = std::move(built.layout);
    pipeline_ = std::move(built.pipeline);
}

void Animator::record(VkCommandBuffer cmd, SceneGpu& scene, float explode,
                      const glm::dvec3& origin) const {
    explode = explode > 0.0f ? std::min(explode, 1.0f) : 0.0f; // NaN counts as at rest
    if (explode == 0.0f && scene.explodeWritten == 0.0f && scene.originWritten == origin) return;
    vk::CmdLabel label(device_.debug(), cmd, "animate objects");

    // Write-after-read (and -write) across frames in flight on the one queue: the previous
    // frame's shaders may still read the matrices this dispatch overwrites.
    auto before = vk::init<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    before.srcAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    before.dstAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    const VkPipelineStageFlags sceneShaders = sceneShaderStages(device_);
    vkCmdPipelineBarrier(cmd, sceneShaders | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &before, 0, nullptr, 0,
                         nullptr);

    gpu::AnimationPush push{glm::dvec4(origin, 0.0), scene.objectsAddress(), scene.restAddress(),
                            scene.offsetsAddress(),  scene.objectCount(),    explode};
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
    vkCmdPushConstants(cmd, layout_.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdDispatch(
        cmd, (scene.objectCount() + gpu::ANIMATE_GROUP_SIZE - 1) / gpu::ANIMATE_GROUP_SIZE, 1, 1);

    // The scene pass reads ObjectData in the vertex or mesh shader (world) and in the geometry
    // and fragment shaders (the rest of the struct, in the same memory); culling's compute
    // passes read the matrices too.
    auto after = vk::init<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    after.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    after.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         sceneShaders | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &after, 0,
                         nullptr, 0, nullptr);
    scene.explodeWritten = explode;
    scene.originWritten = origin;
}

} // namespace render
