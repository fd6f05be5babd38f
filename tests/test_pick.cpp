// test_pick.cpp - the 64-bit atomicMin pick, for every technique x per-draw mode on lavapipe,
// without MSAA and with 4x (where sample 0 decides, in the pick as in the ID image):
// it names the part of the ID image at part interiors, part borders and background; a CPU
// ray cast agrees inside parts (part and depth); the hover and selection highlights change
// exactly the picked part's pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <string>
#include <tuple>

#include "app/headless.h"
#include "app/measure_json.h"
#include "app/scene_source.h"
#include "image_compare.h"
#include "raster_explainer.h"
#include "render/technique.h"
#include "scene/raycast.h"
#include "test_support.h"

namespace {

constexpr uint32_t W = 160, H = 100;
constexpr uint32_t NONE = gpu::BACKGROUND_ID;

struct Points {
    std::vector<app::Options::Pixel> interior, border, background;
};

struct Fixture {
    app::LoadedScene loaded;
    scene::Camera camera;
    std::vector<uint32_t> ids; // per-draw + push, no pick
    Points points;
};

app::Options options(uint32_t msaa) {
    app::Options o = testing_support::headlessOptions(W, H);
    o.live.render.pipeline.msaa = msaa;
    return o;
}

uint32_t idAt(const std::vector<uint32_t>& ids, int x, int y) {
    if (x < 0 || y < 0 || x >= int(W) || y >= int(H)) return NONE;
    return ids[size_t(y) * W + size_t(x)];
}

// Classifies pixels of the reference image and keeps a spread of each kind: interior (the
// 5x5 neighbourhood is one part), border (a 4-neighbour is another part or background) and
// background.
Points choosePoints(const std::vector<uint32_t>& ids) {
    Points all;
    for (uint32_t y = 1; y + 1 < H; ++y)
        for (uint32_t x = 1; x + 1 < W; ++x) {
            const uint32_t id = idAt(ids, int(x), int(y));
            bool uniform = true, edge = false;
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) {
                    const uint32_t n = idAt(ids, int(x) + dx, int(y) + dy);
                    uniform = uniform && n == id;
                    if (std::abs(dx) + std::abs(dy) == 1 && n != id) edge = true;
                }
            if (id == NONE)
                all.background.push_back({x, y});
            else if (edge)
                all.border.push_back({x, y});
            else if (uniform)
                all.interior.push_back({x, y});
        }
    auto spread = [](const std::vector<app::Options::Pixel>& from, size_t n) {
        std::vector<app::Options::Pixel> kept;
        for (size_t i = 0; i < n && !from.empty(); ++i)
            kept.push_back(from[(from.size() - 1) * i / std::max<size_t>(1, n - 1)]);
        return kept;
    };
    return {spread(all.interior, 10), spread(all.border, 10), spread(all.background, 4)};
}

// Per sample count, since MSAA moves the edges of the ID image (sample 0 decides there), and
// per projection: `ortho` looks at the isometric view in orthographic projection.
Fixture& fixture(uint32_t msaa, bool ortho = false) {
    static std::map<std::pair<uint32_t, bool>, Fixture> cache;
    if (auto found = cache.find({msaa, ortho}); found != cache.end()) return found->second;
    Fixture& f = cache[{msaa, ortho}];
    {
        app::SceneSettings source;
        source.builtin = "procedural:preset=small,seed=1";
        source.copies = 2;
        f.loaded = app::loadScene(source);
        app::CameraSettings view;
        if (ortho) view = {scene::findStandardView("isometric"), true};
        f.camera = app::initialCamera(f.loaded, float(W) / float(H), view);
        f.ids = app::renderHeadless(options(msaa), f.loaded.scene, f.camera).ids;
        f.points = choosePoints(f.ids);
    }
    return f;
}

