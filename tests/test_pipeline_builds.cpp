// test_pipeline_builds.cpp - the viewer's non-blocking path (Renderer::prepare, prepareHidden)
// on lavapipe with validation on: while a pipeline is being built on a worker, frames go on
// being recorded and submitted with the configuration drawn before, whose ID image they keep;
// once the build is done, the switch draws what a synchronous configure draws. The worker is
// held (Renderer::holdPipelineBuilds) for as long as the test wants "pending", and its end is
// waited for through the wake callback, never through time.
#include <gtest/gtest.h>

#include <condition_variable>
#include <mutex>

#include "app/offscreen.h"
#include "app/scene_source.h"
#include "image_compare.h"
#include "render/technique.h"
#include "scene/section.h"
#include "test_support.h"
#include "vk/check.h"

namespace {

using testing_support::sameIds;
using testing_support::settingsFor;
// The ID images' width (Rig draws 64x48).
constexpr uint32_t W = 64;

app::LoadedScene tiles() {
    app::SceneSettings source;
    source.builtin = "tiles";
    return app::loadScene(source);
}

// Counts the wake callbacks of the workers (called on them), and waits for a count.
class Wakes {
  public:
    std::function<void()> callback() {
        return [this] {
            {
                std::lock_guard lock(mutex_);
                ++count_;
            }
            woken_.notify_all();
        };
    }
    void waitFor(int count) {
        std::unique_lock lock(mutex_);
        woken_.wait(lock, [&] { return count_ >= count; });
    }

  private:
    std::mutex mutex_;
    std::condition_variable woken_;
    int count_ = 0;
};

struct Rig {
    explicit Rig(vk::Instance& instance) : rig(instance, testing_support::headlessOptions(W, 48)) {}
    // Records and submits a frame without waiting for it (as the viewer's loop does).
    void submit() {
        render::FrameParams params;
        params.viewProj = testing_support::flatViewProj();
        render::FrameSlot& slot = rig.slots.begin(frame++);
        rig.renderer.record(slot, rig.targets, params);
        rig.slots.submit(slot);
    }
    std::vector<uint32_t> ids() { return testing_support::renderIds(rig, frame); }

