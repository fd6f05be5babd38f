// test_far_pick.cpp - picks far from the origin (issue 35): the building of
// tests/far_building.py at UTM coordinates and the machine of idview_far_step_writer placed
// kilometres away, each seen by its fitted camera. At pixels deep inside parts the GPU pick
// names the part the CPU ray cast hits, at the point the ray cast finds, and that point is the
// origin model's pick point plus the offset; tolerances are fractions of the model's size,
// never of how far it lies from the origin. IDVIEW_FAR_OFFSET_SCALE=0 checks the test itself.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>

#include "app/headless.h"
#include "app/scene_source.h"
#include "scene/raycast.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;

constexpr uint32_t W = 320, H = 240;
constexpr uint32_t NONE = gpu::BACKGROUND_ID;
// Of the model's bounding box diagonal: a depth buffer's precision at the fitted distance,
// with room; the same at the origin and 5,000 km away.
constexpr double POINT_OF_SIZE = 1e-5;

struct FarModel {
    const char* name;
    glm::dvec3 offset; // model units
    std::string (*write)(const fs::path& folder, const char* name, glm::dvec3 offset);
};

std::string run(const std::string& command) {
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    return command;
}

std::string writeBuilding(const fs::path& folder, const char* name, glm::dvec3 offset) {
    const std::string path = (folder / (std::string(name) + ".gltf")).string();
    char xyz[128];
    std::snprintf(xyz, sizeof xyz, "%.17g,%.17g,%.17g", offset.x, offset.y, offset.z);
    run("python3 " IDVIEW_FAR_BUILDING_PY " " + path + " " + xyz);
    return path;
}

std::string writeMachine(const fs::path& folder, const char* name, glm::dvec3 offset) {
    const std::string path = (folder / (std::string(name) + ".step")).string();
    char xyz[128];
    std::snprintf(xyz, sizeof xyz, "%.17g %.17g %.17g", offset.x, offset.y, offset.z);
    run(IDVIEW_FAR_STEP_WRITER " " + path + " " + xyz + " >/dev/null");
    return path;
}

struct Seen {
    app::LoadedScene loaded;
    scene::Camera camera;
};

Seen load(const std::string& path) {
    app::SceneSettings settings;
    settings.model = path;
    settings.cadCache = false; // nothing of this temporary file kept
    Seen s{app::loadScene(settings), {}};
    s.camera = app::initialCamera(s.loaded, float(W) / float(H), {});
    return s;
}

// Pixels whose 5x5 neighbourhood is one part in `ids`, about `n` spread over the image.
std::vector<app::Options::Pixel> interiorPixels(const std::vector<uint32_t>& ids, size_t n) {
    std::vector<app::Options::Pixel> all;
    for (uint32_t y = 2; y + 2 < H; ++y)
        for (uint32_t x = 2; x + 2 < W; ++x) {
            const uint32_t id = ids[y * W + x];
            bool uniform = id != NONE;
            for (int dy = -2; dy <= 2 && uniform; ++dy)
                for (int dx = -2; dx <= 2 && uniform; ++dx)
                    uniform = ids[(y + dy) * W + (x + dx)] == id;
            if (uniform) all.push_back({x, y});
        }
    std::vector<app::Options::Pixel> kept;
    for (size_t i = 0; i < n && !all.empty(); ++i)
        kept.push_back(all[(all.size() - 1) * i / (n - 1)]);
    return kept;
}

void PrintTo(const FarModel& model, std::ostream* os) {
    *os << model.name;
}

// IDVIEW_FAR_OFFSET_SCALE=0 puts the far model at the origin too: the check of this test
// itself (tests/far_test.py reads the same variable).
double offsetScale() {
    const char* scale = std::getenv("IDVIEW_FAR_OFFSET_SCALE");
    return scale ? std::atof(scale) : 1.0;
}

class FarPick : public testing::TestWithParam<FarModel> {};

