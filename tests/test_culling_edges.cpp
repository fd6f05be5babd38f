// test_culling_edges.cpp - the edges of culling (render/culling.h), on lavapipe with
// validation on: a part hidden behind an occluder but for one pixel column is drawn by every
// technique and mode that tests the depth pyramid, and a pyramid test whose rectangles are
// shrunk by one pixel loses it; two parts of one object that tie in depth keep their order;
// the counters agree with a count on the CPU; objects whose parts are all hidden are never
// drawn; with MSAA a part that shows in a sample other than the resolved one is drawn first;
// a frozen list keeps drawing while the camera moves.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "app/camera_frame.h"
#include "app/headless.h"
#include "app/offscreen.h"
#include "app/scene_source.h"
#include "image_compare.h"
#include "render/culling.h"
#include "scene/camera_path.h"
#include "scene/mesh_builder.h"
#include "shader_copy.h"
#include "test_support.h"

namespace fs = std::filesystem;

namespace {

using testing_support::replaceInFile;
using testing_support::shaderCopy;

constexpr uint32_t SW = 64, SH = 48; // the sliver scene's image
constexpr glm::uvec2 kSliver{32, 21};

// A flat square in clip space (the tests draw with test_support.h's flat camera, so x and y
// map straight to pixels: x = px / 32 - 1, y = py / 24 - 1) at z, nearer the smaller z.
uint32_t square(scene::Scene& s, float x0, float y0, float x1, float y1, float z,
                const char* name) {
    scene::MeshBuilder mb;
    const glm::vec3 corners[] = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
    mb.addFlatFace(corners);
    return mb.finish(s, name);
}

float px(float pixel) {
    return pixel / 32.0f - 1.0f;
}
float py(float pixel) {
    return pixel / 24.0f - 1.0f;
}

// An occluder over pixels x < 32 at z 0.3, and behind it at 0.6 a square over pixels
// 29.2..32.6 x 20.2..22.6: past the occluder's edge only the pixel column x = 32 shows it.
// Its screen rectangle, pixels 29..32, spans two level-1 texels of the pyramid, the second
// of which (pixels 32..35) holds the background: one pixel less on each side leaves only
// occluder in the rectangle.
scene::Scene sliverScene() {
    scene::Scene s;
    const uint32_t grey = scene::addMaterial(s, "grey", {0.5f, 0.5f, 0.5f, 1});
    const uint32_t occluder = square(s, -1.0f, -1.0f, px(32.0f), 1.0f, 0.3f, "occluder");
    const uint32_t small =
        square(s, px(29.2f), py(20.2f), px(32.6f), py(22.6f), 0.6f, "small part");
    scene::addObject(s, occluder, grey, glm::mat4(1.0f), "occluder");
    scene::addObject(s, small, grey, glm::mat4(1.0f), "small part");
    scene::validate(s);
    return s;
}

// Two parts of one object in one plane: part 0 over pixels 8..40 x 8..40, part 1 over
// 8..56 x 8..40. Where both lie their depths tie exactly, and part 0, drawn first, wins.
scene::Scene tieScene() {
    scene::Scene s;
    const uint32_t grey = scene::addMaterial(s, "grey", {0.5f, 0.5f, 0.5f, 1});
    scene::MeshBuilder mb;
    const glm::vec3 first[] = {
        {px(8), py(8), 0.5f}, {px(40), py(8), 0.5f}, {px(40), py(40), 0.5f}, {px(8), py(40), 0.5f}};
    const glm::vec3 second[] = {
        {px(8), py(8), 0.5f}, {px(56), py(8), 0.5f}, {px(56), py(40), 0.5f}, {px(8), py(40), 0.5f}};
    mb.addFlatFace(first);
    mb.addFlatFace(second);
    scene::addObject(s, mb.finish(s, "two faces in one plane"), grey, glm::mat4(1.0f), "tie");
    scene::validate(s);
    return s;
}

// Frame A with part `hiddenFirst` hidden (so the last ID image lacks it), frame B with every
// part shown: B's ID image, drawn with `settings` and the shaders in `shaderDir`.
std::vector<uint32_t> twoFrameImage(const scene::Scene& s, const render::RenderSettings& settings,
                                    const std::string& shaderDir, uint32_t hiddenFirst,
                                    uint32_t& validationMessages) {
    app::Options o = testing_support::headlessOptions(SW, SH);
    o.shaderDir = shaderDir;
    o.live.render = settings;
    vk::Instance instance({true, {}, false});
    std::vector<uint32_t> ids;
    {
        app::Offscreen rig(instance, o);
        rig.renderer.setScene(s, settings);
        scene::PartSet hidden(s.uniquePartCount());
        hidden.insert(hiddenFirst);
        rig.renderer.setHidden(hidden);
        uint64_t frame = 0;
        testing_support::renderIds(rig, frame);
        rig.renderer.setHidden(scene::PartSet(s.uniquePartCount()));
        ids = testing_support::renderIds(rig, frame);
    }
    validationMessages = instance.validationMessages();
    return ids;
}

// "technique + mode", for failure messages.
std::string nameOf(const render::RenderSettings& settings) {
    return std::string(settings.pipeline.technique->name) + " + " + settings.pipeline.mode->name;
}

// Every part-ID technique and mode whose culling tests the depth pyramid.
std::vector<render::RenderSettings> pyramidConfigs() {
    std::vector<render::RenderSettings> configs;
    for (const render::Technique* t : render::partIdTechniques())
        for (const render::DrawMode& m : render::drawModes())
            if (render::cullPlan(*t, m, render::CullMode::Occlusion).twoPasses) {
                configs.push_back(testing_support::settingsFor(*t, m));
                configs.back().culling.mode = render::CullMode::Occlusion;
            }
    return configs;
}

TEST(CullingSliver, APartShowingOnePixelColumnIsDrawnAndAShrunkTestLosesIt) {
    const scene::Scene s = sliverScene();
    const size_t sliver = size_t(kSliver.y) * SW + kSliver.x;
    uint32_t messages = 0;
    render::RenderSettings off;
    off.culling.mode = render::CullMode::Off;
    const auto reference = twoFrameImage(s, off, IDVIEW_SOURCE_SHADER_DIR, 1, messages);
    EXPECT_EQ(messages, 0u);
    ASSERT_EQ(reference[sliver], 1u) << "the small part should show at the sliver";
    ASSERT_EQ(reference[sliver - 1], 0u) << "the occluder should cover the pixel left of it";

    const fs::path shrunk = shaderCopy("shrunk");
    replaceInFile(shrunk / "cull.glsl", "#define IDV_CULL_SHRINK_PIXELS 0",
                  "#define IDV_CULL_SHRINK_PIXELS 1");
    const auto configs = pyramidConfigs();
    ASSERT_GE(configs.size(), render::partIdTechniques().size()); // every technique, mdi
    for (const render::RenderSettings& settings : configs) {
        const std::string name = nameOf(settings);
        EXPECT_EQ(twoFrameImage(s, settings, IDVIEW_SOURCE_SHADER_DIR, 1, messages), reference)
            << name;
        EXPECT_EQ(messages, 0u) << name;
        const auto wrong = twoFrameImage(s, settings, shrunk.string(), 1, messages);
        EXPECT_NE(wrong[sliver], 1u) << name << ": a test one pixel short still drew the part";
        EXPECT_EQ(messages, 0u) << name;
    }
    fs::remove_all(shrunk);
}

// Where two parts of one object tie in depth, the one first in the list wins with culling as
// without: an object's early clusters are its first ones, up to the last with history, so a
// part the last frame's test lacked is not drawn after a later part of its object.
TEST(CullingOrder, PartsOfOneObjectThatTieInDepthKeepTheirOrder) {
    const scene::Scene s = tieScene();
    uint32_t messages = 0;
    render::RenderSettings off;
    off.culling.mode = render::CullMode::Off;
    const auto reference = twoFrameImage(s, off, IDVIEW_SOURCE_SHADER_DIR, 0, messages);
    EXPECT_EQ(messages, 0u);
    const size_t tie = 20 * SW + 20, alone = 20 * SW + 48;
    ASSERT_EQ(reference[tie], 0u) << "part 0, drawn first, should win the tie";
    ASSERT_EQ(reference[alone], 1u);
    for (const render::RenderSettings& settings : pyramidConfigs()) {
        const std::string name = nameOf(settings);
        EXPECT_EQ(twoFrameImage(s, settings, IDVIEW_SOURCE_SHADER_DIR, 0, messages), reference)
            << name;
        EXPECT_EQ(messages, 0u) << name;
    }

    // Cluster runs: an object's early clusters are its first ones, up to the last that passed
    // the last late test. Choosing them by their own history instead draws part 1's cluster
    // early and part 0's late, and the tie goes to part 1.
    const fs::path history = shaderCopy("cluster-history");
    replaceInFile(history / "cull_runs.glsl", "return pair < historyEnds().values[object];",
                  "return hadHistory(pair);");
    size_t lostByRuns = 0;
    for (const render::RenderSettings& settings : pyramidConfigs()) {
        const auto wrong = twoFrameImage(s, settings, history.string(), 0, messages);
        EXPECT_EQ(messages, 0u) << nameOf(settings);
        if (wrong[tie] != 0u) {
            ++lostByRuns;
            EXPECT_TRUE(settings.pipeline.technique->drawsClusterRuns()) << nameOf(settings);
        }
    }
    size_t runConfigs = 0;
    for (const render::RenderSettings& settings : pyramidConfigs())
        runConfigs +=
            settings.pipeline.technique->drawsClusterRuns() && settings.pipeline.mode->indirect;
    EXPECT_EQ(lostByRuns, runConfigs) << "every technique drawn by runs should lose the tie";
    fs::remove_all(history);
}

// A view from halfway into the default model, where the frustum and the occluders leave out
// much of it.
struct InsideView {
    app::LoadedScene loaded;
    scene::Camera camera;
};

const InsideView& insideView() {
    static const InsideView view = [] {
        InsideView v;
        v.loaded = app::loadScene(app::SceneSettings{});
        const scene::Camera start = app::initialCamera(v.loaded, 160.0f / 90.0f);
        v.camera =
            scene::cameraOnPath(scene::CameraPath::Dolly, start, v.loaded.scene.bounds(), 1, 4);
        return v;
    }();
    return view;
}

render::RenderSettings culled(const char* technique, const char* mode, render::CullMode cull) {
    render::RenderSettings s = testing_support::settingsFor(*render::findTechnique(technique),
                                                            *render::findDrawMode(mode));
    s.culling.mode = cull;
    return s;
}

// Frustum culling lists exactly the objects the CPU's test keeps: on the GPU (mdi) those
// with a cluster (up to 64 triangles of one part) whose box may lie in the view, and with
// cluster runs (vertex-fs) just those clusters' triangles; on the CPU (push) those whose own
// box may. Occlusion culling, once the view stands still, draws every object the ID image
// shows and fewer than the frustum leaves, and by cluster runs fewer triangles than those
// objects hold, but a triangle of every part that shows: the same runs whether the technique
// reads gl_PrimitiveID (tri-fs) or not (vertex-fs).
TEST(CullingCounts, AgreeWithTheObjectsTheCpuCountsAndTheIdImageShows) {
    const InsideView& v = insideView();
    const scene::Scene& s = v.loaded.scene;
    const glm::dmat4 viewProj = v.camera.viewProjection(160.0f / 90.0f);
    uint64_t inFrustum = 0, clusterInFrustum = 0, trianglesInFrustum = 0;
    for (const scene::Object& o : s.objects) {
        // Boxes of the vertices the triangles use, the object's and each cluster's, made here
        // from the triangles rather than by scene/bounds.h.
        const scene::Geometry& g = s.geometries[o.geometry];
        scene::Bounds box{glm::vec3(1e30f), glm::vec3(-1e30f)};
        bool clusterIn = false;
        for (uint32_t p = 0; p < g.partCount; ++p) {
            const scene::Part& part = s.parts[g.firstPart + p];
            scene::Bounds cluster{};
            for (uint32_t t = 0; t < part.triangleCount; ++t) {
                if (t % gpu::CLUSTER_MAX_TRIANGLES == 0)
                    cluster = {glm::dvec3(1e30), glm::dvec3(-1e30)};
                for (uint32_t c = 0; c < 3; ++c) {
                    const uint32_t i = g.firstIndex + 3 * (part.firstTriangle + t) + c;
                    const glm::dvec3 q = s.vertices[g.firstVertex + s.indices[i]].position;
                    cluster.min = glm::min(cluster.min, q);
                    cluster.max = glm::max(cluster.max, q);
                }
                box.min = glm::min(box.min, cluster.min);
                box.max = glm::max(box.max, cluster.max);
                const bool last =
                    t + 1 == part.triangleCount || (t + 1) % gpu::CLUSTER_MAX_TRIANGLES == 0;
                if (last && !render::outsideFrustum(viewProj, o.world, v.camera.eye, cluster)) {
                    clusterIn = true;
                    trianglesInFrustum += t % gpu::CLUSTER_MAX_TRIANGLES + 1;
                }
            }
        }
        inFrustum += render::outsideFrustum(viewProj, o.world, v.camera.eye, box) ? 0 : 1;
        clusterInFrustum += clusterIn ? 1 : 0;
    }
    ASSERT_LT(inFrustum, s.objects.size()) << "the view should leave objects out";
    ASSERT_GT(clusterInFrustum, 0u);
    EXPECT_LT(clusterInFrustum, inFrustum) << "testing cluster by cluster should leave out more";

    app::Options o = testing_support::headlessOptions(160, 90, 3);
    const std::vector<render::RenderSettings> configs = {
        culled("vertex-fs", "mdi-baseinstance", render::CullMode::Frustum),
        culled("vertex-fs", "push", render::CullMode::Frustum),
        culled("tri-fs", "mdi-attribute", render::CullMode::Occlusion),
        culled("vertex-fs", "mdi-attribute", render::CullMode::Occlusion)};
    const auto results = app::renderHeadlessSequence(o, s, v.camera, configs);
    EXPECT_EQ(results.front().validationMessages, 0u);
    const render::CullCounts frustum = render::countsOf(results[0].cullStats.back(), false);
    EXPECT_EQ(frustum.draws, clusterInFrustum);
    EXPECT_EQ(frustum.triangles, trianglesInFrustum);
    EXPECT_EQ(render::countsOf(results[1].cullStats.back(), false).draws, inFrustum);

    std::set<uint32_t> shown, shownParts;
    uint64_t shownTriangles = 0;
    for (uint32_t id : results[2].ids) {
        if (id == gpu::BACKGROUND_ID) continue;
        shownParts.insert(id);
        if (shown.insert(s.locate(id)->object).second)
            shownTriangles += s.geometries[s.objects[s.locate(id)->object].geometry].triangleCount;
    }
    EXPECT_TRUE(testing_support::sameIds(results[3].ids, results[2].ids, o.width));
    const render::CullCounts runs = render::countsOf(results[3].cullStats.back(), false);
    EXPECT_GE(runs.draws, shown.size());
    EXPECT_LT(runs.draws, clusterInFrustum) << "occlusion culling left nothing out";
    EXPECT_GE(runs.triangles, shownParts.size());
    EXPECT_LT(runs.triangles, shownTriangles) << "cluster runs drew whole objects";
    const render::CullCounts primitiveIds = render::countsOf(results[2].cullStats.back(), false);
    EXPECT_EQ(primitiveIds.draws, runs.draws);
    EXPECT_EQ(primitiveIds.triangles, runs.triangles);
}

// Objects whose parts are all hidden are not drawn, by the GPU's lists and the CPU's.
TEST(CullingCounts, ObjectsWithEveryPartHiddenAreNotDrawn) {
    const InsideView& v = insideView();
    const scene::Scene& s = v.loaded.scene;
    app::Options o = testing_support::headlessOptions(160, 90, 2);
    uint32_t hiddenObjects = 0;
    for (size_t i = 0; i < s.objects.size(); i += 3, ++hiddenObjects)
        for (uint32_t p = 0; p < s.geometries[s.objects[i].geometry].partCount; ++p)
            o.hide.push_back(s.objects[i].uniquePartOffset + p);
    // One part of another object: that object is still drawn.
    o.hide.push_back(s.objects[1].uniquePartOffset);
    const std::vector<render::RenderSettings> configs = {
        culled("vertex-fs", "mdi-baseinstance", render::CullMode::Frustum),
        culled("vertex-fs", "push", render::CullMode::Frustum)};
    const scene::Camera fitted = app::initialCamera(v.loaded, 160.0f / 90.0f);
    const auto results = app::renderHeadlessSequence(o, s, fitted, configs);
    EXPECT_EQ(results.front().validationMessages, 0u);
    for (size_t c = 0; c < configs.size(); ++c)
        EXPECT_EQ(render::countsOf(results[c].cullStats.back(), false).draws,
                  s.objects.size() - hiddenObjects)
            << configs[c].pipeline.mode->name;
}

// With MSAA the history follows what may show in any sample, not the resolved sample 0 that
// the ID image keeps: a speck over pixel (40, 30) that covers its samples 1 and 3 (the
// standard 4x positions (0.875, 0.375) and (0.625, 0.875)) but not sample 0 at
// (0.375, 0.125) is missing from the ID image, tints the colour, and is drawn in the first
// half of the next frame, with the square.
TEST(CullingSamples, APartShowingOnlyInLaterSamplesIsDrawnFirst) {
    scene::Scene s;
    const uint32_t grey = scene::addMaterial(s, "grey", {0.5f, 0.5f, 0.5f, 1});
    const uint32_t big = square(s, px(4), py(4), px(20), py(20), 0.5f, "square");
    const uint32_t speck = square(s, px(40.5f), py(30.3f), px(40.95f), py(30.95f), 0.5f, "speck");
    scene::addObject(s, big, grey, glm::mat4(1.0f), "square");
    scene::addObject(s, speck, grey, glm::mat4(1.0f), "speck");
    scene::validate(s);
    const size_t pixel = size_t(30) * SW + 40;

    for (const char* mode : {"mdi-baseinstance", "mdi-attribute"}) {
        app::Options o = testing_support::headlessOptions(SW, SH);
        o.live.render = culled("vertex-fs", mode, render::CullMode::Occlusion);
        o.live.render.pipeline.msaa = 4;
        vk::Instance instance({true, {}, false});
        std::vector<uint32_t> ids;
        std::vector<uint8_t> color;
        gpu::CullStats stats{};
        {
            app::Offscreen rig(instance, o);
            rig.renderer.setScene(s, o.live.render);
            const app::Readback readback(rig.device, rig.extent);
            render::FrameParams params;
            params.viewProj = testing_support::flatViewProj();
            for (uint64_t frame = 0; frame < 2; ++frame) {
                render::FrameSlot& slot = rig.slots.begin(frame);
                rig.renderer.record(slot, rig.targets, params);
                readback.record(slot.cmd, *rig.targets);
                rig.slots.submit(slot);
                rig.slots.finish();
            }
            ids = readback.idValues();
            color = readback.colorBytes();
            stats = rig.slots.cullStats().back();
        }
        EXPECT_EQ(instance.validationMessages(), 0u) << mode;
        ASSERT_EQ(ids[pixel], gpu::BACKGROUND_ID) << mode << ": the speck should miss sample 0";
        ASSERT_EQ(ids[size_t(10) * SW + 10], 0u) << mode;
        const auto rgba = [&](size_t i) {
            return std::vector<uint8_t>(&color[4 * i], &color[4 * i + 4]);
        };
        ASSERT_NE(rgba(pixel), rgba(pixel + 4)) << mode << ": the speck should tint its pixel";
        EXPECT_EQ(stats.draws[0], 2u) << mode << ": the first half should draw both objects";
        EXPECT_EQ(stats.draws[1], 0u) << mode << ": nothing should be left for the second half";
    }
}

// Frozen lists keep drawing what the fitted view chose while the camera flies inside: what
// the occluders hid from the fitted view is missing there, and the counts stay.
TEST(CullingFreeze, KeepsTheListsWhileTheCameraMoves) {
    const InsideView& v = insideView();
    const scene::Scene& s = v.loaded.scene;
    const float aspect = 160.0f / 90.0f;
    const scene::Camera fitted = app::initialCamera(v.loaded, aspect);
    app::Options o = testing_support::headlessOptions(160, 90);
    for (const char* technique : {"vertex-fs", "mesh-vertex-fs"}) {
        render::RenderSettings live =
            culled(technique, "mdi-baseinstance", render::CullMode::Occlusion);
        vk::Instance instance({true, {}, false});
        {
            app::Offscreen rig(instance, o);
            rig.renderer.setScene(s, live);
            uint64_t frame = 0;
            auto draw = [&](const scene::Camera& camera) {
                const render::FrameParams params = app::cameraFrame(camera, rig.extent);
                render::FrameSlot& slot = rig.slots.begin(frame++);
                rig.renderer.record(slot, rig.targets, params);
                const app::Readback readback(rig.device, rig.extent);
                readback.record(slot.cmd, *rig.targets);
                rig.slots.submit(slot);
                rig.slots.finish();
                return std::make_pair(readback.idValues(), rig.slots.cullStats().back());
            };
            for (int i = 0; i < 3; ++i) draw(fitted);
            const auto [fittedIds, fittedStats] = draw(fitted);
            render::RenderSettings frozen = live;
            frozen.culling.freeze = true;
            rig.renderer.configure(s, frozen);
            const auto [frozenIds, frozenStats] = draw(v.camera);
            render::RenderSettings off = live;
            off.culling.mode = render::CullMode::Off;
            rig.renderer.configure(s, off);
            const auto [allIds, allStats] = draw(v.camera);
            EXPECT_FALSE(testing_support::sameIds(frozenIds, allIds, o.width))
                << technique << ": the frozen lists drew everything";
            EXPECT_EQ(render::countsOf(frozenStats, false).draws,
                      render::countsOf(fittedStats, false).draws)
                << technique;
            // Back to live culling: exact again.
            rig.renderer.configure(s, live);
            draw(v.camera);
            EXPECT_TRUE(testing_support::sameIds(draw(v.camera).first, allIds, o.width))
                << technique;
        }
        EXPECT_EQ(instance.validationMessages(), 0u) << technique;
    }
}

} // namespace
