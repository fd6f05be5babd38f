// test_techniques.cpp - every technique x per-draw mode renders, on lavapipe with validation
// on, an ID image identical pixel for pixel to per-draw + push, with the draw count its
// formula predicts; on the procedural small preset with 2 copies, on 2CylinderEngine with
// components as parts, on a glTF whose parts share vertices (tests/shared_vertex_gltf.h), and
// on an IGES file (one part per B-rep face) where occt-misc is installed; and on the engine
// with every object forced to its second coarser level of detail.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "app/headless.h"
#include "app/scene_source.h"
#include "image_compare.h"
#include "raster_explainer.h"
#include "render/technique.h"
#include "scene/lod.h"
#include "shared_vertex_gltf.h"
#include "test_data.h"
#include "test_support.h"

namespace {

struct Reference {
    app::LoadedScene loaded;
    scene::Camera camera;
    app::HeadlessResult image; // per-draw + push
};

app::Options renderOptions(const render::Technique& technique, const render::DrawMode& mode) {
    app::Options o = testing_support::headlessOptions(240, 150, 2);
    o.live.render = testing_support::settingsFor(technique, mode);
    return o;
}

app::Options referenceOptions() {
    return renderOptions(render::defaultTechnique(), render::defaultDrawMode());
}

// Draws each technique must issue: per part, per object, or per batch of search-batch parts.
size_t expectedDraws(const render::Technique& t, const scene::Scene& s, uint32_t batch) {
    switch (t.split) {
    case render::DrawSplit::PerPart:
        return s.uniquePartCount();
    case render::DrawSplit::PerObject:
        return s.objects.size();
    case render::DrawSplit::PerBatch: {
        size_t draws = 0;
        for (const auto& o : s.objects)
            draws += (s.geometries[o.geometry].partCount + batch - 1) / batch;
        return draws;
    }
    }
    return 0;
}

const char* const kEngine =
    "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";

// An IGES file from Debian's occt-misc: 213 faces, over 100 of them in view.
const char* const kCadBearing = "/usr/share/opencascade/data/iges/bearing.iges";

Reference& reference(const std::string& name) {
    static std::map<std::string, Reference> cache;
    auto found = cache.find(name);
    if (found != cache.end()) return found->second;
    app::SceneSettings source;
    if (name == "small-x2") {
        source.builtin = "procedural:preset=small,seed=1";
        source.copies = 2;
    } else if (name == "engine-level-2") {
        // Every object at its second coarser level of detail (scene/lod.h), or its coarsest.
        source.model = testing_support::requiredData(kEngine);
        source.parts = scene::PartMode::Components;
        source.lodLevels = scene::maxLevels;
        source.lodLevel = 2;
    } else if (name == "cad-bearing") {
        source.model = testing_support::requiredData(kCadBearing); // one part per B-rep face
    } else if (name == "shared-vertices") {
        source.model = testing_support::writeSharedVertexGltf(
                           std::filesystem::temp_directory_path() / "idview-techniques")
                           .string();
    } else {
        source.model = testing_support::requiredData(kEngine);
        source.parts = scene::PartMode::Components;
    }
    Reference ref;
    ref.loaded = app::loadScene(source);
    app::Options o = referenceOptions();
    ref.camera = app::initialCamera(ref.loaded, float(o.width) / float(o.height));
    ref.image = app::renderHeadless(o, ref.loaded.scene, ref.camera);
    return cache.emplace(name, std::move(ref)).first->second;
}

struct Combination {
    std::string scene;
    const render::Technique* technique;
    const render::DrawMode* mode;
};

// Readable test output instead of gtest's byte dump.
void PrintTo(const Combination& c, std::ostream* os) {
    *os << c.scene << " " << c.technique->name << " " << c.mode->name;
}

class AllTechniques : public ::testing::TestWithParam<Combination> {};

TEST_P(AllTechniques, IdImageEqualsPerDrawPushPixelForPixel) {
    const Combination& c = GetParam();
    Reference& ref = reference(c.scene);
    ASSERT_EQ(ref.image.validationMessages, 0u);
    const std::set<uint32_t> visible(ref.image.ids.begin(), ref.image.ids.end());
    // Over 100 parts in view, or every part of a scene that has fewer.
    const size_t wanted = std::min<size_t>(101, ref.loaded.scene.uniquePartCount() + 1);
    ASSERT_GE(visible.size(), wanted) << "the reference shows too little to compare";

    app::Options o = renderOptions(*c.technique, *c.mode);
    app::HeadlessResult r = app::renderHeadless(o, ref.loaded.scene, ref.camera);
    EXPECT_EQ(r.validationMessages, 0u);
    EXPECT_TRUE(testing_support::sameIdsAs(*c.technique, r.ids, ref.image.ids, ref.loaded.scene,
                                           ref.camera, {o.width, o.height},
                                           o.live.render.pipeline.msaa));
    EXPECT_EQ(r.stats.draws,
              expectedDraws(*c.technique, ref.loaded.scene, o.live.render.pipeline.searchBatch));
}

std::vector<Combination> combinations() {
    std::vector<Combination> all;
    // bearing.iges comes with occt-misc, which the tests need: without it its cases fail.
    const std::vector<std::string> scenes = {"small-x2", "engine-components", "engine-level-2",
                                             "shared-vertices", "cad-bearing"};
    for (const std::string& scene : scenes)
        for (const render::Technique* t : render::partIdTechniques())
            for (const auto& m : render::drawModes()) all.push_back({scene, t, &m});
    return all;
}

std::string nameOf(const ::testing::TestParamInfo<Combination>& info) {
    return testing_support::testName(info.param.scene + "_" + info.param.technique->name + "_" +
                                     info.param.mode->name);
}

INSTANTIATE_TEST_SUITE_P(Lavapipe, AllTechniques, ::testing::ValuesIn(combinations()), nameOf);

// The level the technique tests force is what is drawn: its triangles, a different image of
// the same parts, and no part lost where full detail shows it large.
TEST(Levels, AForcedLevelIsWhatIsDrawn) {
    const Reference& full = reference("engine-components");
    const Reference& coarse = reference("engine-level-2");
    ASSERT_EQ(coarse.image.validationMessages, 0u);
    const std::vector<scene::LevelStats> levels = scene::levelStats(coarse.loaded.scene);
    ASSERT_GE(levels.size(), 3u);
    EXPECT_EQ(coarse.image.stats.triangles, levels[2].drawnTriangles);
    EXPECT_LT(coarse.image.stats.triangles, full.image.stats.triangles * 2 / 3);
    const size_t differing =
        testing_support::idDifference(coarse.image.ids, full.image.ids, referenceOptions().width)
            .pixels;
    std::map<uint32_t, size_t> fullPixels, coarsePixels;
    for (size_t i = 0; i < full.image.ids.size(); ++i) {
        ++fullPixels[full.image.ids[i]];
        ++coarsePixels[coarse.image.ids[i]];
    }
    EXPECT_GT(differing, 0u) << "the coarse level drew full detail's image";
    EXPECT_LT(differing, full.image.ids.size() / 10);
    for (const auto& [id, pixels] : fullPixels)
        if (pixels >= 50) {
            EXPECT_TRUE(coarsePixels.count(id)) << "part " << id << " vanished";
        }
}

// One renderer switched at run time between search batch sizes, techniques and modes
// rebuilds batches and pipelines and still agrees with the reference; draws follow
// ceil(parts / batch).
TEST(SearchBatch, ChangesAtRunTimeKeepIdsAndFollowTheFormula) {
    Reference& ref = reference("small-x2");
    const uint32_t batches[] = {16, 1, 7, 32, 16};
    // Every technique that reads the search batch, and the modes, taken in turn.
    std::vector<const render::Technique*> searching;
    for (const render::Technique* t : render::partIdTechniques())
        if (t->readsSearchBatch()) searching.push_back(t);
    ASSERT_FALSE(searching.empty());
    std::vector<render::RenderSettings> configs;
    for (uint32_t batch : batches) {
        const size_t i = configs.size();
        configs.push_back(testing_support::settingsFor(
            *searching[i % searching.size()], render::drawModes()[i % render::drawModes().size()]));
        configs.back().pipeline.searchBatch = batch;
    }
    auto results =
        app::renderHeadlessSequence(referenceOptions(), ref.loaded.scene, ref.camera, configs);
    ASSERT_EQ(results.size(), configs.size());
    EXPECT_EQ(results.front().validationMessages, 0u);
    for (size_t i = 0; i < results.size(); ++i) {
        EXPECT_EQ(results[i].ids, ref.image.ids) << "batch " << batches[i];
        EXPECT_EQ(results[i].stats.draws,
                  expectedDraws(*configs[i].pipeline.technique, ref.loaded.scene, batches[i]));
    }
    EXPECT_GT(results[1].stats.draws, results[0].stats.draws); // batch 1: one draw per part
}

} // namespace

