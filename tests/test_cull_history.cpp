// test_cull_history.cpp - each culling history is a buffer of its own with one writer per
// pass (shared_cull.h's History), read back from the GPU after every frame of a camera path
// over the default model that sees it whole, flies into it (so the history shrinks), backs
// out and stands still; lavapipe, validation on.
// - Runs (vertex-fs, mdi-baseinstance): the slot of history ends the late pass wrote holds,
//   per object, one more than its last pair with history, counted on the CPU from the
//   read-back pair history; the other slot still holds what the frame before wrote.
// - Mesh draws (mesh-fs, mdi-baseinstance): the meshlets the late pass chose are exactly
//   those with history now that the early pass did not draw (no history before, or their
//   draw not drawn early).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstring>

#include "app/camera_frame.h"
#include "app/headless.h"
#include "app/offscreen.h"
#include "app/scene_source.h"
#include "render/technique.h"
#include "test_support.h"
#include "vk/barrier.h"

namespace {

constexpr uint32_t W = 160, H = 90;

// A copy of `buffer` on the host, once every command submitted before has finished.
template <typename T>
std::vector<T> readBack(vk::Device& device, const vk::Buffer& buffer) {
    vk::Buffer host =
        vk::hostBuffer(device, buffer.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, "history readback");
    device.submitNow([&](VkCommandBuffer cmd) {
        vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT,
                          VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
        const VkBufferCopy region{0, 0, buffer.size()};
        vkCmdCopyBuffer(cmd, buffer.handle(), host.handle(), 1, &region);
        vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
    });
    std::vector<T> values(buffer.size() / sizeof(T));
    std::memcpy(values.data(), host.mapped(), values.size() * sizeof(T));
    return values;
}

// The path: the fitted view, three quarters of the way to the target (most of the model
// leaves the view), the fitted view again, and standing there.
std::vector<scene::Camera> cameraPath(const app::LoadedScene& loaded) {
    const scene::Camera fitted = app::initialCamera(loaded, float(W) / float(H));
    scene::Camera inside = fitted;
    inside.eye = fitted.target + (fitted.eye - fitted.target) / 4.0;
    scene::fitPlanes(inside, loaded.scene.bounds());
    return {fitted, inside, fitted, fitted};
}

// Flies the path with `technique` in mdi-baseinstance and occlusion culling, calling
// `before(rig, cull)` once the list is built and `check(rig, cull, frame)` after each frame
// has finished; no validation message may come.
template <typename Before, typename Check>
void alongThePath(const char* technique, Before&& before, Check&& check) {
    const app::LoadedScene loaded = app::loadScene(app::SceneSettings{});
    render::RenderSettings settings = testing_support::settingsFor(
        *render::findTechnique(technique), *render::findDrawMode("mdi-baseinstance"));
    settings.culling.mode = render::CullMode::Occlusion;
    app::Options o = testing_support::headlessOptions(W, H);
    o.live.render = settings;
    vk::Instance instance({true, {}, false});
    {
        app::Offscreen rig(instance, o);
        rig.renderer.setScene(loaded.scene, settings);
        const render::CullBuffers& cull = *rig.renderer.drawBuffers()->cull;
        before(rig, cull);
        uint64_t frame = 0;
        for (const scene::Camera& camera : cameraPath(loaded)) {
            render::FrameSlot& slot = rig.slots.begin(frame++);
            rig.renderer.record(slot, rig.targets, app::cameraFrame(camera, rig.extent));
            rig.slots.submit(slot);
            rig.slots.finish();
            check(rig, cull, frame);
        }
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
}

// Per object, one more than its last pair with history (0: none), from the pair history.
std::vector<uint32_t> endsOnTheCpu(const std::vector<uint32_t>& pairHistory,
                                   const std::vector<uint32_t>& drawOfPair,
                                   const std::vector<gpu::DrawData>& draws, uint32_t objects) {
    std::vector<uint32_t> ends(objects, 0);
    for (uint32_t pair = 0; pair < pairHistory.size(); ++pair)
        if (pairHistory[pair] != 0) ends[draws[drawOfPair[pair]].objectIndex] = pair + 1;
    return ends;
}

TEST(CullHistory, TheHistoryEndsAreThoseOfThePairHistoryInTheSlotTheLatePassWrote) {
    std::vector<uint32_t> drawOfPair, endsBefore;
    std::vector<gpu::DrawData> draws;
    size_t withHistory = 0, without = 0, shrunk = 0;
    auto before = [&](app::Offscreen& rig, const render::CullBuffers& cull) {
        ASSERT_TRUE(cull.clusterRuns);
        drawOfPair = readBack<uint32_t>(rig.device, cull.pairs);
        draws = readBack<gpu::DrawData>(rig.device, rig.renderer.drawBuffers()->draws);
        endsBefore.assign(cull.objectCount, 0);
    };
    auto check = [&](app::Offscreen& rig, const render::CullBuffers& cull, uint64_t frame) {
        const auto pairHistory = readBack<uint32_t>(rig.device, cull.pairHistory);
        const auto slots = readBack<uint32_t>(rig.device, cull.historyEnds);
        const uint32_t n = cull.objectCount, written = rig.renderer.historySlot().early;
        const std::vector<uint32_t> ends(slots.begin() + written * n,
                                         slots.begin() + (written + 1) * n);
        const std::vector<uint32_t> other(slots.begin() + (1 - written) * n,
                                          slots.begin() + (2 - written) * n);
        EXPECT_EQ(ends, endsOnTheCpu(pairHistory, drawOfPair, draws, n)) << "frame " << frame;
        EXPECT_EQ(other, endsBefore) << "frame " << frame << ": the early pass's slot";
        withHistory += size_t(std::count(pairHistory.begin(), pairHistory.end(), 1u));
        without += size_t(std::count(pairHistory.begin(), pairHistory.end(), 0u));
        for (uint32_t o = 0; o < n; ++o) shrunk += ends[o] < endsBefore[o];
        endsBefore = ends;
    };
    alongThePath("vertex-fs", before, check);
    // Not vacuous: clusters with and without history, and ends that moved back, which a slot
    // not zeroed before its late pass would keep where they were.
    EXPECT_GT(withHistory, 0u);
    EXPECT_GT(without, 0u);
    EXPECT_GT(shrunk, 0u);
}

TEST(CullHistory, TheLatePassChoosesTheMeshletsWithHistoryTheEarlyPassDidNotDraw) {
    std::vector<gpu::DrawCull> drawCull;
    std::vector<uint32_t> historyBefore;
    size_t chosen = 0, keptFromBefore = 0, lost = 0;
    auto before = [&](app::Offscreen& rig, const render::CullBuffers& cull) {
        ASSERT_GT(cull.meshletWords, 0u);
        drawCull = readBack<gpu::DrawCull>(rig.device, cull.draws);
        historyBefore.assign(cull.meshletWords, 0);
    };
    auto check = [&](app::Offscreen& rig, const render::CullBuffers& cull, uint64_t frame) {
        const auto history = readBack<uint32_t>(rig.device, cull.meshletHistory);
        const auto late = readBack<uint32_t>(rig.device, cull.lateMeshlets);
        const auto state = readBack<uint32_t>(rig.device, cull.state);
        for (uint32_t d = 0; d < cull.drawCount; ++d) {
            const gpu::DrawCull& c = drawCull[d];
            const bool early = (state[d] & gpu::CULL_EARLY) != 0;
            for (uint32_t w = c.meshletBit / 32; w < (c.meshletBit + c.meshletCount + 31) / 32;
                 ++w) {
                const uint32_t drawnEarly = early ? historyBefore[w] : 0u;
                EXPECT_EQ(late[w], history[w] & ~drawnEarly)
                    << "frame " << frame << ", draw " << d << ", word " << w;
                chosen += size_t(std::popcount(late[w]));
                keptFromBefore += size_t(std::popcount(history[w] & drawnEarly));
                lost += size_t(std::popcount(historyBefore[w] & ~history[w]));
            }
        }
        historyBefore = history;
    };
    alongThePath("mesh-fs", before, check);
    EXPECT_GT(chosen, 0u);
    EXPECT_GT(keptFromBefore, 0u);
    EXPECT_GT(lost, 0u);
}

} // namespace