    app::Offscreen rig;
    uint64_t frame = 0;
};

// What a synchronous configure (headless, the benchmark) of `settings` with `hidden` draws.
std::vector<uint32_t> synchronousIds(vk::Instance& instance, const scene::Scene& scene,
                                     const render::RenderSettings& settings,
                                     const scene::PartSet& hidden) {
    Rig sync(instance);
    sync.rig.renderer.setScene(scene, settings);
    sync.rig.renderer.setHidden(hidden);
    return sync.ids();
}

render::RenderSettings withSection(render::RenderSettings settings) {
    settings.section.add(scene::axisPlane(0, 0.0f)); // through the middle of the tiles
    return settings;
}

// A rig drawing the plain settings, its builds waking `wakes`, and what it drew before any
// request: the start of the tests that ask for the section variant.
struct Drawing {
    Drawing(vk::Instance& instance, const scene::Scene& scene)
        : r(instance), renderer(r.rig.renderer) {
        renderer.onPipelineBuilt(wakes.callback());
        renderer.setScene(scene, plain);
        before = r.ids();
        old = renderer.pipeline();
    }
    const render::RenderSettings plain;
    const render::RenderSettings cut = withSection(plain);
    Rig r;
    Wakes wakes; // goes before the rig's renderer, which waits for its workers
    render::Renderer& renderer;
    std::vector<uint32_t> before;
    VkPipeline old = VK_NULL_HANDLE;
};

TEST(PipelineBuilds, FramesGoOnWithTheOldPipelineWhileTheFirstSectionCutBuilds) {
    const app::LoadedScene scene = tiles();
    vk::Instance instance({true, {}});
    {
        Drawing d(instance, scene.scene);

        d.renderer.holdPipelineBuilds(true);
        const auto build = d.renderer.prepare(scene.scene, d.cut);
        ASSERT_TRUE(build.has_value()) << "the section variant was not built yet";
        EXPECT_NE(build->name.find("section"), std::string::npos) << build->name;
        for (int i = 0; i < 6; ++i) {
            EXPECT_TRUE(d.renderer.prepare(scene.scene, d.cut).has_value())
                << "asked again, frame " << i;
            EXPECT_TRUE(d.renderer.building());
            d.r.submit(); // frames in flight, as the viewer's
            EXPECT_TRUE(sameIds(d.r.ids(), d.before, W))
                << "frame " << i << " draws the configuration before";
            EXPECT_EQ(d.renderer.pipeline(), d.old);
            EXPECT_EQ(d.renderer.settings(), d.plain);
        }

        d.renderer.holdPipelineBuilds(false);
        d.wakes.waitFor(1);
        EXPECT_FALSE(d.renderer.prepare(scene.scene, d.cut).has_value())
            << "built: ready to switch";
        EXPECT_FALSE(d.renderer.building()) << "its result was collected";
        d.renderer.configure(scene.scene, d.cut);
        EXPECT_TRUE(d.renderer.lastSwitch().pipelineCached) << "the worker's pipeline is used";
        EXPECT_NE(d.renderer.pipeline(), d.old);
        const std::vector<uint32_t> after = d.r.ids();
        EXPECT_FALSE(sameIds(after, d.before, W)) << "the cut shows in the ID image";
        EXPECT_TRUE(sameIds(after,
                            synchronousIds(instance, scene.scene, d.cut,
                                           scene::PartSet(scene.scene.uniquePartCount())),
                            W));
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
}

TEST(PipelineBuilds, HiddenPartsVanishOnlyOnceTheHidingVariantIsBuilt) {
    const app::LoadedScene scene = tiles();
    vk::Instance instance({true, {}});
    {
        const render::RenderSettings settings;
        scene::PartSet hidden(scene.scene.uniquePartCount());
        for (uint32_t id = 0; id < scene.scene.uniquePartCount(); id += 2) hidden.insert(id);
        ASSERT_FALSE(hidden.empty());
        Rig r(instance);
        Wakes wakes;
        render::Renderer& renderer = r.rig.renderer;
        renderer.onPipelineBuilt(wakes.callback());
        renderer.setScene(scene.scene, settings);
        const std::vector<uint32_t> before = r.ids();

        renderer.holdPipelineBuilds(true);
        ASSERT_TRUE(renderer.prepareHidden(hidden).has_value());
        for (int i = 0; i < 4; ++i) {
            r.submit();
            EXPECT_TRUE(sameIds(r.ids(), before, W)) << "frame " << i;
            EXPECT_TRUE(renderer.hidden().empty());
            EXPECT_TRUE(renderer.prepareHidden(hidden).has_value());
        }
        renderer.holdPipelineBuilds(false);
        wakes.waitFor(1);
        EXPECT_FALSE(renderer.prepareHidden(hidden).has_value());
        renderer.setHidden(hidden);
        const std::vector<uint32_t> after = r.ids();
        EXPECT_FALSE(sameIds(after, before, W)) << "half the parts are hidden";
        EXPECT_TRUE(sameIds(after, synchronousIds(instance, scene.scene, settings, hidden), W));
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
}

// The user switches again while a build runs: both builds finish into the cache, the newest
// wish is what the caller asks for next, and the stale one costs no compile later.
TEST(PipelineBuilds, AStaleBuildFinishesIntoTheCache) {
    const app::LoadedScene scene = tiles();
    vk::Instance instance({true, {}});
    {
        const auto techniques = render::partIdTechniques();
        ASSERT_GE(techniques.size(), 3u);
        const render::RenderSettings a = settingsFor(*techniques[0], render::drawModes()[0]);
        const render::RenderSettings b = settingsFor(*techniques[1], render::drawModes()[0]);
        const render::RenderSettings c = settingsFor(*techniques[2], render::drawModes()[0]);
        Rig r(instance);
        Wakes wakes;
        render::Renderer& renderer = r.rig.renderer;
        renderer.onPipelineBuilt(wakes.callback());
        renderer.setScene(scene.scene, a);
        renderer.holdPipelineBuilds(true);
        ASSERT_TRUE(renderer.prepare(scene.scene, b).has_value());
        ASSERT_TRUE(renderer.prepare(scene.scene, c).has_value());
        r.submit();
        renderer.holdPipelineBuilds(false);
        wakes.waitFor(2);
        EXPECT_FALSE(renderer.prepare(scene.scene, c).has_value());
        EXPECT_EQ(renderer.cachedPipelines(), 3u) << "a, and both builds";
        renderer.configure(scene.scene, c);
        EXPECT_TRUE(renderer.lastSwitch().pipelineCached);
        const uint64_t compiled = r.rig.compiler.compilations();
        renderer.configure(scene.scene, b);
        EXPECT_TRUE(renderer.lastSwitch().pipelineCached);
        EXPECT_EQ(r.rig.compiler.compilations(), compiled);
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
}

// A build that fails on its worker reports its error through the next prepare, once; the
// pipeline drawn stays, and asking again builds it anew.
TEST(PipelineBuilds, AFailedBuildKeepsTheLastGoodPipeline) {
    const app::LoadedScene scene = tiles();
    vk::Instance instance({true, {}});
    {
        Drawing d(instance, scene.scene);

        d.renderer.holdPipelineBuilds(true);
        ASSERT_TRUE(d.renderer.prepare(scene.scene, d.cut).has_value());
        vk::failAfter(1); // the worker's first fault point: its first shader compile
        d.renderer.holdPipelineBuilds(false);
        d.wakes.waitFor(1);
        vk::failAfter(0);
        EXPECT_THROW(d.renderer.prepare(scene.scene, d.cut), vk::Error);
        EXPECT_EQ(d.renderer.pipeline(), d.old);
        EXPECT_TRUE(sameIds(d.r.ids(), d.before, W));
        EXPECT_TRUE(d.renderer.prepare(scene.scene, d.cut).has_value()) << "built again";
        d.wakes.waitFor(2);
        EXPECT_FALSE(d.renderer.prepare(scene.scene, d.cut).has_value());
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
}

} // namespace