std::vector<render::RenderSettings> modesOf(const render::Technique& technique, uint32_t msaa) {
    std::vector<render::RenderSettings> configs;
    for (const auto& mode : render::drawModes()) {
        configs.push_back(testing_support::settingsFor(technique, mode));
        configs.back().pipeline.msaa = msaa;
    }
    return configs;
}

// Pixels whose colour differs between two frames.
std::vector<bool> changed(const app::HeadlessResult& a, const app::HeadlessResult& b) {
    std::vector<bool> out(size_t(W) * H);
    for (size_t i = 0; i < out.size(); ++i)
        for (size_t c = 0; c < 3; ++c) out[i] = out[i] || a.color[i * 4 + c] != b.color[i * 4 + c];
    return out;
}

// The changed pixels are exactly the pixels of `part` in the ID image. With MSAA the resolved
// colour also changes where samples other than sample 0 (which the ID image shows) belong to
// the part (its thin slivers that no sample 0 hits): there a changed pixel outside the part
// must lie within `margin` pixels of it (2 with MSAA, measured on lavapipe at 4x).
void expectExactlyPartChanged(const app::HeadlessResult& plain, const app::HeadlessResult& lit,
                              uint32_t part, int margin, const std::string& what) {
    const std::vector<bool> diff = changed(plain, lit);
    size_t partPixels = 0, unchangedInPart = 0, changedOutside = 0;
    for (size_t i = 0; i < diff.size(); ++i) {
        const bool inPart = lit.ids[i] == part;
        partPixels += inPart;
        unchangedInPart += inPart && !diff[i];
        if (inPart || !diff[i]) continue;
        bool near = false;
        for (int dy = -margin; dy <= margin; ++dy)
            for (int dx = -margin; dx <= margin; ++dx)
                near = near || idAt(lit.ids, int(i % W) + dx, int(i / W) + dy) == part;
        if (!near) {
            ++changedOutside;
            ADD_FAILURE() << what << ": pixel " << i % W << "," << i / W << " changed";
        }
    }
    EXPECT_GT(partPixels, 0u) << what;
    EXPECT_EQ(unchangedInPart, 0u)
        << what << ": part " << part << " has " << partPixels << " pixels";
    EXPECT_EQ(changedOutside, 0u) << what;
}

// Where sample 0 lies in a pixel: Vulkan's standard sample locations.
glm::vec2 sampleZero(uint32_t msaa) {
    switch (msaa) {
    case 2:
        return {0.75f, 0.75f};
    case 4:
        return {0.375f, 0.125f};
    case 8:
        return {0.5625f, 0.3125f};
    default:
        return {0.5f, 0.5f};
    }
}

// The hover read from the ID and depth images is the atomicMin pick's part, and its depth as
// the depth attachment holds it at sample 0.
void expectHoversArePicks(const app::HeadlessResult& r, const std::string& name) {
    ASSERT_EQ(r.hovers.size(), r.picks.size());
    for (size_t i = 0; i < r.picks.size(); ++i) {
        const render::PickReading& hover = r.hovers[i];
        EXPECT_EQ(hover.part, r.picks[i].part) << name << " hover " << i;
        EXPECT_EQ(hover.frame, r.picks[i].frame);
        if (hover.part) {
            EXPECT_NEAR(hover.depth, r.picks[i].depth, 1e-5) << name;
        }
    }
}

// Each pick names the part the ID image shows at its pixel (nothing on background), at a
// depth inside the view.
void expectPicksNameTheIdImage(const app::HeadlessResult& r, const std::string& name) {
    for (const auto& pick : r.picks) {
        const uint32_t expected = idAt(r.ids, int(pick.pixel.x), int(pick.pixel.y));
        const std::string where =
            name + " at " + std::to_string(pick.pixel.x) + "," + std::to_string(pick.pixel.y);
        if (expected == NONE) {
            EXPECT_FALSE(pick.part.has_value()) << where;
            continue;
        }
        ASSERT_TRUE(pick.part.has_value()) << where;
        EXPECT_EQ(*pick.part, expected) << where;
        EXPECT_GT(pick.depth, 0.0f) << where;
        EXPECT_LT(pick.depth, 1.0f) << where;
    }
}

