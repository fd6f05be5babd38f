// test_lod_render.cpp - levels of detail chosen on the GPU (render/culling.h, scene/lod.h), on
// lavapipe with validation on: at error 0 every technique x mode draws the images it drew
// before levels existed; with levels chosen, every culling mode draws culling off's images
// on every frame of a camera path (push mode draws full detail); a huge error draws every object's
// coarsest level, which the engine forced to that level draws too; at a one-pixel error the
// ID image moves only next to full detail's outlines, on the default model and a CAD file,
// while the coarsest levels seen larger move it further (so the check can fail).
#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <filesystem>

#include "app/headless.h"
#include "app/scene_source.h"
#include "image_compare.h"
#include "render/culling.h"
#include "render/technique.h"
#include "scene/lod.h"
#include "test_data.h"
#include "test_support.h"

namespace {

constexpr uint32_t NONE = gpu::BACKGROUND_ID;
using testing_support::sameColours;
using testing_support::sameIds;
// An IGES file from Debian's occt-misc: one object of 213 faces, with Open CASCADE's levels.
const char* const kCadBearing = "/usr/share/opencascade/data/iges/bearing.iges";

app::LoadedScene smallScene(uint32_t lodLevels, uint32_t lodLevel = 0) {
    app::SceneSettings source;
    source.builtin = "procedural:preset=small,seed=1";
    source.copies = 2;
    source.lodLevels = lodLevels;
    source.lodLevel = lodLevel;
    return app::loadScene(source);
}

std::string nameOf(const render::RenderSettings& s) {
    return std::string(s.pipeline.technique->name) + " + " + s.pipeline.mode->name + ", culling " +
           render::cullModeName(s.culling.mode) + ", LOD error " +
           std::to_string(s.lod.errorPixels);
}

// Triangles drawn at the coarser levels over every frame of a result.
uint64_t coarserTriangles(const app::HeadlessResult& r, bool mesh) {
    uint64_t sum = 0;
    for (const gpu::CullStats& stats : r.cullStats) {
        const render::CullCounts c = render::countsOf(stats, mesh);
        for (size_t l = 1; l < c.levelTriangles.size(); ++l) sum += c.levelTriangles[l];
    }
    return sum;
}

} // namespace

// The levels built, at error 0, change nothing: every technique x mode, culling on (the
// default), draws the images of the same scene without levels on every frame of the dolly
// path.
TEST(LodRender, ErrorZeroDrawsTheImagesOfNoLevels) {
    const app::LoadedScene plain = smallScene(1);
    const app::LoadedScene levels = smallScene(scene::maxLevels);
    ASSERT_GT(levels.scene.geometries.size(), plain.scene.geometries.size());
    constexpr uint32_t W = 160, H = 90, frames = 3;
    std::vector<render::RenderSettings> configs;
    for (const render::Technique& t : render::techniques())
        for (const render::DrawMode& m : render::drawModes())
            configs.push_back(testing_support::settingsFor(t, m));
    app::Options o = testing_support::headlessOptions(W, H, frames);
    o.cameraPath = scene::CameraPath::Dolly;
    o.keepEveryFrame = true;
    const scene::Camera camera = app::initialCamera(plain, float(W) / float(H));
    const auto before = app::renderHeadlessSequence(o, plain.scene, camera, configs);
    const auto after = app::renderHeadlessSequence(o, levels.scene, camera, configs);
    EXPECT_EQ(before.front().validationMessages, 0u);
    EXPECT_EQ(after.front().validationMessages, 0u);
    for (size_t c = 0; c < configs.size(); ++c) {
        ASSERT_EQ(after[c].frames.size(), frames) << nameOf(configs[c]);
        for (uint32_t f = 0; f < frames; ++f) {
            EXPECT_TRUE(sameIds(after[c].frames[f].ids, before[c].frames[f].ids, W))
                << nameOf(configs[c]) << ", frame " << f;
            EXPECT_TRUE(sameColours(after[c].frames[f].color, before[c].frames[f].color, W))
                << nameOf(configs[c]) << ", frame " << f;
        }
    }
}