namespace {

// With 4x MSAA every technique and mode resolves the same ID image (sample 0 of each pixel),
// which differs from the 1x image only near edges: pixels inside a 5x5 block of one part
// keep it (a 3x3 block is not enough: sub-pixel features can hide between pixel centres).
TEST(Msaa, EveryTechniqueAndModeResolvesTheSameIdImage) {
    Reference& ref = reference("small-x2");
    std::vector<render::RenderSettings> configs;
    for (const render::Technique* t : render::partIdTechniques())
        for (const auto& m : render::drawModes()) {
            configs.push_back(testing_support::settingsFor(*t, m));
            configs.back().pipeline.msaa = 4;
        }
    const app::Options o = referenceOptions();
    const auto results = app::renderHeadlessSequence(o, ref.loaded.scene, ref.camera, configs);
    EXPECT_EQ(results.front().validationMessages, 0u);
    for (size_t i = 0; i < results.size(); ++i)
        EXPECT_TRUE(testing_support::sameIdsAs(*configs[i].pipeline.technique, results[i].ids,
                                               results.front().ids, ref.loaded.scene, ref.camera,
                                               {o.width, o.height}, 4))
            << configs[i].pipeline.technique->name << " + " << configs[i].pipeline.mode->name;

    const auto& ms = results.front().ids;
    const auto& single = ref.image.ids;
    size_t edgeDifferences = 0, interiorDifferences = 0;
    for (uint32_t y = 2; y + 2 < o.height; ++y)
        for (uint32_t x = 2; x + 2 < o.width; ++x) {
            const size_t i = size_t(y) * o.width + x;
            if (ms[i] == single[i]) continue;
            bool interior = true; // a 5x5 block of one part: no edge can reach sample 0
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx)
                    interior =
                        interior && single[size_t(int(i) + dy * int(o.width) + dx)] == single[i];
            ++(interior ? interiorDifferences : edgeDifferences);
        }
    EXPECT_GT(edgeDifferences, 0u) << "MSAA changed nothing: is it on?";
    EXPECT_EQ(interiorDifferences, 0u);
}

} // namespace

