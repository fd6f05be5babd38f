// test_animation.cpp - the exploded view: the offsets by assembly level against a computation
// from the objects' paths alone (nested and flat assemblies) and the CPU reference by hand,
// then, on lavapipe with validation on, the GPU-animated ID image must equal bit for bit the
// image of the CPU-exploded scene drawn at rest (and differ from the unexploded image), the
// pick must name what the animated image shows, `--explode F` headless must draw the same
// and pick what the CPU ray cast of the exploded scene meets, and explode 0 must bring the
// rest back.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "app/camera_frame.h"
#include "app/headless.h"
#include "app/image_io.h"
#include "app/offscreen.h"
#include "app/scene_source.h"
#include "image_compare.h"
#include "render/technique.h"
#include "scene/explode.h"
#include "scene/face_info.h"
#include "scene/raycast.h"
#include "test_support.h"
#include "vk/context.h"

namespace {

constexpr uint32_t W = 160, H = 100;
using testing_support::idDifference;
using testing_support::sameIds;

// Two placements of one triangle whose bounds are easy to write down.
scene::Scene twoTriangles() {
    scene::Scene s;
    s.vertices = {{{0, 0, 0}, {0, 0, 1}}, {{1, 0, 0}, {0, 0, 1}}, {{0, 1, 0}, {0, 0, 1}}};
    s.indices = {0, 1, 2};
    s.parts = {{0, 1}};
    s.geometries = {{"triangle", 0, 3, 0, 1, 0, 1, {}, {}, {}, {}, 0, 0.0f}};
    scene::addMaterial(s, "grey", glm::vec4(0.5f));
    glm::mat4 a(1.0f), b(2.0f); // b scales by 2
    a[3] = {-3, 0, 0, 1};
    b[3] = {5, 0, 2, 1};
    scene::addObject(s, 0, 0, a);
    scene::addObject(s, 0, 0, b);
    return s;
}

TEST(ExplodeMaths, OffsetsPointFromSceneCentreToObjectCentres) {
    // Object bounds: x -3..-2, y 0..1, z 0 and x 5..7, y 0..2, z 2; the scene's centre is
    // (2, 1, 1).
    const auto offsets = scene::explodeOffsets(twoTriangles());
    ASSERT_EQ(offsets.size(), 2u);
    EXPECT_EQ(offsets[0], glm::vec4(-4.5f, -0.5f, -1.0f, 0.0f));
    EXPECT_EQ(offsets[1], glm::vec4(4.0f, 0.0f, 1.0f, 0.0f));
}

TEST(ExplodeMaths, ExplodedSceneMovesTranslationsOnly) {
    const scene::Scene rest = twoTriangles();
    const scene::Scene none = scene::explodedScene(rest, 0.0f);
    for (size_t i = 0; i < rest.objects.size(); ++i)
        EXPECT_EQ(none.objects[i].world, rest.objects[i].world);

    // At 1 each object's centre is twice as far from the scene centre: (-2.5, 0.5, 0) goes to
    // (-7, 0, -1) and (6, 1, 2) to (10, 1, 3).
    const scene::Scene full = scene::explodedScene(rest, 1.0f);
    EXPECT_EQ(full.objects[0].world[3], glm::dvec4(-7.5, -0.5, -1.0, 1.0));
    EXPECT_EQ(full.objects[1].world[3], glm::dvec4(9.0, 0.0, 3.0, 1.0));
    for (size_t i = 0; i < rest.objects.size(); ++i) {
        for (int c = 0; c < 3; ++c) EXPECT_EQ(full.objects[i].world[c], rest.objects[i].world[c]);
        EXPECT_EQ(full.objects[i].uniquePartOffset, rest.objects[i].uniquePartOffset);
    }

    const scene::Scene some = scene::explodedScene(rest, 0.6f);
    // The reference's operations, rounded the same way: the step in float, the add in double.
    const double x = -3.0 + double(-4.5f * 0.6f);
    EXPECT_EQ(some.objects[0].world[3].x, x);
}

// One triangle placed `n` times by `paths`, each placement moved and scaled differently.
scene::Scene placedTriangles(const std::vector<std::string>& paths) {
    scene::Scene s = twoTriangles();
    s.objects.clear();
    for (size_t i = 0; i < paths.size(); ++i) {
        glm::dmat4 world(1.0 + 0.25 * double(i % 3));
        world[3] = glm::dvec4(7.0 * std::sin(double(i)), 3.0 * double(i % 4), double(i) * 0.5, 1);
        const size_t slash = paths[i].rfind('/');
        scene::addObject(s, 0, 0, world, paths[i].substr(slash + 1), paths[i]);
    }
    return s;
}

// The offsets worked out from the objects' path strings alone (no assembly tree): for each
// prefix of an object's path, the box of every object under it, and how many different names
// follow it (its members); the object moves by the sum over its path of weight * (centre of
// the longer prefix - centre of the shorter), the weight halving below a prefix of two or
// more members. Holds for scenes whose objects' paths are unique and name no group.
std::vector<glm::dvec3> offsetsByPaths(const scene::Scene& s) {
    auto under = [&](const std::string& prefix, const scene::Object& o) {
        return prefix.empty() || o.path == prefix || o.path.starts_with(prefix + "/");
    };
    auto centre = [&](const std::string& prefix) {
        glm::dvec3 lo(1e30), hi(-1e30);
        for (const scene::Object& o : s.objects)
            if (under(prefix, o))
                for (int v = 0; v < 3; ++v) {
                    const glm::dvec3 p = scene::placed(o.world, s.vertices[v].position);
                    lo = glm::min(lo, p);
                    hi = glm::max(hi, p);
                }
        return (lo + hi) * 0.5;
    };
    auto members = [&](const std::string& prefix) {
        std::set<std::string> next;
        for (const scene::Object& o : s.objects)
            if (under(prefix, o) && o.path != prefix) {
                const std::string rest = prefix.empty() ? o.path : o.path.substr(prefix.size() + 1);
                next.insert(rest.substr(0, rest.find('/')));
            }
        return next.size();
    };
    std::vector<glm::dvec3> offsets;
    for (const scene::Object& o : s.objects) {
        glm::dvec3 sum(0.0);
        double weight = 1.0;
        std::string prefix;
        for (size_t end = 0; end != std::string::npos;) {
            end = o.path.find('/', prefix.empty() ? 0 : prefix.size() + 1);
            const std::string longer = o.path.substr(0, end);
            sum += weight * (centre(longer) - centre(prefix));
            if (members(prefix) > 1) weight *= 0.5;
            prefix = longer;
        }
        offsets.push_back(sum);
    }
    return offsets;
}

// The flat offsets of before assembly levels: object centre minus scene centre.
std::vector<glm::vec4> flatOffsets(const scene::Scene& s) {
    const glm::dvec3 all = s.bounds().center();
    std::vector<glm::vec4> offsets;
    for (const scene::Object& o : s.objects) {
        glm::dvec3 lo(1e30), hi(-1e30);
        for (int v = 0; v < 3; ++v) {
            lo = glm::min(lo, scene::placed(o.world, s.vertices[v].position));
            hi = glm::max(hi, scene::placed(o.world, s.vertices[v].position));
        }
        offsets.push_back(glm::vec4((lo + hi) * 0.5 - all, 0.0f));
    }
    return offsets;
}

TEST(ExplodeMaths, NestedAssemblyPartsByLevel) {
    // Three levels below a single top node: sub-assemblies, a sub-sub-assembly, parts.
    const scene::Scene s = placedTriangles(
        {"rig/arm/link a", "rig/arm/link b", "rig/arm/wrist/pin 1", "rig/arm/wrist/pin 2",
         "rig/arm/wrist/pin 3", "rig/base/plate", "rig/base/foot", "rig/cover"});
    const auto offsets = scene::explodeOffsets(s);
    const auto expected = offsetsByPaths(s);
    const auto flat = flatOffsets(s);
    ASSERT_EQ(offsets.size(), expected.size());
    double apart = 0.0; // how far the levels moved objects from where the flat view would
    for (size_t i = 0; i < offsets.size(); ++i) {
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(offsets[i][c], expected[i][c], 1e-5) << s.objects[i].path << " " << c;
        EXPECT_EQ(offsets[i].w, 0.0f);
        apart = std::max(apart, double(glm::length(offsets[i] - flat[i])));
    }
    EXPECT_GT(apart, 0.5) << "the levels must change the offsets of nested parts";
    // The wrist's pins keep their sub-assembly's motion, and part within it by a quarter.
    auto centre = [&](size_t i) { // the triangle's box: (0, 0, 0) to (1, 1, 0), scaled
        const glm::dmat4& world = s.objects[i].world;
        return glm::dvec3(world[3]) + world[0][0] * glm::dvec3(0.5, 0.5, 0.0);
    };
    const glm::dvec3 pins = glm::dvec3(glm::vec3(offsets[3] - offsets[2]));
    const glm::dvec3 restPins = centre(3) - centre(2);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(pins[c], 0.25 * restPins[c], 1e-4);
}

TEST(ExplodeMaths, FlatAssemblyKeepsTheSceneCentreOffsets) {
    // Objects at the root, and objects all under one node (a chain of one member).
    for (const std::vector<std::string>& paths :
         {std::vector<std::string>{"a", "b", "c", "d"},
          std::vector<std::string>{"top/a", "top/b", "top/c", "top/d"}}) {
        const scene::Scene s = placedTriangles(paths);
        EXPECT_EQ(scene::explodeOffsets(s), flatOffsets(s)) << paths[0];
    }
}

TEST(ExplodeMaths, LoopGoesOutAndBackInFourSeconds) {
    EXPECT_EQ(scene::explodeLoop(0.0f), 0.0f);
    EXPECT_NEAR(scene::explodeLoop(1.0f), 0.5f, 1e-6f);
    EXPECT_NEAR(scene::explodeLoop(2.0f), 1.0f, 1e-6f);
    EXPECT_NEAR(scene::explodeLoop(4.0f), 0.0f, 1e-6f);
    EXPECT_NEAR(scene::explodeLoop(5.0f), scene::explodeLoop(1.0f), 1e-6f);
}

TEST(AnimationFlags, ParseAnimateAndTime) {
    const app::Options o = app::parseArgs({"--animate", "--time", "1.5"});
    EXPECT_TRUE(o.live.animation.animate);
    ASSERT_TRUE(o.live.animation.time.has_value());
    EXPECT_EQ(*o.live.animation.time, 1.5f);
    EXPECT_FALSE(app::parseArgs(std::vector<std::string>{}).live.animation.time.has_value());
    EXPECT_THROW(app::parseArgs({"--time", "1"}), app::UsageError); // needs --animate
    EXPECT_THROW(app::parseArgs({"--animate", "--time", "soon"}), app::UsageError);
    EXPECT_THROW(app::parseArgs({"--animate", "--time=-1"}), app::UsageError);
    EXPECT_THROW(app::parseArgs({"--animate", "--time", "nan"}), app::UsageError);
    EXPECT_NE(app::usage().find("--animate"), std::string::npos);
}

TEST(AnimationFlags, ExplodeTakesZeroToOne) {
    EXPECT_EQ(app::parseArgs({"--explode", "0.25"}).live.animation.explode, 0.25f);
    EXPECT_EQ(app::parseArgs({"--explode=1"}).live.animation.explode, 1.0f);
    EXPECT_EQ(app::parseArgs(std::vector<std::string>{}).live.animation.explode, 0.0f);
    for (const char* bad : {"1.5", "-0.1", "far", "nan"}) {
        try {
            app::parseArgs({"--explode", bad});
            ADD_FAILURE() << bad << " was taken";
        } catch (const app::UsageError& e) {
            EXPECT_EQ(std::string(e.what()),
                      std::string("--explode expects a number from 0 to 1, not '") + bad + "'");
        }
    }
    EXPECT_THROW(app::parseArgs({"--explode", "0.5", "--animate"}), app::UsageError);
}

app::Options renderOptions(const render::Technique& technique, const render::DrawMode& mode) {
    app::Options o = testing_support::headlessOptions(W, H, 2);
    o.live.render = testing_support::settingsFor(technique, mode);
    return o;
}

struct Fixture {
    app::LoadedScene loaded;
    scene::Camera camera; // fitted to the scene at rest; exploded objects may leave the view
};

Fixture& fixture() {
    static Fixture f = [] {
        app::SceneSettings source;
        source.builtin = "procedural:preset=small,seed=1";
        Fixture made;
        made.loaded = app::loadScene(source);
        made.camera = app::initialCamera(made.loaded, float(W) / float(H));
        return made;
    }();
    return f;
}

struct Combination {
    const render::Technique* technique;
    const render::DrawMode* mode;
};

void PrintTo(const Combination& c, std::ostream* os) {
    *os << c.technique->name << " + " << c.mode->name;
}

class GpuAnimation : public ::testing::TestWithParam<Combination> {};

TEST_P(GpuAnimation, MatchesCpuExplodedSceneBitForBitAndPicksWhatItShows) {
    const Combination& c = GetParam();
    Fixture& f = fixture();
    const float explode = 0.6f;

    app::Options animated = renderOptions(*c.technique, *c.mode);
    animated.live.animation.explode = explode;
    // Picks across the image: they run before the timed frames, at the same explode.
    for (uint32_t y = 5; y < H; y += 18)
        for (uint32_t x = 5; x < W; x += 25) animated.picks.push_back({x, y});
    const app::HeadlessResult gpu = app::renderHeadless(animated, f.loaded.scene, f.camera);
    const app::Options still = renderOptions(*c.technique, *c.mode);
    const app::HeadlessResult cpu =
        app::renderHeadless(still, scene::explodedScene(f.loaded.scene, explode), f.camera);
    const app::HeadlessResult rest = app::renderHeadless(still, f.loaded.scene, f.camera);
    EXPECT_EQ(gpu.validationMessages, 0u);
    EXPECT_EQ(cpu.validationMessages, 0u);
    EXPECT_EQ(rest.validationMessages, 0u);

    ASSERT_EQ(gpu.ids.size(), size_t(W) * H);
    ASSERT_EQ(cpu.ids.size(), gpu.ids.size());
    EXPECT_TRUE(sameIds(gpu.ids, cpu.ids, W));
    // The motion is real: a good share of the image changed against the scene at rest.
    EXPECT_GT(idDifference(gpu.ids, rest.ids, W).pixels, gpu.ids.size() / 20);

    ASSERT_EQ(gpu.picks.size(), animated.picks.size());
    size_t onParts = 0;
    for (const auto& pick : gpu.picks) {
        const uint32_t shown = gpu.ids[size_t(pick.pixel.y) * W + pick.pixel.x];
        EXPECT_EQ(pick.part.value_or(gpu::BACKGROUND_ID), shown)
            << "pick at " << pick.pixel.x << "," << pick.pixel.y;
        onParts += pick.part.has_value();
    }
    EXPECT_GT(onParts, 3u) << "too few picks hit a part to mean anything";
}

std::string nameOf(const ::testing::TestParamInfo<Combination>& info) {
    return testing_support::testName(std::string(info.param.technique->name) + "_" +
                                     info.param.mode->name);
}

// Every part-ID technique of the registry, the modes taken in turn.
std::vector<Combination> combinations() {
    std::vector<Combination> all;
    const auto& modes = render::drawModes();
    for (const render::Technique* t : render::partIdTechniques())
        all.push_back({t, &modes[all.size() % modes.size()]});
    return all;
}

INSTANTIATE_TEST_SUITE_P(Lavapipe, GpuAnimation, ::testing::ValuesIn(combinations()), nameOf);

// --animate --time T renders the loop's explode at T, identical to the CPU reference.
TEST(GpuAnimationLoop, AnimateAtTimeFollowsTheLoop) {
    Fixture& f = fixture();
    const render::Technique& technique = *render::partIdTechniques().back();
    app::Options o = renderOptions(technique, render::defaultDrawMode());
    o.live.animation.animate = true;
    o.live.animation.time = 1.3f;
    const app::HeadlessResult gpu = app::renderHeadless(o, f.loaded.scene, f.camera);
    const app::HeadlessResult cpu = app::renderHeadless(
        renderOptions(technique, render::defaultDrawMode()),
        scene::explodedScene(f.loaded.scene, scene::explodeLoop(1.3f)), f.camera);
    EXPECT_EQ(gpu.validationMessages, 0u);
    EXPECT_TRUE(sameIds(gpu.ids, cpu.ids, W));
}

// Pixels inside parts of `ids` (the 3x3 pixels around show one part), a spread of about 24
// of them: a headless pick takes a frame each.
std::vector<app::Options::Pixel> pixelsInsideParts(const std::vector<uint32_t>& ids) {
    auto idAt = [&](uint32_t x, uint32_t y) { return ids[size_t(y) * W + x]; };
    std::vector<app::Options::Pixel> pixels;
    for (uint32_t y = 2; y + 2 < H; y += 3)
        for (uint32_t x = 2; x + 2 < W; x += 3) {
            bool inside = idAt(x, y) != gpu::BACKGROUND_ID;
            for (uint32_t dy = 0; dy < 3; ++dy)
                for (uint32_t dx = 0; dx < 3; ++dx)
                    inside = inside && idAt(x + dx - 1, y + dy - 1) == idAt(x, y);
            if (inside) pixels.push_back({x, y});
        }
    const size_t every = std::max<size_t>(1, pixels.size() / 24);
    for (size_t i = 0; i * every < pixels.size(); ++i) pixels[i] = pixels[i * every];
    pixels.resize((pixels.size() + every - 1) / every);
    return pixels;
}

// Each pick of `picked` names the part the CPU's ray cast of `exploded` meets at its pixel.
void expectPicksMeetTheRayCast(const app::HeadlessResult& picked, const scene::Scene& exploded,
                               const scene::Camera& camera) {
    const scene::RayCaster caster(exploded);
    const glm::dmat4 viewProj = camera.viewProjection(double(W) / double(H));
    for (const auto& pick : picked.picks) {
        const auto hit = caster.cast(
            scene::pixelRay(viewProj, glm::vec2(float(W), float(H)), glm::vec2(pick.pixel) + 0.5f));
        ASSERT_TRUE(hit.has_value()) << pick.pixel.x << "," << pick.pixel.y;
        EXPECT_EQ(pick.part.value_or(gpu::BACKGROUND_ID), hit->uniquePartId)
            << "pick at " << pick.pixel.x << "," << pick.pixel.y;
    }
}

// What the CPU answers headless at explode 0.7 sees the parts where they are drawn: the face
// report of `part`, under pixel `at`, boxes the point the measurement from `at` to `other`
// gives there, and the box of the part at rest does not (it moved).
void expectFaceInfoWhereThePartIsDrawn(app::Options::Pixel at, app::Options::Pixel other,
                                       uint32_t part, const scene::Scene& rest,
                                       const scene::Scene& exploded) {
    const std::string measure = std::to_string(at.x) + "," + std::to_string(at.y) + "," +
                                std::to_string(other.x) + "," + std::to_string(other.y);
    app::Options inspect = app::parseArgs(
        {"--headless", "--size", std::to_string(W) + "x" + std::to_string(H), "--scene",
         "procedural:preset=small,seed=1", "--explode", "0.7", "--frames", "1", "--measure",
         measure, "--face-info", std::to_string(at.x) + "," + std::to_string(at.y)});
    testing::internal::CaptureStdout();
    const int code = app::runHeadless(inspect);
    const std::string lines = testing::internal::GetCapturedStdout();
    ASSERT_EQ(code, 0);
    auto numbers = [&](const std::string& key) { // the three numbers after `key`
        glm::dvec3 v(0.0);
        const size_t found = lines.find(key);
        EXPECT_NE(found, std::string::npos) << key << " in " << lines;
        if (found != std::string::npos)
            std::sscanf(lines.c_str() + found + key.size(), "%lf,%lf,%lf", &v.x, &v.y, &v.z);
        return v;
    };
    const glm::dvec3 point = numbers("\"p0\":["), lo = numbers("\"min\":["),
                     hi = numbers("\"max\":[");
    const double slack = 1e-4 * exploded.bounds().radius();
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(point, lo - slack)) &&
                glm::all(glm::lessThanEqual(point, hi + slack)))
        << lines;
    const auto restFace = scene::faceReport(rest, part);
    ASSERT_TRUE(restFace.has_value());
    EXPECT_FALSE(glm::all(glm::greaterThanEqual(point, restFace->bbox.min - slack)) &&
                 glm::all(glm::lessThanEqual(point, restFace->bbox.max + slack)))
        << "the part did not move";
}