// Inside parts (the picks from `first` on) the CPU ray through the deciding point (pixel
// centre, or sample 0 of the standard MSAA pattern) hits the same part at the depth the GPU
// recorded.
void expectRayCastAgreesInside(const app::HeadlessResult& r, size_t first,
                               const scene::RayCaster& caster, const glm::dmat4& viewProj,
                               uint32_t msaa, const std::string& name) {
    for (size_t i = first; i < r.picks.size(); ++i) {
        const auto& pick = r.picks[i];
        const glm::vec2 centre = glm::vec2(pick.pixel) + sampleZero(msaa);
        const scene::Ray ray = scene::pixelRay(viewProj, glm::vec2(float(W), float(H)), centre);
        const auto hit = caster.cast(ray);
        ASSERT_TRUE(hit.has_value()) << name;
        EXPECT_EQ(hit->uniquePartId, pick.part.value_or(NONE)) << name;
        const glm::vec4 clip = viewProj * glm::vec4(ray.origin + hit->t * ray.direction, 1.0f);
        EXPECT_NEAR(clip.z / clip.w, pick.depth, 1e-4) << name;
    }
}

using Param = std::tuple<const render::Technique*, uint32_t>; // technique, MSAA samples
class PickPerTechnique : public ::testing::TestWithParam<Param> {};

TEST_P(PickPerTechnique, AgreesWithIdImageRayCastAndHighlightsExactlyThePart) {
    const auto& [technique, msaa] = GetParam();
    Fixture& f = fixture(msaa);
    const Points& p = f.points;
    ASSERT_EQ(p.interior.size(), 10u);
    ASSERT_EQ(p.border.size(), 10u);
    ASSERT_EQ(p.background.size(), 4u);

    // Picks end on an interior point, so the timed frame shows it hovered; `plain` ends on
    // background and shows nothing highlighted.
    app::Options o = options(msaa);
    o.picks = p.background;
    o.picks.insert(o.picks.end(), p.border.begin(), p.border.end());
    o.picks.insert(o.picks.end(), p.interior.begin(), p.interior.end());
    const auto configs = modesOf(*technique, msaa);
    const auto results = app::renderHeadlessSequence(o, f.loaded.scene, f.camera, configs);
    app::Options plainOptions = options(msaa);
    plainOptions.picks = {p.background.front()};
    plainOptions.selects = {p.background.front()};
    const auto plain = app::renderHeadlessSequence(plainOptions, f.loaded.scene, f.camera, configs);
    app::Options selectOptions = plainOptions;
    selectOptions.selects = {p.interior.front()};
    const auto selected =
        app::renderHeadlessSequence(selectOptions, f.loaded.scene, f.camera, configs);

    const scene::RayCaster caster(f.loaded.scene);
    const glm::dmat4 viewProj = f.camera.viewProjection(float(W) / float(H));
    for (size_t c = 0; c < configs.size(); ++c) {
        const std::string name = std::string(technique->name) + " + " +
                                 configs[c].pipeline.mode->name + " msaa " + std::to_string(msaa);
        const app::HeadlessResult& r = results[c];
        EXPECT_EQ(r.validationMessages, 0u);
        ASSERT_TRUE(testing_support::sameIdsAs(*technique, r.ids, f.ids, f.loaded.scene, f.camera,
                                               {W, H}, msaa))
            << name;
        ASSERT_EQ(r.picks.size(), o.picks.size());
        expectHoversArePicks(r, name);
        expectPicksNameTheIdImage(r, name);
        expectRayCastAgreesInside(r, p.background.size() + p.border.size(), caster, viewProj, msaa,
                                  name);
        if (HasFatalFailure()) return;

        ASSERT_TRUE(plain[c].picks.front().part == std::nullopt);
        expectExactlyPartChanged(plain[c], r, *r.picks.back().part, msaa > 1 ? 2 : 0,
                                 name + " hover");
        ASSERT_TRUE(selected[c].selected.has_value()) << name;
        EXPECT_EQ(*selected[c].selected,
                  idAt(f.ids, int(p.interior.front().x), int(p.interior.front().y)));
        expectExactlyPartChanged(plain[c], selected[c], *selected[c].selected, msaa > 1 ? 2 : 0,
                                 name + " select");
        EXPECT_FALSE(plain[c].selected.has_value()) << name;
    }
}