// With levels chosen, the images do not depend on the culling: frustum and two-phase
// occlusion culling draw what culling off draws (the cull pass's levels step alone), on every
// frame of a path along which objects change level, for every technique in the modes that
// choose levels; push mode draws full detail, the images of error 0.
TEST(LodRender, CullingDrawsTheImagesOfCullingOffWithLevelsChosen) {
    const app::LoadedScene loaded = smallScene(scene::maxLevels);
    constexpr uint32_t W = 160, H = 90, frames = 4;
    const std::vector<render::CullMode> modes = {render::CullMode::Off, render::CullMode::Frustum,
                                                 render::CullMode::Occlusion};
    std::vector<render::RenderSettings> configs;
    std::vector<size_t> referenceOf; // per config: its technique and mode's culling off
    for (const render::Technique& t : render::techniques())
        for (const render::DrawMode& m : render::drawModes())
            for (render::CullMode mode : modes) {
                const size_t reference =
                    mode == modes.front() ? configs.size() : referenceOf.back();
                referenceOf.push_back(reference);
                configs.push_back(testing_support::settingsFor(t, m));
                configs.back().culling.mode = mode;
                configs.back().lod.errorPixels = render::levelsChosenIn(m) ? 1.0f : 0.0f;
                if (render::levelsChosenIn(m)) continue;
                // Push mode: the same with an error, which it cannot honour.
                referenceOf.push_back(reference);
                configs.push_back(configs.back());
                configs.back().lod.errorPixels = 1.0f;
            }
    app::Options o = testing_support::headlessOptions(W, H, frames);
    o.cameraPath = scene::CameraPath::Dolly;
    o.keepEveryFrame = true;
    const scene::Camera camera = app::initialCamera(loaded, float(W) / float(H));
    const auto results = app::renderHeadlessSequence(o, loaded.scene, camera, configs);
    EXPECT_EQ(results.front().validationMessages, 0u);
    size_t chosen = 0;
    for (size_t c = 0; c < configs.size(); ++c) {
        const size_t reference = referenceOf[c];
        const std::string name = nameOf(configs[c]);
        ASSERT_EQ(results[c].frames.size(), frames) << name;
        for (uint32_t f = 0; f < frames; ++f) {
            EXPECT_TRUE(sameIds(results[c].frames[f].ids, results[reference].frames[f].ids, W))
                << name << ", frame " << f;
            EXPECT_TRUE(
                sameColours(results[c].frames[f].color, results[reference].frames[f].color, W))
                << name << ", frame " << f;
        }
        const bool mesh = configs[c].pipeline.technique->usesMeshShader();
        if (!render::levelsChosenIn(*configs[c].pipeline.mode)) {
            EXPECT_EQ(coarserTriangles(results[c], mesh), 0u) << name << ": push mode chose";
            continue;
        }
        // Levels were chosen, and not only the coarsest: the path comes close enough for
        // full detail too.
        ++chosen;
        EXPECT_GT(coarserTriangles(results[c], mesh), 0u) << name;
        uint64_t full = 0;
        for (const gpu::CullStats& stats : results[c].cullStats)
            full += render::countsOf(stats, mesh).levelTriangles[0];
        EXPECT_GT(full, 0u) << name;
    }
    EXPECT_GE(chosen, 3u * render::techniques().size());
}

