// test_clear_choice.cpp - ClearPath::Auto's timings file (render/clear_choice.h): written and
// read back, refused when another driver or a damaged file wrote it; and on lavapipe, a
// renderer at Auto follows what the file beside its pipeline cache says and times the paths
// again when the file is of another driver.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <optional>
#include <tuple>

#include "app/offscreen.h"
#include "app/scene_source.h"
#include "cad_test_parts.h"
#include "render/clear_choice.h"
#include "test_support.h"
#include "util/cache_file.h"

namespace {

using render::ClearPath;
using render::ClearTiming;

render::PipelineCacheIdentity someDriver() {
    render::PipelineCacheIdentity id;
    id.vendorId = 0x10de;
    id.deviceId = 0x2330;
    id.driverVersion = 2435301632u;
    for (size_t i = 0; i < id.uuid.size(); ++i) id.uuid[i] = uint8_t(17 * i);
    return id;
}

TEST(ClearTimings, ComeBackAsWrittenAndSayWhichIsFaster) {
    const auto id = someDriver();
    std::map<uint32_t, ClearTiming> timings;
    timings[1] = {1, 0.4502, 0.1694};
    timings[4] = {4, 0.6, 2.0865};
    const auto back = render::decodeClearTimings(render::encodeClearTimings(id, timings), id);
    ASSERT_EQ(back.size(), 2u);
    for (const auto& [samples, t] : timings) {
        ASSERT_TRUE(back.count(samples));
        EXPECT_EQ(back.at(samples).samples, samples);
        EXPECT_DOUBLE_EQ(back.at(samples).passMs, t.passMs);
        EXPECT_DOUBLE_EQ(back.at(samples).computeMs, t.computeMs);
        EXPECT_TRUE(back.at(samples).remembered);
    }
    EXPECT_EQ(back.at(1).faster(), ClearPath::Compute);
    EXPECT_EQ(back.at(4).faster(), ClearPath::Pass);
}

TEST(ClearTimings, AnotherDriverOrADamagedFileReadsAsNothing) {
    const auto id = someDriver();
    const std::string text = render::encodeClearTimings(id, {{4, {4, 2.0, 0.6}}});
    auto newer = id;
    newer.driverVersion += 1;
    EXPECT_TRUE(render::decodeClearTimings(text, newer).empty()) << "a new driver times again";
    EXPECT_EQ(render::decodeClearTimings(text, id).size(), 1u);
    for (const std::string& damaged :
         {text + "4 2.0\n", text + "3 1.0 1.0\n", text + "8 -1 2\n", text + "2 1 1 1\n",
          std::string("idview clear paths 0 driver 1\n4 1 2\n"), std::string()})
        EXPECT_TRUE(render::decodeClearTimings(damaged, id).empty()) << damaged;
}

TEST(ClearTimings, TheFileIsNamedForTheDeviceAndDriverBesideThePipelineCache) {
    const auto id = someDriver();
    const std::string name = render::clearTimingFileName(id);
    const std::string pipelines = render::pipelineFileName(id);
    EXPECT_EQ(name.rfind("clear-paths-", 0), 0u) << name;
    EXPECT_EQ(name.substr(name.size() - 4), ".txt");
    // The same device and driver part as the pipeline cache's file.
    EXPECT_EQ(name.substr(11, name.size() - 15), pipelines.substr(9, pipelines.size() - 13));
    auto other = id;
    other.uuid[3] ^= 1;
    EXPECT_NE(render::clearTimingFileName(other), name);
}

// The renderer at Auto with what `text` makes of this device's identity (nothing: no file) in
// the timings file beside its pipeline cache: the path it draws with at `msaa`, and the
// timing it reports.
using FileText = std::function<std::optional<std::string>(const render::PipelineCacheIdentity&)>;
std::pair<ClearPath, ClearTiming> autoWith(const std::filesystem::path& home, uint32_t msaa,
                                           const FileText& text) {
    cadtest::CacheHome cacheHome(home);
    app::Options o = testing_support::headlessOptions(32, 24);
    o.live.scene.builtin = "procedural:preset=small";
    o.live.render.clear = ClearPath::Auto;
    o.live.render.pipeline.msaa = msaa;
    vk::Instance instance({true, {}, false});
    std::pair<ClearPath, ClearTiming> result;
    {
        app::Offscreen rig(instance, o);
        const auto id = render::pipelineCacheIdentity(rig.device.physical());
        const auto file =
            rig.renderer.driverCache().file().parent_path() / render::clearTimingFileName(id);
        std::filesystem::remove(file);
        if (const auto contents = text(id)) {
            EXPECT_EQ(util::writeFileAtomically(file, {*contents}), "");
        }
        const app::LoadedScene loaded = app::loadScene(o.live.scene);
        rig.renderer.setScene(loaded.scene, o.live.render);
        result.first = rig.renderer.clearPath();
        result.second = rig.renderer.clearTiming(msaa).value_or(ClearTiming{});
        EXPECT_TRUE(std::filesystem::exists(file)) << "the timings are kept";
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
    return result;
}

TEST(ClearTimingsOnLavapipe, AutoFollowsTheFileAndTimesAgainForAnotherDriver) {
    const auto home = std::filesystem::temp_directory_path() / "idview-clear-choice-test";
    std::filesystem::remove_all(home);
    // What the file says is what Auto draws with, either way round, untimed.
    for (const auto& [pass, compute, expected] :
         {std::tuple{9.0, 1.0, ClearPath::Compute}, std::tuple{1.0, 9.0, ClearPath::Pass}}) {
        const auto [path, timing] = autoWith(home, 4, [&](const auto& id) {
            return render::encodeClearTimings(id, {{4, {4, pass, compute}}});
        });
        EXPECT_EQ(path, expected);
        EXPECT_TRUE(timing.remembered);
        EXPECT_DOUBLE_EQ(timing.passMs, pass);
    }
    // Another driver's file: timed again on this one, and the file rewritten for it.
    const auto [path, timing] = autoWith(home, 1, [](auto id) {
        id.driverVersion ^= 1;
        return render::encodeClearTimings(id, {{1, {1, 9.0, 1.0}}});
    });
    EXPECT_FALSE(timing.remembered);
    EXPECT_GT(timing.passMs, 0.0);
    EXPECT_GT(timing.computeMs, 0.0);
    EXPECT_NE(timing.passMs, 9.0);
    EXPECT_EQ(path, timing.faster());
    // No file at all: timed.
    const auto [again, timed] = autoWith(home, 1, [](const auto&) { return std::nullopt; });
    EXPECT_FALSE(timed.remembered);
    EXPECT_EQ(again, timed.faster());
    std::filesystem::remove_all(home);
}

} // namespace
