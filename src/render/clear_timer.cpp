// clear_timer.cpp - ClearPath::Auto on this device: both clear paths timed on frames that draw
// nothing, once per MSAA setting, and the timings kept beside the pipeline cache
// (clear_choice.h has the file).
#include <algorithm>
#include <array>
#include <cstdio>
#include <vector>

#include "render/renderer.h"
#include "util/cache_file.h"
#include "vk/check.h"

namespace render {
namespace {

constexpr VkExtent2D kTimedExtent{clearTimingWidth, clearTimingHeight};
constexpr uint32_t kRounds = 3;         // the paths alternate, so drift hits both alike
constexpr uint32_t kFramesPerRound = 4; // per path

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

// The median GPU ms of an empty frame on each path: the scene pass clearing what its path
// clears, and on the compute path the resolve after it.
ClearTiming timeClearPaths(vk::Device& device, const ScenePass& pass, const Resolver& resolver) {
    SceneTargets targets(device, pass, kTimedExtent);
    constexpr uint32_t stamps = kRounds * 2 * kFramesPerRound * 2;
    auto queryInfo = vk::init<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    queryInfo.queryType = VK_QUERY_TYPE_TIMESTAMP;
    queryInfo.queryCount = stamps;
    const auto queries = vk::make(device, vkCreateQueryPool, queryInfo, "clear path timestamps");
    // The one wait this needs: Auto is resolved once, before the first frame of its MSAA.
    device.submitNow([&](VkCommandBuffer cmd) {
        vkCmdResetQueryPool(cmd, queries.get(), 0, stamps);
        std::array<VkClearValue, 3> clears{};
        clears[0].color = {
            {backgroundColor.r, backgroundColor.g, backgroundColor.b, backgroundColor.a}};
        clears[1].color.uint32[0] = gpu::BACKGROUND_ID;
        clears[2].depthStencil = {0.0f, 0};
        uint32_t stamp = 0;
        for (uint32_t round = 0; round < kRounds; ++round)
            for (ClearPath path : {ClearPath::Pass, ClearPath::Compute})
                for (uint32_t frame = 0; frame < kFramesPerRound; ++frame) {
                    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries.get(),
                                        stamp++);
                    auto begin =
                        vk::init<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO);
                    begin.renderPass = pass.handle(PassPart::Whole, path);
                    begin.framebuffer = targets.framebuffer(PassPart::Whole, path);
                    begin.renderArea = {{0, 0}, kTimedExtent};
                    begin.clearValueCount = static_cast<uint32_t>(clears.size());
                    begin.pClearValues = clears.data();
                    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
                    vkCmdEndRenderPass(cmd);
                    if (path == ClearPath::Compute) resolver.record(cmd, targets, 0);
                    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries.get(),
                                        stamp++);
                }
    });
    std::array<uint64_t, stamps> ticks{};
    vk::check(vkGetQueryPoolResults(device.handle(), queries.get(), 0, stamps, sizeof ticks,
                                    ticks.data(), sizeof(uint64_t),
                                    VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
              "vkGetQueryPoolResults (clear paths)");
    std::vector<double> ms[2];
    const double period = device.info().timestampPeriodNs * 1e-6;
    for (uint32_t i = 0; i < stamps; i += 2) {
        const bool compute = (i / (2 * kFramesPerRound)) % 2 == 1;
        ms[compute].push_back(double(ticks[i + 1] - ticks[i]) * period);
    }
    ClearTiming timing;
    timing.samples = uint32_t(pass.samples());
    timing.passMs = median(ms[0]);
    timing.computeMs = median(ms[1]);
    return timing;
}

} // namespace

ClearPath Renderer::clearPathFor(ClearPath wanted, uint32_t msaa, const Technique& technique) {
    if (technique.isVisibilityBuffer()) return ClearPath::Compute;
    if (wanted != ClearPath::Auto) return wanted;
    if (auto known = clearTimings_.find(msaa); known != clearTimings_.end())
        return known->second.faster();
    // Kept beside the pipeline cache, under a name of this device and driver.
    const std::filesystem::path& cacheFile = pipelines_.driverCache().file();
    const PipelineCacheIdentity identity = pipelineCacheIdentity(device_.physical());
    std::filesystem::path file;
    std::map<uint32_t, ClearTiming> remembered;
    if (!cacheFile.empty()) {
        file = cacheFile.parent_path() / clearTimingFileName(identity);
        if (auto text = util::readWholeFile(file)) remembered = decodeClearTimings(*text, identity);
    }
    auto found = remembered.find(msaa);
    if (found == remembered.end()) {
        remembered[msaa] = timeClearPaths(device_, pass(msaa), *resolver_);
        if (!file.empty()) {
            const std::string text = encodeClearTimings(identity, remembered);
            if (const std::string error = util::writeFileAtomically(file, {text}); !error.empty())
                std::fprintf(stderr, "idview: warning: clear path timings not kept: %s\n",
                             error.c_str());
        }
        found = remembered.find(msaa);
    }
    clearTimings_[msaa] = found->second;
    return found->second.faster();
}

} // namespace render