// Every part-ID technique the registry lists, without MSAA and at 4x.
INSTANTIATE_TEST_SUITE_P(Lavapipe, PickPerTechnique,
                         ::testing::Combine(::testing::ValuesIn(render::partIdTechniques()),
                                            ::testing::Values(1u, 4u)),
                         [](const auto& info) {
                             return testing_support::testName(
                                 std::string(std::get<0>(info.param)->name) + "_msaa" +
                                 std::to_string(std::get<1>(info.param)));
                         });

// --measure, without MSAA and at 4x: each point lies where the CPU ray through its pick point
// (pixel centre, or sample 0) meets the part the ray cast names, within a ten-thousandth of
// the scene's size; the distance and delta are those of the two points; the JSON line says
// so; a background pixel gives nulls.
// In perspective with and without MSAA, and in ortho (parallel rays, a near plane that may
// lie behind the eye: the depth still unprojects to the surface).
TEST(Measure, WorldPointsAreWhereTheRayCastMeetsTheParts) {
    for (const auto& [msaa, ortho] :
         {std::pair(1u, false), std::pair(4u, false), std::pair(1u, true)}) {
        SCOPED_TRACE(ortho ? "ortho" : "perspective");
        Fixture& f = fixture(msaa, ortho);
        const Points& p = f.points;
        ASSERT_GE(p.interior.size(), 2u);
        ASSERT_FALSE(p.background.empty());
        app::Options o = options(msaa);
        o.measure = {p.interior.front(), p.interior.back()};
        const app::HeadlessResult r = app::renderHeadless(o, f.loaded.scene, f.camera);
        EXPECT_EQ(r.validationMessages, 0u);
        const scene::RayCaster caster(f.loaded.scene);
        const glm::dmat4 viewProj = f.camera.viewProjection(float(W) / float(H));
        const float size = glm::length(f.loaded.scene.bounds().max - f.loaded.scene.bounds().min);
        ASSERT_EQ(r.measured.size(), 2u);
        for (size_t i = 0; i < 2; ++i) {
            const glm::vec2 at = glm::vec2(r.measured[i].pixel) + sampleZero(msaa);
            const scene::Ray ray = scene::pixelRay(viewProj, glm::vec2(float(W), float(H)), at);
            const auto hit = caster.cast(ray);
            ASSERT_TRUE(hit.has_value());
            ASSERT_TRUE(r.measuredPoints[i].has_value());
            EXPECT_EQ(r.measured[i].part.value_or(NONE), hit->uniquePartId) << "msaa " << msaa;
            EXPECT_LT(glm::length(*r.measuredPoints[i] - (ray.origin + hit->t * ray.direction)),
                      1e-4f * size)
                << "msaa " << msaa << " point " << i;
        }
        const glm::dvec3 delta = *r.measuredPoints[1] - *r.measuredPoints[0];
        EXPECT_GT(glm::length(delta), 0.0);
        const std::string line = app::measureJson(r, f.loaded.scene.unit);
        // Every digit: the distance printed reads back as the double computed.
        const size_t distance = line.find("\"distance\":");
        ASSERT_NE(distance, std::string::npos) << line;
        EXPECT_EQ(std::strtod(line.c_str() + distance + 11, nullptr), glm::length(delta)) << line;
        EXPECT_NE(line.find("\"parts\":[" + std::to_string(*r.measured[0].part) + "," +
                            std::to_string(*r.measured[1].part) + "]"),
                  std::string::npos)
            << line;

        o.measure = {p.background.front(), p.interior.front()};
        const app::HeadlessResult off = app::renderHeadless(o, f.loaded.scene, f.camera);
        EXPECT_FALSE(off.measuredPoints[0].has_value());
        ASSERT_TRUE(off.measuredPoints[1].has_value());
        const std::string nulls = app::measureJson(off, f.loaded.scene.unit);
        EXPECT_EQ(nulls.rfind("{\"p0\":null,", 0), 0u) << nulls;
        EXPECT_NE(nulls.find("\"distance\":null,\"delta\":null,\"parts\":[null,"),
                  std::string::npos)
            << nulls;
    }
}