TEST_P(FarPick, AgreesWithTheRayCastAndWithTheOriginModel) {
    FarModel model = GetParam();
    model.offset *= offsetScale();
    const fs::path folder =
        fs::temp_directory_path() / ("idview-far-pick-" + std::to_string(getpid()));
    fs::create_directories(folder);
    const Seen origin = load(model.write(folder, "origin", glm::dvec3(0.0)));
    const Seen far = load(model.write(folder, "far", model.offset));
    fs::remove_all(folder);

    app::Options o = testing_support::headlessOptions(W, H);
    const std::vector<uint32_t> ids =
        app::renderHeadless(o, origin.loaded.scene, origin.camera).ids;
    o.picks = interiorPixels(ids, 24);
    ASSERT_GE(o.picks.size(), 20u);
    const app::HeadlessResult atOrigin = app::renderHeadless(o, origin.loaded.scene, origin.camera);
    const app::HeadlessResult atFar = app::renderHeadless(o, far.loaded.scene, far.camera);
    EXPECT_EQ(atOrigin.validationMessages, 0u);
    EXPECT_EQ(atFar.validationMessages, 0u);
    ASSERT_EQ(atFar.picks.size(), o.picks.size());

    const auto bounds = origin.loaded.scene.bounds();
    const double size = glm::length(glm::dvec3(bounds.max) - glm::dvec3(bounds.min));
    const double tolerance = POINT_OF_SIZE * size;
    const scene::RayCaster caster(far.loaded.scene);
    const glm::vec2 image{float(W), float(H)};
    const auto viewProj = far.camera.viewProjection(image.x / image.y);
    const auto originViewProj = origin.camera.viewProjection(image.x / image.y);
    double worstToRay = 0.0, worstToOrigin = 0.0;
    for (size_t i = 0; i < o.picks.size(); ++i) {
        const auto& pixel = o.picks[i];
        const std::string where = std::string(model.name) + " at " + std::to_string(pixel.x) + "," +
                                  std::to_string(pixel.y);
        const render::PickReading& pick = atFar.picks[i];
        if (!atOrigin.picks[i].part) {
            ADD_FAILURE() << where << ": no part at the origin";
            continue;
        }
        EXPECT_EQ(pick.part.value_or(NONE), *atOrigin.picks[i].part) << where;
        const glm::vec2 at = glm::vec2(float(pixel.x), float(pixel.y)) + 0.5f;
        const auto ray = scene::pixelRay(viewProj, image, at);
        const auto hit = caster.cast(ray);
        if (!hit) { // a miss counts as a failure, and the other pixels are still measured
            ADD_FAILURE() << where << ": the ray cast hits nothing, the pick "
                          << pick.part.value_or(NONE);
            continue;
        }
        EXPECT_EQ(pick.part.value_or(NONE), hit->uniquePartId) << where;
        const glm::dvec3 rayPoint =
            glm::dvec3(ray.origin) + double(hit->t) * glm::dvec3(ray.direction);
        const glm::dvec3 picked(scene::unprojectPixel(viewProj, image, at, pick.depth));
        const glm::dvec3 pickedAtOrigin(
            scene::unprojectPixel(originViewProj, image, at, atOrigin.picks[i].depth));
        const double toRay = glm::length(picked - rayPoint);
        const double toOrigin = glm::length(picked - (pickedAtOrigin + model.offset));
        worstToRay = std::max(worstToRay, toRay);
        worstToOrigin = std::max(worstToOrigin, toOrigin);
        EXPECT_LE(toRay, tolerance) << where << ": the pick's point is that far from the ray's";
        EXPECT_LE(toOrigin, tolerance)
            << where << ": the pick's point is that far from the origin's plus the offset";
    }
    // For the report: how far off the worst pixel is, in model units.
    std::cout << model.name << ": pick to ray cast at most " << worstToRay
              << ", to the origin's pick plus the offset at most " << worstToOrigin
              << " (tolerance " << tolerance << ", model size " << size << ")\n";
}

INSTANTIATE_TEST_SUITE_P(
    Models, FarPick,
    testing::Values(FarModel{"building", {458000.0, 5439000.0, 110.0}, writeBuilding},
                    FarModel{"machine", {2e6, -3.5e6, 8e5}, writeMachine}),
    [](const testing::TestParamInfo<FarModel>& info) { return std::string(info.param.name); });

} // namespace
