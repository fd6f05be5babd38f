// test_xray.cpp - X-ray (render/xray.h) on lavapipe with validation on: for every part-ID
// technique in every per-draw mode, and at 4x MSAA, the ID image under X-ray holds only the
// selected parts, byte for byte as isolating them draws it; the parts outside the selection
// still show, translucent, over the background; and a pick where one of them covered a
// selected part finds the selected part.
#include <gtest/gtest.h>

#include <algorithm>

#include "app/headless.h"
#include "app/scene_source.h"
#include "image_compare.h"
#include "render/technique.h"
#include "render/xray.h"
#include "test_support.h"

namespace {

constexpr uint32_t W = 160, H = 100;
constexpr uint32_t NONE = gpu::BACKGROUND_ID;

std::string nameOf(const render::RenderSettings& s) {
    return std::string(s.pipeline.technique->name) + " + " + s.pipeline.mode->name + " msaa " +
           std::to_string(s.pipeline.msaa);
}

// Every part-ID technique in push mode (whose culling is the CPU's), the default one in every
// mode (the GPU's lists) and at 4x MSAA: hiding is each one's own, X-ray's pass is one for all.
std::vector<render::RenderSettings> xrayConfigs() {
    std::vector<render::RenderSettings> configs;
    for (const render::Technique* t : render::partIdTechniques())
        configs.push_back(testing_support::settingsFor(*t, render::defaultDrawMode()));
    for (const render::DrawMode& m : render::drawModes())
        if (&m != &render::defaultDrawMode())
            configs.push_back(testing_support::settingsFor(render::defaultTechnique(), m));
    configs.push_back(configs.front());
    configs.back().pipeline.msaa = 4;
    return configs;
}

// Up to three pixels where a part outside `selected` covers (in `plain`) a selected part that
// X-ray shows (in `xrayed`): a pick there must go through the translucent part.
std::vector<app::Options::Pixel> pixelsThroughOthers(const std::vector<uint32_t>& plain,
                                                     const std::vector<uint32_t>& xrayed,
                                                     const scene::PartSet& selected) {
    std::vector<app::Options::Pixel> through;
    for (uint32_t y = 0; y < H && through.size() < 3; y += 3)
        for (uint32_t x = 0; x < W && through.size() < 3; x += 5) {
            const size_t i = size_t(y) * W + x;
            if (plain[i] != NONE && !selected.contains(plain[i]) && selected.contains(xrayed[i]))
                through.push_back({x, y});
        }
    return through;
}

// X-ray's ID image `r` holds nothing but the selection `own`, exactly where isolating it
// (`iso`) shows it; the rest shows: where isolating leaves background and the parts outside
// the selection lie (in `plain`), X-ray's picture has their colour; where none lies, the
// background's.
void expectSelectionAloneAndTheRestTranslucent(const app::HeadlessResult& r,
                                               const app::HeadlessResult& iso,
                                               const app::HeadlessResult& plain,
                                               const scene::PartSet& own, const std::string& name) {
    EXPECT_TRUE(testing_support::sameIds(r.ids, iso.ids, W)) << name;
    size_t shown = 0, others = 0;
    for (uint32_t id : r.ids) {
        shown += own.contains(id);
        others += id != NONE && !own.contains(id);
    }
    EXPECT_GT(shown, 100u) << name;
    EXPECT_EQ(others, 0u) << name;
    size_t behindOthers = 0, tinted = 0, strays = 0;
    for (size_t i = 0; i < r.ids.size(); ++i) {
        if (r.ids[i] != NONE) continue;
        const bool differs =
            !std::equal(r.color.begin() + 4 * long(i), r.color.begin() + 4 * long(i) + 3,
                        iso.color.begin() + 4 * long(i));
        if (plain.ids[i] != NONE) {
            ++behindOthers;
            tinted += differs;
        } else {
            strays += differs;
        }
    }
    EXPECT_GT(behindOthers, 100u) << name;
    // The plain image is push mode's at 1x: other paths and MSAA's edges differ a little.
    EXPECT_GT(tinted, behindOthers * 4 / 5) << name;
    EXPECT_LT(strays, r.ids.size() / 100) << name;
}

// Picks go through the translucent parts to the selected part behind (at 1x, the one the ID
// image shows there).
void expectPicksReachTheSelection(const app::HeadlessResult& r, size_t picks,
                                  const scene::PartSet& own, uint32_t msaa,
                                  const std::string& name) {
    ASSERT_EQ(r.picks.size(), picks) << name;
    for (const render::PickReading& pick : r.picks) {
        ASSERT_TRUE(pick.part.has_value()) << name;
        EXPECT_TRUE(own.contains(*pick.part)) << name;
        if (msaa == 1) {
            EXPECT_EQ(*pick.part, r.ids[size_t(pick.pixel.y) * W + pick.pixel.x]) << name;
        }
    }
}

// A click's selection (--select) at `at` under X-ray: the part `plain` shows there, drawn as
// isolating it draws it.
void expectAClickSelectsAsIsolated(const scene::Scene& scene, const scene::Camera& camera,
                                   const app::HeadlessResult& plain, app::Options::Pixel at) {
    app::Options click = testing_support::headlessOptions(W, H);
    click.selects = {at};
    click.live.xray = true;
    const app::HeadlessResult one = app::renderHeadless(click, scene, camera);
    ASSERT_TRUE(one.selected.has_value());
    EXPECT_EQ(*one.selected, plain.ids[size_t(at.y) * W + at.x]);
    app::Options alone = testing_support::headlessOptions(W, H);
    alone.isolate = {*one.selected};
    EXPECT_TRUE(
        testing_support::sameIds(one.ids, app::renderHeadless(alone, scene, camera).ids, W));
    EXPECT_GT(std::count(one.ids.begin(), one.ids.end(), *one.selected), 0);
}

TEST(Xray, TheIdImageHoldsTheSelectionAsIsolatedAndTheRestShowsTranslucent) {
    app::SceneSettings source;
    source.builtin = "procedural:preset=small,seed=1";
    const app::LoadedScene loaded = app::loadScene(source);
    const scene::Scene& scene = loaded.scene;
    const scene::Camera camera = app::initialCamera(loaded, float(W) / float(H), {});
    const std::vector<render::RenderSettings> configs = xrayConfigs();

    // The parts seen in the middle of the view become the selection, under X-ray.
    app::Options xray = testing_support::headlessOptions(W, H);
    xray.selectRect = render::PartSetQuery{{W / 2 - 12, H / 2 - 8}, {W / 2 + 12, H / 2 + 8}};
    xray.live.xray = true;
    const app::HeadlessResult plain =
        app::renderHeadless(testing_support::headlessOptions(W, H), scene, camera);
    // The pixels to pick through, found on the image X-ray draws without picks.
    const auto first = app::renderHeadlessSequence(xray, scene, camera, {configs.front()});
    ASSERT_TRUE(first.front().rectParts.has_value());
    const scene::PartSet selected = *first.front().rectParts;
    ASSERT_GE(selected.size(), 3u);
    const auto through = pixelsThroughOthers(plain.ids, first.front().ids, selected);
    ASSERT_FALSE(through.empty()) << "no selected part lies behind another in this view";
    xray.picks = through;
    const auto xrayed = app::renderHeadlessSequence(xray, scene, camera, configs);
    app::Options isolate = testing_support::headlessOptions(W, H);
    isolate.isolate = selected.ids();
    const auto isolated = app::renderHeadlessSequence(isolate, scene, camera, configs);
    EXPECT_EQ(xrayed.front().validationMessages, 0u);
    EXPECT_EQ(isolated.front().validationMessages, 0u);

    for (size_t c = 0; c < configs.size(); ++c) {
        const std::string name = nameOf(configs[c]);
        const app::HeadlessResult& r = xrayed[c];
        ASSERT_TRUE(r.rectParts.has_value()) << name;
        // With MSAA the box reads the resolved IDs, which may find a sliver more or less: the
        // image to compare isolates what this configuration selected.
        const scene::PartSet& own = *r.rectParts;
        app::HeadlessResult alone;
        if (own != selected) {
            app::Options o = isolate;
            o.isolate = own.ids();
            alone = app::renderHeadlessSequence(o, scene, camera, {configs[c]}).front();
            EXPECT_EQ(alone.validationMessages, 0u);
        }
        const app::HeadlessResult& iso = own == selected ? isolated[c] : alone;
        expectSelectionAloneAndTheRestTranslucent(r, iso, plain, own, name);
        expectPicksReachTheSelection(r, through.size(), own, configs[c].pipeline.msaa, name);
        if (HasFatalFailure()) return;
    }
    expectAClickSelectsAsIsolated(scene, camera, plain, through.front());
    if (HasFatalFailure()) return;
    // The plain view shows other parts where X-ray shows the selection's.
    size_t covered = 0;
    for (size_t i = 0; i < plain.ids.size(); ++i)
        covered += plain.ids[i] != NONE && !selected.contains(plain.ids[i]);
    EXPECT_GT(covered, 500u);
}

// X-ray's sets: the selection's complement hidden and, of it, what is not hidden drawn
// translucent; nothing selected or X-ray off: the hidden parts alone.
TEST(Xray, PartsFollowTheSelectionAndTheHiddenParts) {
    scene::PartSet selected(70), hidden(70);
    selected.insert(3);
    selected.insert(40);
    hidden.insert(5);
    hidden.insert(40);
    const render::XrayParts on = render::xrayParts(true, selected, hidden);
    EXPECT_EQ(on.hidden.size(), 69u); // all but 3: 40 is hidden, so not shown either way
    EXPECT_FALSE(on.hidden.contains(3));
    EXPECT_EQ(on.translucent.size(), 67u); // neither selected nor hidden
    EXPECT_FALSE(on.translucent.contains(3) || on.translucent.contains(5) ||
                 on.translucent.contains(40));
    const render::XrayParts off = render::xrayParts(false, selected, hidden);
    EXPECT_EQ(off.hidden, hidden);
    EXPECT_TRUE(off.translucent.empty());
    const render::XrayParts none = render::xrayParts(true, scene::PartSet(70), hidden);
    EXPECT_EQ(none.hidden, hidden);
    EXPECT_TRUE(none.translucent.empty());
}

} // namespace
