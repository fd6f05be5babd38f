// test_switching.cpp - what a switch costs and what it leaves behind, on lavapipe with
// validation on: a pipeline used before comes from the cache (no compile), R empties every
// cache level, no switch waits for the frames in flight (idview calls no waiting Vulkan
// function during it, a switch that builds no pipeline returns with their fence still
// unsignalled, and validation reports any object destroyed under them), and a throw at any
// fault point of a switch leaks nothing and keeps the previous configuration drawing.
#include <gtest/gtest.h>

#include <dlfcn.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <functional>
#include <mutex>

#include "app/offscreen.h"
#include "app/scene_source.h"
#include "image_compare.h"
#include "render/technique.h"
#include "test_support.h"
#include "util/deadline.h"
#include "vk/check.h"

// Every call of this test binary (idview_core is linked into it) to a Vulkan function that
// blocks the host until the GPU gets somewhere lands here first, is counted, and goes on to
// the loader's. Fence polls (timeout 0) do not count.
std::atomic<int> hostWaits{0};

template <typename Fn>
Fn loaderFunction(const char* name) {
    return reinterpret_cast<Fn>(dlsym(RTLD_NEXT, name));
}

// Frames held in flight for as long as the test likes, not as long as lavapipe takes to draw
// them: while the gate is armed, every command buffer begun waits first for an event the host
// sets (outside a render pass, which Vulkan allows), and stays unfinished until the gate
// opens. While a switch runs (watched), the waiting functions below open the gate first, so
// that a switch that waits fails its checks instead of hanging; a wait they do not see (a
// driver lock: lavapipe builds a pipeline under the lock its queue thread holds while it runs
// a frame) has the gate opened after a minute (Lifetimes' safety net).
class FrameGate {
  public:
    void create(VkDevice device) {
        device_ = device;
        const auto info = vk::init<VkEventCreateInfo>(VK_STRUCTURE_TYPE_EVENT_CREATE_INFO);
        vk::check(vkCreateEvent(device, &info, nullptr, &event_), "vkCreateEvent");
    }
    void destroy() {
        vkDestroyEvent(device_, event_, nullptr);
        event_ = VK_NULL_HANDLE;
    }
    // Command buffers begun from now on (vkBeginCommandBuffer below) wait for the gate.
    void arm(bool on) {
        const std::lock_guard lock(mutex_);
        armed_ = on;
    }
    void waitFor(VkCommandBuffer cmd) {
        const std::lock_guard lock(mutex_);
        if (!armed_) return;
        vkCmdWaitEvents(cmd, 1, &event_, VK_PIPELINE_STAGE_HOST_BIT,
                        VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, nullptr, 0, nullptr, 0, nullptr);
        holding_ = true;
    }
    // While a switch runs.
    void watch(bool on) {
        const std::lock_guard lock(mutex_);
        watching_ = on;
    }
    // A wait for the GPU.
    void onWait() {
        const std::lock_guard lock(mutex_);
        if (watching_) openLocked();
    }
    void open() {
        const std::lock_guard lock(mutex_);
        openLocked();
    }
    // Once the held frames have finished: closed again for the next ones.
    void reset() {
        const std::lock_guard lock(mutex_);
        vkResetEvent(device_, event_);
    }

  private:
    void openLocked() {
        if (holding_) vkSetEvent(device_, event_);
        holding_ = false;
    }

    std::mutex mutex_;
    VkDevice device_ = VK_NULL_HANDLE;
    VkEvent event_ = VK_NULL_HANDLE;
    bool armed_ = false, holding_ = false, watching_ = false;
};
FrameGate gate;