// An error no level reaches draws every object at its coarsest level: the GPU's choice draws
// the image of the engine forced to that level, for every technique in every mode that
// chooses, and the counters put every triangle at the coarser levels.
TEST(LodRender, AHugeErrorDrawsTheCoarsestLevel) {
    const app::LoadedScene chosen = smallScene(scene::maxLevels);
    const app::LoadedScene forced = smallScene(scene::maxLevels, scene::maxLevels - 1);
    constexpr uint32_t W = 160, H = 90;
    std::vector<render::RenderSettings> configs, references;
    for (const render::Technique& t : render::techniques())
        for (const render::DrawMode& m : render::drawModes()) {
            if (!render::cullPlan(t, m, render::CullMode::Occlusion).gpuLists) continue;
            references.push_back(testing_support::settingsFor(t, m));
            configs.push_back(references.back());
            configs.back().lod.errorPixels = 1e6f;
        }
    const app::Options o = testing_support::headlessOptions(W, H, 2);
    const scene::Camera camera = app::initialCamera(chosen, float(W) / float(H));
    const auto gpu = app::renderHeadlessSequence(o, chosen.scene, camera, configs);
    const auto engine = app::renderHeadlessSequence(o, forced.scene, camera, references);
    EXPECT_EQ(gpu.front().validationMessages, 0u);
    EXPECT_EQ(engine.front().validationMessages, 0u);
    for (size_t c = 0; c < configs.size(); ++c) {
        const std::string name = nameOf(configs[c]);
        EXPECT_TRUE(sameIds(gpu[c].ids, engine[c].ids, W)) << name;
        EXPECT_TRUE(sameColours(gpu[c].color, engine[c].color, W)) << name;
        ASSERT_FALSE(gpu[c].cullStats.empty()) << name;
        const render::CullCounts counts = render::countsOf(
            gpu[c].cullStats.back(), configs[c].pipeline.technique->usesMeshShader());
        EXPECT_GT(counts.triangles, 0u) << name;
        uint64_t coarser = 0;
        for (size_t l = 1; l < counts.levelTriangles.size(); ++l)
            coarser += counts.levelTriangles[l];
        EXPECT_EQ(coarser + counts.levelTriangles[0], counts.triangles) << name;
        EXPECT_GT(coarser, 0u) << name;
        // Level by level what the forced engine draws: full detail only where an object has
        // no coarser level.
        ASSERT_FALSE(engine[c].cullStats.empty()) << name;
        const render::CullCounts forcedCounts = render::countsOf(
            engine[c].cullStats.back(), configs[c].pipeline.technique->usesMeshShader());
        EXPECT_EQ(counts.levelTriangles, forcedCounts.levelTriangles) << name;
    }
}

namespace {

// Chebyshev distance of every pixel to the nearest outline pixel of `ids` (a pixel whose
// right or lower neighbour shows another part or background, and that neighbour), capped.
std::vector<uint32_t> outlineDistance(const std::vector<uint32_t>& ids, uint32_t w, uint32_t h,
                                      uint32_t cap) {
    std::vector<uint32_t> distance(ids.size(), cap);
    std::deque<size_t> queue;
    auto mark = [&](size_t i) {
        if (distance[i] != 0) queue.push_back(i);
        distance[i] = 0;
    };
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            if (x + 1 < w && ids[i + 1] != ids[i]) mark(i), mark(i + 1);
            if (y + 1 < h && ids[i + w] != ids[i]) mark(i), mark(i + w);
        }
    while (!queue.empty()) {
        const size_t i = queue.front();
        queue.pop_front();
        const int x = int(i % w), y = int(i / w);
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                if (x + dx < 0 || y + dy < 0 || x + dx >= int(w) || y + dy >= int(h)) continue;
                const size_t j = size_t(y + dy) * w + size_t(x + dx);
                if (distance[j] > distance[i] + 1) {
                    distance[j] = distance[i] + 1;
                    queue.push_back(j);
                }
            }
    }
    return distance;
}

struct Moved {
    size_t changed = 0; // pixels whose part differs from full detail's
    size_t far = 0;     // of which further than 2 pixels from full detail's outlines
    std::string first;  // where the first far one is
};

Moved movedPixels(const std::vector<uint32_t>& full, const std::vector<uint32_t>& level, uint32_t w,
                  uint32_t h) {
    const std::vector<uint32_t> distance = outlineDistance(full, w, h, 99);
    Moved m;
    for (size_t i = 0; i < full.size(); ++i) {
        if (full[i] == level[i]) continue;
        ++m.changed;
        if (distance[i] <= 2) continue;
        if (m.far++ == 0)
            m.first = std::to_string(i % w) + "," + std::to_string(i / w) + ": part " +
                      std::to_string(full[i]) + " became " +
                      (level[i] == NONE ? std::string("background") : std::to_string(level[i]));
    }
    return m;
}