// `idview --headless --explode F` end to end: its ID image is the exploded scene's drawn at
// rest, both framed by the opening view of the exploded scene; and at that explode the GPU's
// picks name the part the CPU's ray cast of the exploded scene meets.
TEST(GpuExplode, HeadlessFlagDrawsAndPicksTheExplodedScene) {
    Fixture& f = fixture();
    const float explode = 0.7f;
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("idview_explode_" + std::to_string(::getpid()) + ".ids"))
                                 .string();
    const app::Options flag = app::parseArgs(
        {"--headless", "--validation", "--size", std::to_string(W) + "x" + std::to_string(H),
         "--scene", "procedural:preset=small,seed=1", "--explode", "0.7", "--id-image", path});
    ASSERT_EQ(app::runHeadless(flag), 0);
    const std::vector<uint32_t> flagIds = app::readIdImage(path);
    std::filesystem::remove(path);

    const scene::Scene exploded = scene::explodedScene(f.loaded.scene, explode);
    const scene::Camera camera =
        app::initialCamera(f.loaded, float(W) / float(H), {}, exploded.bounds());
    const app::Options still = testing_support::headlessOptions(W, H);
    const app::HeadlessResult cpu = app::renderHeadless(still, exploded, camera);
    EXPECT_EQ(cpu.validationMessages, 0u);
    ASSERT_EQ(flagIds.size(), cpu.ids.size());
    EXPECT_TRUE(sameIds(flagIds, cpu.ids, W));
    const app::HeadlessResult rest = app::renderHeadless(still, f.loaded.scene, camera);
    EXPECT_GT(idDifference(cpu.ids, rest.ids, W).pixels, cpu.ids.size() / 20) << "nothing moved";

    app::Options picking = still;
    picking.live.animation.explode = explode;
    picking.picks = pixelsInsideParts(cpu.ids);
    ASSERT_GT(picking.picks.size(), 10u);
    const app::HeadlessResult picked = app::renderHeadless(picking, f.loaded.scene, camera);
    EXPECT_EQ(picked.validationMessages, 0u);
    ASSERT_EQ(picked.picks.size(), picking.picks.size());
    expectPicksMeetTheRayCast(picked, exploded, camera);
    ASSERT_TRUE(picked.picks.front().part.has_value());
    expectFaceInfoWhereThePartIsDrawn(picking.picks.front(), picking.picks.back(),
                                      *picked.picks.front().part, f.loaded.scene, exploded);
}

