// test_cad_progressive.cpp - a STEP assembly drawn while it loads (scene::CadPartial): a part
// picked in a partial scene, on lavapipe, is the same part (unique ID, object, B-rep face) when
// the load has finished, and the partial scene draws only the solids meshed so far.
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "scene/cad/cad_loader.h"
#include "scene/camera.h"
#include "test_data.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;

// Five deep copies of screw.step, one piece each, by idview-step-copies.
fs::path screws() {
    const fs::path sample = "/usr/share/opencascade/data/step/screw.step";
    if (!fs::exists(sample)) ADD_FAILURE() << testing_support::missingData(sample);
    // Not cad_test_parts.h's folder: its Open CASCADE headers' Handle macro meets Vulkan's here.
    const fs::path out =
        fs::temp_directory_path() / ("idview_progressive_" + std::to_string(::getpid()) + ".step");
    const std::string command = std::string(IDVIEW_STEP_COPIES) + " -n 5 -o '" + out.string() +
                                "' '" + sample.string() + "'";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    return out;
}

struct Removed {
    fs::path path;
    ~Removed() {
        std::error_code ignored;
        fs::remove(path, ignored);
    }
};

scene::Bounds unite(const std::vector<scene::Bounds>& boxes) {
    scene::Bounds all{glm::dvec3(1e300), glm::dvec3(-1e300)};
    for (const scene::Bounds& b : boxes) {
        all.min = glm::min(all.min, b.min);
        all.max = glm::max(all.max, b.max);
    }
    return all;
}

} // namespace

TEST(CadProgressive, APartPickedWhileItLoadsIsThatPartOnceLoaded) {
    scene::CadOptions options;
    options.workers = 2;
    std::optional<scene::CadPartial> some; // a partial scene with some solids, not all
    const Removed file{screws()};
    const scene::CadLoadResult done = scene::loadCad(
        file.path.string(), options, {}, 1, nullptr, [&](const scene::CadPartial& p) {
            if (!some && p.solidsReady > 0 && p.solidsReady < p.solidsTotal) some = p;
        });
    ASSERT_TRUE(some) << "no partial scene with some of the solids";
    // The camera frames the whole assembly from the boxes, as the viewer does at once.
    const scene::Camera camera =
        scene::fitCamera(unite(some->boxes), glm::dvec3(0.9, -1.6, 1.2), glm::dvec3(0, 0, 1),
                         glm::radians(40.0f), 160.0 / 96.0);
    app::Options o = testing_support::headlessOptions(160, 96);
    const app::HeadlessResult partial = app::renderHeadless(o, *some->scene, camera);
    // Only meshed solids draw; up to six pixels of them, spread over the image, are picked.
    for (uint32_t id : partial.ids) {
        if (id == gpu::BACKGROUND_ID) continue;
        const auto ref = some->scene->locate(id);
        ASSERT_TRUE(ref) << id;
        EXPECT_EQ(some->state[ref->object], scene::kObjectReady) << id;
    }
    for (size_t i = 0; i < partial.ids.size() && o.picks.size() < 6; i += 37)
        if (partial.ids[i] != gpu::BACKGROUND_ID)
            o.picks.push_back({uint32_t(i % 160), uint32_t(i / 160)});
    ASSERT_GE(o.picks.size(), 3u);
    const app::HeadlessResult early = app::renderHeadless(o, *some->scene, camera);
    const app::HeadlessResult late = app::renderHeadless(o, done.scene, camera);
    ASSERT_EQ(early.picks.size(), o.picks.size());
    ASSERT_EQ(late.picks.size(), o.picks.size());
    size_t same = 0;
    for (size_t i = 0; i < o.picks.size(); ++i) {
        ASSERT_TRUE(early.picks[i].part);
        ASSERT_TRUE(late.picks[i].part);
        const auto before = scene::describePart(*some->scene, *early.picks[i].part);
        const auto after = scene::describePart(done.scene, *early.picks[i].part);
        ASSERT_TRUE(before && after);
        // The ID names the same object and face in both scenes.
        EXPECT_EQ(before->path, after->path);
        EXPECT_EQ(before->face, after->face);
        EXPECT_EQ(before->triangleCount, after->triangleCount);
        // And the finished scene shows it there, unless a solid meshed since lies in front.
        const auto late_ = scene::describePart(done.scene, *late.picks[i].part);
        const uint32_t lateObject = late_->object;
        same += *late.picks[i].part == *early.picks[i].part;
        if (*late.picks[i].part != *early.picks[i].part) {
            EXPECT_NE(some->state[lateObject], scene::kObjectReady) << "pick " << i;
        }
    }
    EXPECT_GT(same, 0u);
    EXPECT_EQ(partial.validationMessages, 0u);
    EXPECT_EQ(late.validationMessages, 0u);
}