// At a one-pixel error, on every frame of the dolly path (the fitted view, into the assembly
// and out) at w x h, each pixel whose part differs from full detail's lies within 2 pixels of
// an outline of full detail's ID image: no part moves further, no crack opens where full
// detail shows a surface. Where `zoom` is given, the rule is shown to fail: every object at
// its coarsest level, seen `zoom` times larger, moves pixels further.
void expectNearOutlines(const app::SceneSettings& source, uint32_t w, uint32_t h, uint32_t zoom) {
    const app::LoadedScene loaded = app::loadScene(source);
    const uint32_t frames = 4;
    std::vector<render::RenderSettings> configs(
        2, testing_support::settingsFor(*render::findTechnique("vertex-fs"),
                                        *render::findDrawMode("mdi-baseinstance")));
    configs[1].lod.errorPixels = 1.0f;
    app::Options o = testing_support::headlessOptions(w, h, frames);
    o.cameraPath = scene::CameraPath::Dolly;
    o.keepEveryFrame = true;
    const scene::Camera camera = app::initialCamera(loaded, float(w) / float(h));
    const auto results = app::renderHeadlessSequence(o, loaded.scene, camera, configs);
    EXPECT_EQ(results.front().validationMessages, 0u);
    ASSERT_EQ(results[1].frames.size(), frames);
    size_t changed = 0;
    for (uint32_t f = 0; f < frames; ++f) {
        const Moved one = movedPixels(results[0].frames[f].ids, results[1].frames[f].ids, w, h);
        EXPECT_EQ(one.far, 0u) << "frame " << f << ", first at " << one.first;
        changed += one.changed;
    }
    // The levels were drawn and changed the image.
    EXPECT_GT(coarserTriangles(results[1], false), 0u);
    EXPECT_GT(changed, 0u);

    if (zoom == 0) return;
    configs[1].lod.errorPixels = 1e6f;
    const app::Options large = testing_support::headlessOptions(w * zoom, h * zoom);
    const auto coarsest = app::renderHeadlessSequence(large, loaded.scene, camera, configs);
    EXPECT_GT(movedPixels(coarsest[0].ids, coarsest[1].ids, w * zoom, h * zoom).far, 0u);
}

} // namespace

TEST(LodRender, AOnePixelErrorMovesPartsOnlyNextToOutlinesOnTheDefaultModel) {
    app::SceneSettings source;
    source.lodLevels = scene::maxLevels;
    expectNearOutlines(source, 320, 180, 4);
}

TEST(LodRender, AOnePixelErrorMovesPartsOnlyNextToOutlinesOnACadFile) {
    REQUIRE_DATA(kCadBearing);
    app::SceneSettings source;
    source.model = kCadBearing;
    source.lodLevels = scene::maxLevels;
    // Small enough for the first level to be chosen: its error is 0.7 % of the diagonal.
    // Open CASCADE's coarsest level of this file moves no pixel beyond 2 pixels even at
    // 1280x720 (tried), so the failing side is shown on the default model only.
    expectNearOutlines(source, 160, 90, 0);
}

// In a still view a new error chooses the levels again: the images are those of a run that
// started with the new error. Kept draw lists (and their culling history) carry over between
// the two settings.
TEST(LodRender, ChangingTheErrorInAStillViewChoosesAgain) {
    const app::LoadedScene loaded = smallScene(scene::maxLevels);
    constexpr uint32_t W = 160, H = 90;
    std::vector<render::RenderSettings> sequence, fresh;
    for (const char* name : {"vertex-fs", "mesh-fs"}) {
        render::RenderSettings s = testing_support::settingsFor(
            *render::findTechnique(name), *render::findDrawMode("mdi-baseinstance"));
        s.lod.errorPixels = 0.01f; // full detail, mostly
        sequence.push_back(s);
        s.lod.errorPixels = 1e6f;
        sequence.push_back(s);
        fresh.push_back(s);
    }
    const app::Options o = testing_support::headlessOptions(W, H, 5);
    const scene::Camera camera = app::initialCamera(loaded, float(W) / float(H));
    const auto switched = app::renderHeadlessSequence(o, loaded.scene, camera, sequence);
    EXPECT_EQ(switched.front().validationMessages, 0u);
    for (size_t i = 0; i < fresh.size(); ++i) {
        const auto alone = app::renderHeadlessSequence(o, loaded.scene, camera, {fresh[i]});
        const app::HeadlessResult& before = switched[2 * i];
        const app::HeadlessResult& after = switched[2 * i + 1];
        const std::string name = nameOf(fresh[i]);
        EXPECT_TRUE(sameIds(after.ids, alone.front().ids, W)) << name;
        EXPECT_TRUE(sameColours(after.color, alone.front().color, W)) << name;
        EXPECT_FALSE(sameIds(after.ids, before.ids, W)) << name;
    }
}