// One renderer, frames in flight: exploded, then back to explode 0, which must restore the
// rest matrices (the dispatch runs once more) even though nothing is recorded afterwards.
TEST(GpuAnimationLoop, ExplodeZeroAfterMotionRestoresTheRestPose) {
    Fixture& f = fixture();
    const app::Options o = renderOptions(render::defaultTechnique(), render::drawModes().back());
    const app::HeadlessResult rest = app::renderHeadless(o, f.loaded.scene, f.camera);
    const app::HeadlessResult moved =
        app::renderHeadless(o, scene::explodedScene(f.loaded.scene, 1.0f), f.camera);
    // A pixel whose part changes with the motion, both images showing a part there.
    size_t at = rest.ids.size();
    for (size_t i = 0; i < rest.ids.size() && at == rest.ids.size(); ++i)
        if (rest.ids[i] != moved.ids[i] && rest.ids[i] != gpu::BACKGROUND_ID &&
            moved.ids[i] != gpu::BACKGROUND_ID)
            at = i;
    ASSERT_LT(at, rest.ids.size());
    const glm::uvec2 pixel(at % W, at / W);

    vk::Instance instance({true, {}});
    std::vector<std::optional<uint32_t>> picked;
    {
        app::Offscreen rig(instance, o);
        rig.renderer.setScene(f.loaded.scene, o.live.render);
        render::FrameParams params = app::cameraFrame(f.camera, rig.extent);
        params.pickPixel = pixel;
        uint64_t frame = 0;
        // Two frames in flight per explode value, then wait and read the pick.
        for (float explode : {1.0f, 0.0f, 0.0f, 1.0f, 0.0f}) {
            params.explode = explode;
            for (int i = 0; i < 2; ++i) {
                render::FrameSlot& slot = rig.slots.begin(frame++);
                rig.renderer.record(slot, rig.targets, params);
                rig.slots.submit(slot);
            }
            rig.slots.finish();
            picked.push_back(rig.slots.latestPick()->part);
        }
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
    const std::optional<uint32_t> atRest = rest.ids[at], atOne = moved.ids[at];
    EXPECT_EQ(picked, (std::vector<std::optional<uint32_t>>{atOne, atRest, atRest, atOne, atRest}));
}

} // namespace