extern "C" {
VKAPI_ATTR VkResult VKAPI_CALL vkWaitForFences(VkDevice device, uint32_t count,
                                               const VkFence* fences, VkBool32 waitAll,
                                               uint64_t timeout) {
    if (timeout > 0) {
        ++hostWaits;
        gate.onWait();
    }
    static const auto next = loaderFunction<PFN_vkWaitForFences>("vkWaitForFences");
    return next(device, count, fences, waitAll, timeout);
}
VKAPI_ATTR VkResult VKAPI_CALL vkQueueWaitIdle(VkQueue queue) {
    ++hostWaits;
    gate.onWait();
    static const auto next = loaderFunction<PFN_vkQueueWaitIdle>("vkQueueWaitIdle");
    return next(queue);
}
VKAPI_ATTR VkResult VKAPI_CALL vkDeviceWaitIdle(VkDevice device) {
    ++hostWaits;
    gate.onWait();
    static const auto next = loaderFunction<PFN_vkDeviceWaitIdle>("vkDeviceWaitIdle");
    return next(device);
}
VKAPI_ATTR VkResult VKAPI_CALL vkWaitSemaphores(VkDevice device, const VkSemaphoreWaitInfo* info,
                                                uint64_t timeout) {
    if (timeout > 0) {
        ++hostWaits;
        gate.onWait();
    }
    static const auto next = loaderFunction<PFN_vkWaitSemaphores>("vkWaitSemaphores");
    return next(device, info, timeout);
}
VKAPI_ATTR VkResult VKAPI_CALL vkBeginCommandBuffer(VkCommandBuffer cmd,
                                                    const VkCommandBufferBeginInfo* info) {
    static const auto next = loaderFunction<PFN_vkBeginCommandBuffer>("vkBeginCommandBuffer");
    const VkResult result = next(cmd, info);
    if (result == VK_SUCCESS) gate.waitFor(cmd);
    return result;
}
}

namespace {

using testing_support::settingsFor;

app::LoadedScene load(const char* spec, uint32_t copies = 1) {
    app::SceneSettings source;
    source.builtin = spec;
    source.copies = copies;
    return app::loadScene(source);
}

// Two part-ID techniques whose draw lists agree (same split and ID data) but whose pipelines
// differ, if the registry has such a pair (the fs and gs forms of one lookup).
std::pair<const render::Technique*, const render::Technique*> sameDrawsPair() {
    for (const render::Technique* a : render::partIdTechniques())
        for (const render::Technique* b : render::partIdTechniques())
            if (a != b && a->split == b->split && a->ids == b->ids &&
                a->primitives == b->primitives && a->stage != b->stage)
                return {a, b};
    return {nullptr, nullptr};
}

struct Frames {
    app::Offscreen& rig;
    uint64_t next = 0;