namespace {

// The layer's synchronization validation over every technique and mode (and the no-id
// floor), with what adds barriers: MSAA resolve, in the pass and in compute (the two clear
// paths alternate, so that each technique meets both over the modes, and the switches
// between them are checked too), the pick's reset and copies, the animation's compute pass,
// the edge and part set passes over the ID image, hidden parts (with MSAA) and the readback.
// Any hazard it reports counts as a validation message.
TEST(SyncValidation, EveryTechniqueAndModeIsHazardFree) {
    Reference& ref = reference("small-x2");
    for (uint32_t msaa : {1u, 4u}) {
        // Every technique of the registry, the no-id floor included, in every mode.
        std::vector<render::RenderSettings> configs;
        for (const auto& m : render::drawModes())
            for (const auto& t : render::techniques()) {
                configs.push_back(testing_support::settingsFor(t, m));
                configs.back().pipeline.msaa = msaa;
                configs.back().edges.on = true;
                configs.back().clear =
                    configs.size() % 2 ? render::ClearPath::Compute : render::ClearPath::Pass;
            }
        app::Options o = referenceOptions();
        o.selectRect = render::PartSetQuery{{10, 10}, {60, 50}};
        o.visibleParts = true;
        if (msaa > 1) o.hide = {0, 1, 2, 3, 40, 41};
        o.width = 96;
        o.height = 64;
        o.syncValidation = true;
        o.picks = {{48, 32}};
        o.selects = {{40, 30}};
        o.live.animation.explode = 0.4f;
        const auto results = app::renderHeadlessSequence(o, ref.loaded.scene, ref.camera, configs);
        EXPECT_EQ(results.front().validationMessages, 0u) << "MSAA " << msaa;
    }
}

} // namespace

namespace {

// nsearch at the corners of its parameters (fan-out 3 and 16, guess on and off, linear scan
// from 0 and 64 parts, 1 and 64 steps) equals per-draw + push pixel for pixel: a step cap too
// low to finish leaves the rest to the linear scan, so every set is exact. One renderer
// switches between the sets, so each change must rebuild the pipeline.
TEST(NarySearch, EveryParameterSetEqualsPerDraw) {
    const std::vector<render::NarySearch> sets = {
        {3, false, 0, 1}, {3, true, 0, 64},  {16, true, 64, 1}, {16, false, 0, 64},
        {16, true, 0, 1}, {3, true, 64, 64}, {8, true, 8, 16},  {5, false, 1, 2},
    };
    // Every technique that reads the N-ary search parameters, taken in turn.
    std::vector<const render::Technique*> nary;
    for (const render::Technique* t : render::partIdTechniques())
        if (t->narySearch) nary.push_back(t);
    ASSERT_FALSE(nary.empty());
    for (const char* scene : {"small-x2", "engine-components", "shared-vertices"}) {
        Reference& ref = reference(scene);
        std::vector<render::RenderSettings> configs;
        for (size_t i = 0; i < sets.size(); ++i) {
            configs.push_back(testing_support::settingsFor(
                *nary[i % nary.size()], render::drawModes()[i % render::drawModes().size()]));
            configs.back().pipeline.nsearch = sets[i];
        }
        auto results =
            app::renderHeadlessSequence(referenceOptions(), ref.loaded.scene, ref.camera, configs);
        ASSERT_EQ(results.size(), configs.size());
        EXPECT_EQ(results.front().validationMessages, 0u);
        for (size_t i = 0; i < results.size(); ++i) {
            const render::NarySearch& n = sets[i];
            EXPECT_EQ(results[i].ids, ref.image.ids)
                << scene << " " << configs[i].pipeline.technique->name << " n " << n.n << " guess "
                << n.guess << " linear " << n.linearBelow << " steps " << n.maxSteps;
            EXPECT_EQ(results[i].stats.draws, ref.loaded.scene.objects.size());
        }
    }
}

} // namespace
