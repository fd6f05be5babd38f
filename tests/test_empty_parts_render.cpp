// test_empty_parts_render.cpp - empty parts (no triangles) draw nothing and shift no ID, on
// lavapipe with validation on: for every technique x per-draw mode of the registry, culling
// off and on, and with levels of detail where the mode chooses them, the procedural small
// preset with empty parts at the start, middle and end of every geometry and an object of only
// empty parts (empty_parts_scene.h) draws the ID image of the same scene without them, mapped
// to its IDs, and the same colour image; a pick of a part that follows an empty one names it.
// A scene with nothing meshed draws the background.
#include <gtest/gtest.h>

#include "app/headless.h"
#include "empty_parts_scene.h"
#include "image_compare.h"
#include "render/culling.h"
#include "render/technique.h"
#include "scene/lod.h"
#include "scene/procedural/procedural.h"
#include "scene/raycast.h"
#include "test_support.h"

namespace {

constexpr uint32_t W = 96, H = 64;

// The small preset with its levels of detail and, on every geometry alike, a material of its
// own on every third part, so that the colour image shows which part the shaders found.
scene::Scene plainScene() {
    scene::Scene s = scene::makeProcedural({"small", 1});
    scene::buildLevels(s);
    const uint32_t accent = scene::addMaterial(s, "accent", glm::vec4(0.2f, 0.5f, 0.9f, 1.0f));
    for (scene::Geometry& g : s.geometries) {
        g.partMaterials.assign(g.partCount, gpu::OBJECT_MATERIAL);
        for (uint32_t p = 1; p < g.partCount; p += 3) g.partMaterials[p] = accent;
    }
    scene::validate(s);
    return s;
}

// A pixel whose 5 x 5 block shows one part (by the CPU's ray cast) that follows an empty one in
// the scene with empty parts; its ID there.
struct PickTarget {
    app::Options::Pixel pixel;
    uint32_t part = 0;
};
PickTarget partAfterAnEmptyOne(const testing_support::WithEmptyParts& e,
                               const scene::Camera& camera) {
    const scene::Scene& s = e.scene;
    const glm::dvec2 size(W, H);
    const scene::RayCaster caster(s);
    const glm::dmat4 viewProj = camera.viewProjection(size.x / size.y);
    auto partAt = [&](int x, int y) {
        const auto hit = caster.cast(scene::pixelRay(viewProj, size, {x + 0.5, y + 0.5}));
        return hit ? hit->uniquePartId : gpu::BACKGROUND_ID;
    };
    for (int y = 2; y + 2 < int(H); ++y)
        for (int x = 2; x + 2 < int(W); ++x) {
            const uint32_t id = partAt(x, y);
            if (id == gpu::BACKGROUND_ID || id == 0 ||
                e.plainId[id - 1] != testing_support::kEmptyPart)
                continue;
            bool block = true;
            for (int dy = -2; dy <= 2 && block; ++dy)
                for (int dx = -2; dx <= 2 && block; ++dx) block = partAt(x + dx, y + dy) == id;
            if (block) return {{uint32_t(x), uint32_t(y)}, id};
        }
    throw std::logic_error("no part after an empty one shows in a 5 x 5 block");
}

std::string nameOf(const render::RenderSettings& s) {
    return std::string(s.pipeline.technique->name) + " + " + s.pipeline.mode->name + ", culling " +
           render::cullModeName(s.culling.mode) + ", LOD error " +
           std::to_string(s.lod.errorPixels);
}

// Every technique x mode, culling off and on, and where the mode chooses levels of detail,
// culling on with an error so large that every object draws its coarsest level. Part colours
// off: the scenes number their parts differently, and the colour image must not show it.
std::vector<render::RenderSettings> configurations() {
    std::vector<render::RenderSettings> configs;
    auto add = [&](const render::Technique& t, const render::DrawMode& m, render::CullMode cull,
                   float lodError) {
        render::RenderSettings settings = testing_support::settingsFor(t, m);
        settings.culling.mode = cull;
        settings.lod.errorPixels = lodError;
        settings.shading.partWeight = 0.0f;
        settings.clear = render::ClearPath::Pass; // the same path for both scenes
        configs.push_back(settings);
    };
    for (const render::Technique& t : render::techniques())
        for (const render::DrawMode& m : render::drawModes()) {
            add(t, m, render::CullMode::Off, 0.0f);
            add(t, m, render::CullMode::Occlusion, 0.0f);
            if (render::levelsChosenIn(m)) add(t, m, render::CullMode::Occlusion, 1e6f);
        }
    return configs;
}

// Triangles the cull pass drew at the coarser levels in a result's last frame.
uint64_t coarserTriangles(const app::HeadlessResult& r, bool mesh) {
    if (r.cullStats.empty()) return 0;
    const render::CullCounts c = render::countsOf(r.cullStats.back(), mesh);
    uint64_t sum = 0;
    for (size_t l = 1; l < c.levelTriangles.size(); ++l) sum += c.levelTriangles[l];
    return sum;
}

} // namespace

