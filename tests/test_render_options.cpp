// test_render_options.cpp - options every technique honours, on lavapipe with validation:
// --visible draws only the first objects (the ID image names no other object's parts), and
// --ignore-materials shades everything in one neutral grey.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "app/headless.h"
#include "app/scene_source.h"
#include "image_compare.h"
#include "render/draw_list.h"
#include "render/technique.h"
#include "test_support.h"

namespace {

struct Fixture {
    app::LoadedScene loaded;
    scene::Camera camera;
};

app::Options options() {
    return testing_support::headlessOptions(200, 120);
}

const Fixture& fixture() {
    static const Fixture f = [] {
        app::SceneSettings source;
        source.builtin = "procedural:preset=small,seed=1";
        Fixture made;
        made.loaded = app::loadScene(source);
        made.camera = app::initialCamera(made.loaded, 200.0f / 120.0f);
        return made;
    }();
    return f;
}

} // namespace

TEST(Visible, HalfTheObjectsShowOnlyTheirOwnParts) {
    const scene::Scene& s = fixture().loaded.scene;
    const size_t half = render::visibleObjectCount(0.5f, s.objects.size());
    ASSERT_GT(half, 0u);
    ASSERT_LT(half, s.objects.size());
    // Every part-ID technique of the registry, the modes taken in turn.
    std::vector<render::RenderSettings> configs;
    for (const render::Technique* t : render::partIdTechniques())
        for (float visible : {0.5f, 0.0f, 1.0f}) {
            configs.push_back(testing_support::settingsFor(
                *t, render::drawModes()[configs.size() % render::drawModes().size()]));
            configs.back().draws.visible = visible;
        }
    const auto results = app::renderHeadlessSequence(options(), s, fixture().camera, configs);
    EXPECT_EQ(results.front().validationMessages, 0u);
    for (size_t i = 0; i < results.size(); ++i) {
        const float visible = configs[i].draws.visible;
        const std::string name = std::string(configs[i].pipeline.technique->name) + " visible " +
                                 std::to_string(visible);
        size_t shown = 0, beyond = 0;
        for (uint32_t id : results[i].ids) {
            if (id == gpu::BACKGROUND_ID) continue;
            ++shown;
            const auto part = s.locate(id);
            ASSERT_TRUE(part.has_value()) << name;
            if (part->object >= render::visibleObjectCount(visible, s.objects.size())) ++beyond;
        }
        EXPECT_EQ(beyond, 0u) << name;
        if (visible == 0.0f) {
            EXPECT_EQ(shown, 0u) << name;
            EXPECT_EQ(results[i].stats.draws, 0u) << name;
            EXPECT_EQ(results[i].stats.triangles, 0u) << name;
        } else {
            EXPECT_GT(shown, 0u) << name;
        }
    }
    // Half the objects draw fewer triangles than all of them, and the same with any technique.
    EXPECT_LT(results[0].stats.triangles, results[2].stats.triangles);
    EXPECT_EQ(results[2].stats.triangles, s.drawnTriangleCount());
    for (size_t i = 3; i < results.size(); i += 3)
        EXPECT_TRUE(testing_support::sameIds(results[0].ids, results[i].ids, options().width));
}

TEST(IgnoreMaterials, WithoutPartColourEveryPixelIsNeutralGrey) {
    const scene::Scene& s = fixture().loaded.scene;
    app::Options o = options();
    o.live.render.shading.partWeight = 0.0f;
    o.live.render.pipeline.technique = render::partIdTechniques().back();
    const app::HeadlessResult plain = app::renderHeadless(o, s, fixture().camera);
    o.live.render.shading.ignoreMaterials = true;
    const app::HeadlessResult grey = app::renderHeadless(o, s, fixture().camera);
    EXPECT_EQ(plain.validationMessages + grey.validationMessages, 0u);
    ASSERT_EQ(grey.color.size(), size_t(4) * grey.ids.size());
    // The same parts, only shaded differently.
    EXPECT_TRUE(testing_support::sameIds(grey.ids, plain.ids, o.width));
    size_t covered = 0, coloured = 0;
    for (size_t i = 0; i < grey.ids.size(); ++i) {
        if (grey.ids[i] == gpu::BACKGROUND_ID) continue;
        ++covered;
        const uint8_t* p = &grey.color[4 * i];
        EXPECT_LE(std::abs(int(p[0]) - int(p[1])), 1) << "pixel " << i;
        EXPECT_LE(std::abs(int(p[1]) - int(p[2])), 1) << "pixel " << i;
        const uint8_t* q = &plain.color[4 * i];
        if (std::abs(int(q[0]) - int(q[1])) > 1 || std::abs(int(q[1]) - int(q[2])) > 1) ++coloured;
    }
    EXPECT_GT(covered, 1000u);
    EXPECT_GT(coloured, 0u) << "the default shows material colours";
    EXPECT_FALSE(testing_support::sameColours(grey.color, plain.color, o.width));
    // With part colours back, the neutral base lets them through: no longer all grey.
    o.live.render.shading.partWeight = 0.5f;
    const app::HeadlessResult tinted = app::renderHeadless(o, s, fixture().camera);
    EXPECT_FALSE(testing_support::sameColours(tinted.color, grey.color, o.width));
}