    // Records and submits one frame; returns its number.
    uint64_t submit() {
        render::FrameParams params;
        params.viewProj = testing_support::flatViewProj();
        params.pickPixel = glm::uvec2(1, 1);
        render::FrameSlot& slot = rig.slots.begin(next);
        rig.renderer.record(slot, rig.targets, params);
        rig.slots.submit(slot);
        return next++;
    }
    // One frame, waited for, and its ID image.
    std::vector<uint32_t> ids() { return testing_support::renderIds(rig, next); }
};

TEST(PipelineCache, SwitchingBackIsALookupAndRClearsEveryLevel) {
    const app::LoadedScene tiles = load("tiles");
    app::Options o = testing_support::headlessOptions(64, 48);
    vk::Instance instance({true, {}});
    {
        app::Offscreen rig(instance, o);
        const auto techniques = render::partIdTechniques();
        ASSERT_GE(techniques.size(), 2u);
        const render::RenderSettings a = settingsFor(*techniques.front(), render::drawModes()[0]);
        const render::RenderSettings b = settingsFor(*techniques.back(), render::drawModes()[1]);

        rig.renderer.setScene(tiles.scene, a);
        EXPECT_FALSE(rig.renderer.lastSwitch().pipelineCached);
        const VkPipeline first = rig.renderer.pipeline();
        rig.renderer.configure(tiles.scene, b);
        EXPECT_FALSE(rig.renderer.lastSwitch().pipelineCached);
        EXPECT_FALSE(rig.renderer.lastSwitch().drawsKept);
        EXPECT_EQ(rig.renderer.cachedPipelines(), 2u);

        // Back to a: the same pipeline object, no glslang run, no driver compile.
        const uint64_t compiled = rig.compiler.compilations();
        rig.renderer.configure(tiles.scene, a);
        EXPECT_TRUE(rig.renderer.lastSwitch().pipelineCached);
        EXPECT_EQ(rig.renderer.pipeline(), first);
        EXPECT_EQ(rig.compiler.compilations(), compiled);
        EXPECT_GE(rig.renderer.lastSwitch().ms, 0.0);

        // What a technique does not read selects nothing: no new pipeline, draws kept.
        render::RenderSettings shaded = a;
        shaded.shading.colorizeDraws = true;
        shaded.shading.partWeight = 0.25f;
        if (!a.pipeline.technique->narySearch) shaded.pipeline.nsearch.n += 1;
        rig.renderer.configure(tiles.scene, shaded);
        EXPECT_TRUE(rig.renderer.lastSwitch().pipelineCached);
        EXPECT_TRUE(rig.renderer.lastSwitch().drawsKept);
        EXPECT_EQ(rig.renderer.pipeline(), first);
        EXPECT_EQ(rig.renderer.cachedPipelines(), 2u);

        // The fs and gs forms of a lookup share their draw list.
        const auto [fs, gs] = sameDrawsPair();
        if (fs) {
            rig.renderer.configure(tiles.scene, settingsFor(*fs, render::drawModes()[0]));
            rig.renderer.configure(tiles.scene, settingsFor(*gs, render::drawModes()[0]));
            EXPECT_TRUE(rig.renderer.lastSwitch().drawsKept) << fs->name << " / " << gs->name;
            EXPECT_FALSE(rig.renderer.lastSwitch().pipelineCached);
        }

        // R: the pipelines and the SPIR-V are forgotten (the driver's cache stays: it is
        // keyed by the shaders' code); only the current pipeline is built again, and going
        // back to b compiles anew.
        rig.renderer.configure(tiles.scene, a);
        const uint64_t beforeReload = rig.compiler.compilations();
        rig.renderer.reloadShaders();
        EXPECT_EQ(rig.renderer.cachedPipelines(), 1u);
        EXPECT_GT(rig.compiler.compilations(), beforeReload);
        const uint64_t afterReload = rig.compiler.compilations();
        rig.renderer.configure(tiles.scene, b);
        EXPECT_FALSE(rig.renderer.lastSwitch().pipelineCached);
        EXPECT_GT(rig.compiler.compilations(), afterReload);

        Frames frames{rig};
        const auto ids = frames.ids();
        EXPECT_GT(ids.size() - std::count(ids.begin(), ids.end(), gpu::BACKGROUND_ID), 0u)
            << "the tiles are drawn";
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
}

// Each switch happens while two heavy frames are in flight (lavapipe: most of a second each).
// idview must call nothing that waits for the GPU during any switch. Where the switch builds
// no pipeline, the frames are held (FrameGate) until it has returned, which the later one's
// fence must show unsignalled then, however slow the machine. (Mesa 25's lavapipe compiles a
// pipeline under the lock its queue thread holds while it runs a submission, so inside
// vkCreateGraphicsPipelines the driver itself waits for the frames in flight; there the
// frames are not held and the fence says nothing about idview.) Validation on: an object
// destroyed while a frame in flight uses it is an error.
TEST(Lifetimes, NoSwitchWaitsForTheFramesInFlight) {
    const app::LoadedScene heavy = load("procedural:preset=small,seed=1", 64);
    const app::LoadedScene light = load("procedural:preset=small,seed=1");
    app::Options o = testing_support::headlessOptions(256, 256);
    vk::Instance instance({true, {}});
    {
        app::Offscreen rig(instance, o);
        Frames frames{rig};
        const auto techniques = render::partIdTechniques();
        // Per draw and per part: the heaviest frame to record and draw.
        render::RenderSettings settings =
            settingsFor(render::defaultTechnique(), render::defaultDrawMode());
        rig.renderer.setScene(heavy.scene, settings);
        frames.submit(); // compiles what lavapipe compiles at the first draw
        rig.slots.finish();

        struct Switch {
            const char* what;
            std::function<void()> run;
            bool buildsPipeline;
        };
        render::RenderSettings other = settingsFor(*techniques.back(), render::drawModes()[1]);
        render::RenderSettings msaa = settings;
        msaa.pipeline.msaa = 4;
        const std::vector<Switch> switches = {
            {"technique and mode (built)", [&] { rig.renderer.configure(heavy.scene, other); },
             true},
            {"technique and mode (cached)", [&] { rig.renderer.configure(heavy.scene, settings); },
             false},
            {"MSAA",
             [&] {
                 rig.renderer.configure(heavy.scene, msaa);
                 rig.useMsaa(4);
             },
             true},
            {"reload (R)", [&] { rig.renderer.reloadShaders(); }, true},
            {"scene", [&] { rig.renderer.setScene(light.scene, msaa); }, false}, // light frames
        };
        gate.create(rig.device.handle());
        for (const Switch& s : switches) {
            rig.useMsaa(rig.renderer.settings().pipeline.msaa);
            gate.arm(!s.buildsPipeline);
            frames.submit();
            const uint64_t last = frames.submit();
            gate.arm(false);
            hostWaits = 0;
            {
                // Should the switch wait for the held frames in a way the gate does not see (a
                // driver lock), the gate opens after a minute, and the switch fails its
                // checks instead of hanging. A switch that waits for nothing takes milliseconds.
                const util::Deadline safetyNet(std::chrono::minutes(1), [] { gate.open(); });
                gate.watch(true);
                s.run();
                gate.watch(false);
            }
            EXPECT_EQ(hostWaits.load(), 0) << s.what << " waited for the GPU";
            if (!s.buildsPipeline) {
                EXPECT_FALSE(rig.slots.finished(last)) << s.what << " waited for the GPU";
            }
            gate.open();
            rig.slots.finish();
            gate.reset();
        }
        gate.destroy();
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
}

// A throw at every fault point a switch passes, one after the other: the switch fails in
// words, the configuration before it keeps drawing the same image with the same device
// memory, and the validation layer finds no object left at teardown.
TEST(FaultInjection, AThrowAnywhereInASwitchLeaksNothing) {
    const app::LoadedScene tiles = load("tiles");
    const app::LoadedScene assembly = load("assembly", 2);
    app::Options o = testing_support::headlessOptions(64, 48);
    vk::Instance instance({true, {}});
    uint32_t points = 0;
    {
        app::Offscreen rig(instance, o);
        Frames frames{rig};
        const render::RenderSettings start =
            settingsFor(render::defaultTechnique(), render::defaultDrawMode());
        // What each state the switch passes through draws and holds.
        struct State {
            std::vector<uint32_t> ids;
            int64_t bytes;
        };
        auto stateOf = [&](const app::LoadedScene& loaded) {
            rig.renderer.setScene(loaded.scene, start);
            const std::vector<uint32_t> ids = frames.ids();
            return State{ids, rig.device.liveMemory().bytes};
        };
        const State onAssembly = stateOf(assembly), onTiles = stateOf(tiles);
        ASSERT_FALSE(testing_support::sameIds(onAssembly.ids, onTiles.ids, o.width));

        // The switch: another scene, then a technique, mode and MSAA not used yet, from empty
        // caches, so that every kind of object gets made: buffers, uploads, shaders, pipelines,
        // a render pass.
        render::RenderSettings next =
            settingsFor(*render::partIdTechniques().back(), render::drawModes().back());
        next.pipeline.msaa = 4;
        for (uint32_t n = 1;; ++n) {
            ASSERT_LT(n, 1000u) << "the switch never completed";
            rig.renderer.reloadShaders();
            rig.renderer.setScene(tiles.scene, start);
            rig.slots.finish();
            const State* expected = &onTiles;
            vk::failAfter(n);
            bool threw = false;
            try {
                rig.renderer.setScene(assembly.scene, start);
                expected = &onAssembly;
                rig.renderer.configure(assembly.scene, next);
            } catch (const vk::Error& e) {
                threw = true;
                EXPECT_NE(std::string(e.what()).find("injected fault at"), std::string::npos)
                    << e.what();
            }
            const uint32_t passed = vk::faultPointsPassed();
            vk::failAfter(0);
            if (!threw) {
                points = n - 1;
                EXPECT_LT(passed, n); // every point was reached and passed
                break;
            }
            const std::string where = "after a fault at point " + std::to_string(n);
            EXPECT_EQ(rig.renderer.settings(), start) << where;
            EXPECT_TRUE(testing_support::sameIds(frames.ids(), expected->ids, o.width)) << where;
            EXPECT_EQ(rig.device.liveMemory().bytes, expected->bytes) << where;
        }
    }
    std::printf("a throw at each of %u fault points of the switch\n", points);
    EXPECT_GE(points, 20u) << "too few fault points to mean anything";
    EXPECT_EQ(instance.validationMessages(), 0u); // objects left at vkDestroyDevice count
}

} // namespace
