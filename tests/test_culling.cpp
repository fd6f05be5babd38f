// test_culling.cpp - culling leaves the images exactly as they are without it
// (render/culling.h): every technique x mode of the registry, the floors included, at 1x and
// 4x MSAA, on every frame of a dolly path over the default model and a CAD file (and of an
// orbit in orthographic projection), frustum and occlusion culling draw the ID and colour
// images of culling off byte for byte. The counters, hidden objects, freezing, and a pyramid
// test shrunk by one pixel are in test_culling_edges.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>

#include "app/headless.h"
#include "app/scene_source.h"
#include "image_compare.h"
#include "render/culling.h"
#include "render/technique.h"
#include "shader_copy.h"
#include "test_data.h"
#include "test_support.h"

namespace {

// An IGES file from Debian's occt-misc: one object of 213 faces (one part each).
const char* const kCadBearing = "/usr/share/opencascade/data/iges/bearing.iges";

constexpr uint32_t W = 160, H = 90;
// Frames along the dolly path: the fitted view, halfway in, the middle of the assembly and
// halfway out again, so the frustum leaves out more and more and the last ID image is
// always from another view.
constexpr uint32_t kFrames = 4;

// The default model's cases are split by pipeline (vertex or mesh shader), so ctest runs
// them side by side.
enum class Pipelines { Vertex, Mesh, All };

struct PathCase {
    const char* scene; // "default" or "cad"
    uint32_t msaa;
    Pipelines pipelines;
    // The camera stands still instead of flying the dolly path: every frame culls again from
    // the history the one before left, from the second frame on each cluster with history
    // by itself (FRAME_VIEW_UNCHANGED). Only occlusion culling keeps a history, so a still
    // case leaves frustum out.
    bool still = false;
    // Orthographic: the opening view zoomed in to a third of the fitted distance (so the
    // frustum leaves parts out), orbiting the target about the up axis, since an ortho dolly
    // would keep the view's size: the frustum's planes and the pyramid with w 1 everywhere,
    // and a near plane behind the eye.
    bool ortho = false;
    // Cut by a section plane through the middle, on the camera's side: the caps and what the
    // cut opens to view are culled as everything else.
    bool section = false;
    // Frustum culling decides by boxes against the view, whatever the sample count: over the
    // default model it is tested at 1x (on the CAD file at both), which keeps the suite's
    // heaviest rendering to what can differ.
    bool frustum() const { return !still && (msaa == 1 || std::string(scene) == "cad" || ortho); }
};

const char* pipelinesName(Pipelines p) {
    return p == Pipelines::Vertex ? "vertex" : p == Pipelines::Mesh ? "mesh" : "all";
}

void PrintTo(const PathCase& c, std::ostream* os) {
    *os << c.scene << " msaa " << c.msaa << " " << pipelinesName(c.pipelines)
        << (c.still ? " still" : "") << (c.ortho ? " ortho" : "") << (c.section ? " section" : "");
}

class CullingExact : public ::testing::TestWithParam<PathCase> {};

// The case's camera: the opening view, or for ortho a third of its distance away.
scene::Camera pathCamera(const PathCase& c, const app::LoadedScene& loaded) {
    if (!c.ortho) return app::initialCamera(loaded, float(W) / float(H));
    scene::Camera camera = app::initialCamera(loaded, float(W) / float(H), {nullptr, true});
    camera.eye = camera.target + (camera.eye - camera.target) / 3.0;
    scene::fitPlanes(camera, loaded.scene.bounds());
    return camera;
}

// What a case renders: per technique the reference without culling, then every mode with
// each culling mode the case tests (referenceOf: config -> its technique's reference).
struct PathConfigs {
    std::vector<render::RenderSettings> configs;
    std::map<size_t, size_t> referenceOf;
};

PathConfigs pathConfigs(const PathCase& c, const scene::Camera& camera) {
    PathConfigs p;
    for (const render::Technique& t : render::techniques()) {
        if (c.pipelines != Pipelines::All && t.usesMeshShader() != (c.pipelines == Pipelines::Mesh))
            continue;
        const size_t reference = p.configs.size();
        p.configs.push_back(testing_support::settingsFor(t, render::defaultDrawMode()));
        p.configs.back().culling.mode = render::CullMode::Off;
        for (const render::DrawMode& m : render::drawModes())
            for (render::CullMode mode : {render::CullMode::Frustum, render::CullMode::Occlusion}) {
                if (mode == render::CullMode::Frustum && !c.frustum()) continue;
                // Where occlusion gets nothing more than frustum culling (push mode's vertex
                // pipelines), it draws the same lists: once is enough, whichever of the two
                // the case tests.
                const render::CullPlan plan = render::cullPlan(t, m, mode);
                if (mode == render::CullMode::Occlusion && !plan.twoPasses && c.frustum()) continue;
                p.referenceOf[p.configs.size()] = reference;
                p.configs.push_back(testing_support::settingsFor(t, m));
                p.configs.back().culling.mode = mode;
            }
    }
    scene::Section section;
    if (c.section) { // across the axis the camera looks along most, the camera's side cut away
        const glm::vec3 look = camera.target - camera.eye;
        const glm::vec3 size = glm::abs(look);
        const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
        section.planes[0] = scene::axisPlane(axis, camera.target[axis], look[axis] > 0.0f);
    }
    for (render::RenderSettings& s : p.configs) {
        s.pipeline.msaa = c.msaa;
        s.section = section;
    }
    // The section case also draws the first reference uncut: the plane must cut something.
    if (c.section) {
        p.configs.push_back(p.configs.front());
        p.configs.back().section = {};
    }
    return p;
}

// A culled configuration drew its reference's images on every frame, and never more
// triangles than there are; along a path it left something out (where there is more than
// the one object the CAD file is, or smaller draws, or meshlets).
void expectCulledAsReference(const PathCase& c, const app::LoadedScene& loaded,
                             const render::RenderSettings& s, const app::HeadlessResult& r,
                             const app::HeadlessResult& ref) {
    const std::string name = std::string(s.pipeline.technique->name) + " + " +
                             s.pipeline.mode->name + ", culling " +
                             render::cullModeName(s.culling.mode);
    ASSERT_EQ(r.frames.size(), kFrames) << name;
    ASSERT_EQ(ref.frames.size(), kFrames) << name;
    for (uint32_t f = 0; f < kFrames; ++f) {
        EXPECT_TRUE(testing_support::sameIds(r.frames[f].ids, ref.frames[f].ids, W))
            << name << ", frame " << f;
        EXPECT_TRUE(testing_support::sameColours(r.frames[f].color, ref.frames[f].color, W))
            << name << ", frame " << f;
    }
    uint64_t drawn = 0, total = 0;
    ASSERT_EQ(r.cullStats.size(), kFrames) << name;
    for (const gpu::CullStats& stats : r.cullStats) {
        const render::CullCounts counts =
            render::countsOf(stats, s.pipeline.technique->usesMeshShader());
        EXPECT_LE(counts.triangles, r.cullTotals.triangles) << name;
        drawn += counts.triangles;
        total += r.cullTotals.triangles;
    }
    // Where a draw is the one object of the CAD file (push mode culls whole objects, search
    // batches span the ring), only meshlets and single parts can be left out.
    const render::Technique& t = *s.pipeline.technique;
    const bool partsCulled = s.pipeline.mode->indirect && t.split == render::DrawSplit::PerPart;
    if (!c.still && (loaded.scene.objects.size() > 1 || partsCulled || t.usesMeshShader())) {
        EXPECT_LT(drawn, total) << name << ": culling left nothing out along the path";
    }
}

// Without culling every frame draws everything.
void expectEverythingDrawn(const render::RenderSettings& s, const app::HeadlessResult& r) {
    const bool mesh = s.pipeline.technique->usesMeshShader();
    for (const gpu::CullStats& stats : r.cullStats) {
        const render::CullCounts counts = render::countsOf(stats, mesh);
        EXPECT_EQ(counts.draws, r.cullTotals.draws);
        EXPECT_EQ(counts.triangles, r.cullTotals.triangles);
        EXPECT_EQ(counts.meshlets, r.cullTotals.meshlets);
    }
}

TEST_P(CullingExact, EveryTechniqueAndModeDrawsTheImagesOfCullingOffOnEveryFrame) {
    const PathCase& c = GetParam();
    app::SceneSettings source;
    if (std::string(c.scene) == "cad") {
        REQUIRE_DATA(kCadBearing);
        source.model = kCadBearing;
    }
    const app::LoadedScene loaded = app::loadScene(source);
    const scene::Camera camera = pathCamera(c, loaded);
    const PathConfigs p = pathConfigs(c, camera);
    app::Options o = testing_support::headlessOptions(W, H, kFrames);
    o.cameraPath = c.still   ? scene::CameraPath::None
                   : c.ortho ? scene::CameraPath::Orbit
                             : scene::CameraPath::Dolly;
    o.keepEveryFrame = true;
    const auto results = app::renderHeadlessSequence(o, loaded.scene, camera, p.configs);
    ASSERT_EQ(results.size(), p.configs.size());
    EXPECT_EQ(results.front().validationMessages, 0u);
    for (const auto& [culled, reference] : p.referenceOf)
        expectCulledAsReference(c, loaded, p.configs[culled], results[culled], results[reference]);
    if (c.section) {
        EXPECT_NE(results.back().frames.back().ids, results.front().frames.back().ids);
    }
    for (size_t i = 0; i < p.configs.size(); ++i)
        if (!p.referenceOf.count(i)) expectEverythingDrawn(p.configs[i], results[i]);
}

INSTANTIATE_TEST_SUITE_P(
    Lavapipe, CullingExact,
    ::testing::Values(
        PathCase{"default", 1, Pipelines::Vertex}, PathCase{"default", 1, Pipelines::Mesh},
        PathCase{"default", 4, Pipelines::Vertex}, PathCase{"default", 4, Pipelines::Mesh},
        PathCase{"cad", 1, Pipelines::All}, PathCase{"cad", 4, Pipelines::All},
        PathCase{"default", 1, Pipelines::Vertex, true}, PathCase{"cad", 1, Pipelines::All, true},
        PathCase{"cad", 4, Pipelines::All, true},
        PathCase{"cad", 1, Pipelines::All, false, false, true},
        PathCase{"cad", 4, Pipelines::All, false, false, true},
        PathCase{"cad", 1, Pipelines::All, true, false, true},
        // Orthographic over the CAD file: over the default model the two cases took four
        // minutes of the suite's time, and the frustum and pyramid code they test is the same.
        PathCase{"cad", 1, Pipelines::All, false, true},
        PathCase{"cad", 4, Pipelines::All, false, true}),
    [](const ::testing::TestParamInfo<PathCase>& info) {
        return std::string(info.param.scene) + "_msaa" + std::to_string(info.param.msaa) + "_" +
               pipelinesName(info.param.pipelines) + (info.param.still ? "_still" : "") +
               (info.param.ortho ? "_ortho" : "") + (info.param.section ? "_section" : "");
    });

// In a still view cluster runs draw first just the clusters that passed the last frame's
// test, each by itself (FRAME_VIEW_UNCHANGED): fewer triangles than an object's first
// clusters up to the last that passed (what a moving view draws first), with the images of
// culling off either way.
TEST(CullingStill, ClusterRunsDrawFewerTrianglesOnceTheViewStandsStill) {
    const app::LoadedScene loaded = app::loadScene(app::SceneSettings{});
    const scene::Camera camera = app::initialCamera(loaded, float(W) / float(H));
    const std::filesystem::path moving = testing_support::shaderCopy("still-as-moving");
    testing_support::replaceInFile(moving / "cull_runs.glsl",
                                   "if ((cullFrame().flags & FRAME_VIEW_UNCHANGED) != 0u)",
                                   "if (false)");
    std::vector<render::RenderSettings> configs;
    for (render::CullMode mode : {render::CullMode::Off, render::CullMode::Occlusion}) {
        configs.push_back(testing_support::settingsFor(*render::findTechnique("vertex-fs"),
                                                       *render::findDrawMode("mdi-baseinstance")));
        configs.back().culling.mode = mode;
    }
    app::Options o = testing_support::headlessOptions(W, H, kFrames);
    const auto still = app::renderHeadlessSequence(o, loaded.scene, camera, configs);
    o.shaderDir = moving.string();
    const auto asMoving = app::renderHeadlessSequence(o, loaded.scene, camera, configs);
    std::filesystem::remove_all(moving);
    ASSERT_EQ(still.size(), 2u);
    ASSERT_EQ(asMoving.size(), 2u);
    EXPECT_EQ(still.front().validationMessages, 0u);
    EXPECT_TRUE(still[1].ids == still[0].ids);
    EXPECT_TRUE(still[1].color == still[0].color);
    EXPECT_TRUE(asMoving[1].ids == still[0].ids);
    const uint64_t drawn = render::countsOf(still[1].cullStats.back(), false).triangles;
    const uint64_t drawnAsMoving = render::countsOf(asMoving[1].cullStats.back(), false).triangles;
    EXPECT_LT(drawn, drawnAsMoving);
}

// The per-frame histories (counters, GPU times) are in frame order, whichever frame slot
// the run ends on: the counters of a run along the dolly path equal those of the same run
// that waits for every frame before it records the next.
TEST(CullingCounters, StayInFrameOrderAtTheEndOfARun) {
    const app::LoadedScene loaded = app::loadScene(app::SceneSettings{});
    const scene::Camera camera = app::initialCamera(loaded, float(W) / float(H));
    render::RenderSettings s = testing_support::settingsFor(
        *render::findTechnique("vertex-fs"), *render::findDrawMode("mdi-baseinstance"));
    s.culling.mode = render::CullMode::Occlusion;
    // An odd count: the last frame is in the first slot, the one before it in the second.
    app::Options o = testing_support::headlessOptions(W, H, 3);
    o.cameraPath = scene::CameraPath::Dolly;
    const auto overlapped = app::renderHeadlessSequence(o, loaded.scene, camera, {s});
    o.keepEveryFrame = true;
    const auto oneByOne = app::renderHeadlessSequence(o, loaded.scene, camera, {s});
    auto triangles = [](const app::HeadlessResult& r) {
        std::vector<uint64_t> t;
        for (const gpu::CullStats& stats : r.cullStats)
            t.push_back(render::countsOf(stats, false).triangles);
        return t;
    };
    const std::vector<uint64_t> expected = triangles(oneByOne.front());
    ASSERT_EQ(expected.size(), 3u);
    ASSERT_NE(expected[1], expected[2]) << "the path should draw other triangles each frame";
    EXPECT_EQ(triangles(overlapped.front()), expected);
    EXPECT_EQ(overlapped.front().validationMessages, 0u);
}

} // namespace