// In ortho a pick names the part the ID image shows at its pixel (interiors, borders and
// background alike), the CPU ray cast agrees inside parts, and its depth unprojects to the
// point where that ray meets the part.
TEST(Pick, OrthoPicksAgreeWithTheIdImageAndTheRayCast) {
    Fixture& f = fixture(1, true);
    ASSERT_TRUE(f.camera.ortho);
    const Points& p = f.points;
    ASSERT_GE(p.interior.size(), 5u);
    ASSERT_GE(p.border.size(), 5u);
    ASSERT_FALSE(p.background.empty());
    app::Options o = options(1);
    for (const auto* points : {&p.interior, &p.border, &p.background})
        o.picks.insert(o.picks.end(), points->begin(), points->end());
    const app::HeadlessResult r = app::renderHeadless(o, f.loaded.scene, f.camera);
    EXPECT_EQ(r.validationMessages, 0u);
    ASSERT_EQ(r.picks.size(), o.picks.size());
    const scene::RayCaster caster(f.loaded.scene);
    const glm::vec2 size{float(W), float(H)};
    const glm::dmat4 viewProj = f.camera.viewProjection(size.x / size.y);
    const float extent = glm::length(f.loaded.scene.bounds().max - f.loaded.scene.bounds().min);
    for (size_t i = 0; i < o.picks.size(); ++i) {
        const auto& pixel = o.picks[i];
        const std::string where = std::to_string(pixel.x) + "," + std::to_string(pixel.y);
        EXPECT_EQ(r.picks[i].part.value_or(NONE), idAt(f.ids, int(pixel.x), int(pixel.y))) << where;
        if (i >= p.interior.size()) continue;
        const glm::vec2 at = glm::vec2(float(pixel.x), float(pixel.y)) + 0.5f;
        const scene::Ray ray = scene::pixelRay(viewProj, size, at);
        const auto hit = caster.cast(ray);
        ASSERT_TRUE(hit.has_value()) << where;
        EXPECT_EQ(r.picks[i].part.value_or(NONE), hit->uniquePartId) << where;
        EXPECT_LT(glm::length(scene::unprojectPixel(viewProj, size, at, r.picks[i].depth) -
                              (ray.origin + hit->t * ray.direction)),
                  1e-4f * extent)
            << where;
    }
}

// The decode of the packed value: depth bits inverted high (shared.h pickKey), part low, all
// ones for nothing.
TEST(PickDecode, SplitsDepthAndPart) {
    const float depth = 0.25f;
    const uint64_t value = (uint64_t(~std::bit_cast<uint32_t>(depth)) << 32) | 1234u;
    const auto reading = render::decodePick(value, 7, {3, 4});
    EXPECT_EQ(reading.part, 1234u);
    EXPECT_EQ(reading.depth, depth);
    EXPECT_EQ(reading.frame, 7u);
    EXPECT_FALSE(render::decodePick(gpu::PICK_NONE, 0, {}).part.has_value());
}

} // namespace