namespace {

// The triangles per level the scene draws in an orthographic view of `camera` at `errorPixels`
// when every object is in view, as the CPU works it out: a world unit spans viewport height /
// view height pixels at any depth, so an object of scale s takes its coarsest level whose
// error e keeps e * s * pixels per unit under the error asked (full detail always fits).
// `margin` gets the smallest relative distance of any object's error from that bound.
std::array<uint64_t, gpu::LOD_MAX_LEVELS> orthoLevelTriangles(const scene::Scene& s,
                                                              const scene::Camera& camera,
                                                              uint32_t height, float errorPixels,
                                                              double& margin) {
    std::array<uint64_t, gpu::LOD_MAX_LEVELS> triangles{};
    const double pixelsPerUnit = double(height) / double(camera.orthoHeight());
    margin = 1e30;
    for (const scene::Object& object : s.objects) {
        const double scale = std::max({glm::length(glm::vec3(object.world[0])),
                                       glm::length(glm::vec3(object.world[1])),
                                       glm::length(glm::vec3(object.world[2]))});
        uint32_t chosen = object.geometry;
        for (uint32_t level = 1; level < gpu::LOD_MAX_LEVELS; ++level) {
            const uint32_t g = scene::geometryAtLevel(s, object.geometry, level);
            if (g == scene::geometryAtLevel(s, object.geometry, level - 1)) break;
            const double pixels = double(s.geometries[g].lodError) * scale * pixelsPerUnit;
            margin = std::min(margin, std::abs(pixels / errorPixels - 1.0));
            if (pixels < errorPixels) chosen = g;
        }
        triangles[s.geometries[chosen].level] += s.geometries[chosen].triangleCount;
    }
    return triangles;
}

} // namespace

// In ortho the GPU chooses each object's level by the constant pixels per world unit: with
// the whole scene in view, the triangles drawn at each level are exactly those the CPU's
// choice gives, for an error where no object lies within 1% of its bound and objects draw
// different levels (the CPU's count at twice the error differs, so a wrong scale would show).
TEST(LodRender, OrthoChoosesTheLevelsTheCpuWorksOut) {
    const app::LoadedScene loaded = smallScene(scene::maxLevels);
    constexpr uint32_t W = 160, H = 90;
    const scene::Camera camera = app::initialCamera(loaded, float(W) / float(H),
                                                    {scene::findStandardView("isometric"), true});
    float error = 0.0f;
    std::array<uint64_t, gpu::LOD_MAX_LEVELS> expected{};
    for (float candidate : {1.0f, 1.3f, 1.7f, 2.2f, 0.7f, 3.0f}) {
        double margin = 0.0;
        expected = orthoLevelTriangles(loaded.scene, camera, H, candidate, margin);
        const size_t levelsUsed = size_t(
            std::count_if(expected.begin(), expected.end(), [](uint64_t t) { return t != 0; }));
        if (margin > 0.01 && levelsUsed >= 2) {
            error = candidate;
            break;
        }
    }
    ASSERT_GT(error, 0.0f) << "no error tried gives a clear choice of several levels";
    double unused = 0.0;
    EXPECT_NE(orthoLevelTriangles(loaded.scene, camera, H, 2.0f * error, unused), expected);

    render::RenderSettings s = testing_support::settingsFor(
        *render::findTechnique("vertex-fs"), *render::findDrawMode("mdi-baseinstance"));
    s.culling.mode = render::CullMode::Frustum;
    s.lod.errorPixels = error;
    const auto results = app::renderHeadlessSequence(testing_support::headlessOptions(W, H, 2),
                                                     loaded.scene, camera, {s});
    EXPECT_EQ(results.front().validationMessages, 0u);
    ASSERT_FALSE(results.front().cullStats.empty());
    const render::CullCounts counts = render::countsOf(results.front().cullStats.back(), false);
    for (size_t l = 0; l < expected.size(); ++l)
        EXPECT_EQ(counts.levelTriangles[l], expected[l])
            << "level " << l << " at " << error << " px";
}