TEST(EmptyPartsRender, EveryTechniqueDrawsTheImagesOfTheSceneWithout) {
    const scene::Scene plain = plainScene();
    const testing_support::WithEmptyParts e = testing_support::withEmptyParts(plain);
    const scene::Camera camera = scene::fitCamera(plain.bounds(), {0.6, -1.0, 0.8}, {0, 0, 1},
                                                  glm::radians(45.0f), double(W) / double(H));
    const PickTarget target = partAfterAnEmptyOne(e, camera);
    const std::vector<render::RenderSettings> configs = configurations();
    app::Options o = testing_support::headlessOptions(W, H, 2); // the second culls by history
    o.picks = {target.pixel};
    const auto before = app::renderHeadlessSequence(o, plain, camera, configs);
    const auto after = app::renderHeadlessSequence(o, e.scene, camera, configs);
    EXPECT_EQ(before.front().validationMessages, 0u);
    EXPECT_EQ(after.front().validationMessages, 0u);
    for (size_t c = 0; c < configs.size(); ++c) {
        const std::string name = nameOf(configs[c]);
        EXPECT_TRUE(
            testing_support::sameIds(testing_support::plainIds(e, after[c].ids), before[c].ids, W))
            << name;
        EXPECT_TRUE(testing_support::sameColours(after[c].color, before[c].color, W)) << name;
        const render::Technique& t = *configs[c].pipeline.technique;
        const bool levels = configs[c].lod.errorPixels > 0.0f;
        if (levels) {
            EXPECT_GT(coarserTriangles(after[c], t.usesMeshShader()), 0u) << name;
        }
        if (t.isFloor()) continue; // no IDs, no picks
        // The pick is the fragment shader's own, not read from the ID image: the plain
        // scene's pick, mapped.
        ASSERT_EQ(after[c].picks.size(), 1u) << name;
        ASSERT_TRUE(after[c].picks[0].part) << name;
        const uint32_t picked = *after[c].picks[0].part;
        EXPECT_EQ(e.plainId.at(picked), before[c].picks[0].part) << name;
        // At full detail, the part the ray cast found; coarser levels move its outline.
        if (!levels) {
            EXPECT_EQ(picked, target.part) << name;
        }
    }
}

// A load shown as it goes starts with no object meshed: every technique x mode draws the
// background alone, without a validation message.
TEST(EmptyPartsRender, NothingMeshedYetDrawsTheBackground) {
    testing_support::WithEmptyParts e =
        testing_support::withEmptyParts(scene::makeProcedural({"small", 1}));
    for (scene::Object& o : e.scene.objects) o.geometry = e.scene.objects[e.emptyObject].geometry;
    std::vector<render::RenderSettings> configs;
    for (const render::Technique& t : render::techniques())
        for (const render::DrawMode& m : render::drawModes())
            configs.push_back(testing_support::settingsFor(t, m));
    const scene::Camera camera =
        scene::fitCamera(e.scene.bounds(), {0.6, -1.0, 0.8}, {0, 0, 1}, glm::radians(45.0f), 1.0);
    const auto results = app::renderHeadlessSequence(testing_support::headlessOptions(16, 16),
                                                     e.scene, camera, configs);
    EXPECT_EQ(results.front().validationMessages, 0u);
    for (size_t c = 0; c < configs.size(); ++c) {
        EXPECT_EQ(results[c].ids, std::vector<uint32_t>(16 * 16, gpu::BACKGROUND_ID))
            << nameOf(configs[c]);
        EXPECT_EQ(results[c].stats.draws, 0u) << nameOf(configs[c]);
    }
}
