// test_id_passes.cpp - what the ID buffer buys, checked for every technique the registry
// lists, on lavapipe with validation on: part edges and outlines against the same rule
// applied on the CPU to the ID image; box selection and the visible parts against the IDs
// in the ID image; hidden and isolated parts against the unhidden image and a CPU ray cast
// (hidden parts never reach the ID image, picks go through them); at full detail and with
// every object at its coarsest level of detail, and in orthographic projection.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "app/headless.h"
#include "app/scene_source.h"
#include "image_compare.h"
#include "raster_explainer.h"
#include "render/technique.h"
#include "scene/lod.h"
#include "scene/raycast.h"
#include "test_support.h"

namespace {

constexpr uint32_t W = 240, H = 150;
constexpr uint32_t NONE = gpu::BACKGROUND_ID;
using testing_support::sameIds;

struct Fixture {
    app::LoadedScene loaded;
    scene::Camera camera;
    scene::Section section;    // every configuration draws it, the ray cast honours it
    std::vector<uint32_t> ids; // per-draw + push, nothing hidden
};

// The scene at full detail, or with every object at its coarsest level of detail
// (scene/lod.h), whose geometry the ray cast then follows too; at full detail seen from the
// isometric view in orthographic projection (the ray cast's rays then run parallel); or at
// full detail cut by a section plane through the middle of the assembly's height, the camera
// on the side cut away.
enum class Detail { Full, Coarsest, Ortho, Sectioned };

Fixture& fixture(Detail detail) {
    static std::map<Detail, Fixture> fixtures;
    auto [it, added] = fixtures.try_emplace(detail);
    Fixture& fx = it->second;
    if (!added) return fx;
    app::SceneSettings source;
    source.builtin = "procedural:preset=small,seed=1";
    source.copies = 2;
    if (detail == Detail::Coarsest) {
        source.lodLevels = scene::maxLevels;
        source.lodLevel = scene::maxLevels - 1;
    }
    fx.loaded = app::loadScene(source);
    app::CameraSettings view;
    if (detail == Detail::Ortho) view = {scene::findStandardView("isometric"), true};
    fx.camera = app::initialCamera(fx.loaded, float(W) / float(H), view);
    if (detail == Detail::Sectioned) // across the plates, the camera on the side cut away
        fx.section.planes[0] =
            scene::axisPlane(2, fx.camera.target.z, fx.camera.eye.z < fx.camera.target.z);
    app::Options o = testing_support::headlessOptions(W, H);
    o.live.render.section = fx.section;
    fx.ids = app::renderHeadless(o, fx.loaded.scene, fx.camera).ids;
    return fx;
}

class IdPasses : public ::testing::TestWithParam<Detail> {};

std::string detailName(const ::testing::TestParamInfo<Detail>& info) {
    const char* names[] = {"FullDetail", "CoarsestLevel", "Ortho", "Sectioned"};
    return names[int(info.param)];
}

// Every part-ID technique in push mode, then every mode of the default technique and two
// with 4x MSAA: the passes read the resolved image, whatever drew it. All draw the fixture's
// section, if any.
std::vector<render::RenderSettings> configurations(const Fixture& f) {
    std::vector<render::RenderSettings> configs;
    for (const render::Technique* t : render::partIdTechniques())
        configs.push_back(testing_support::settingsFor(*t, render::defaultDrawMode()));
    for (const auto& m : render::drawModes())
        configs.push_back(testing_support::settingsFor(render::defaultTechnique(), m));
    for (const char* name : {"vertex-fs", "tri-fs"}) {
        configs.push_back(
            testing_support::settingsFor(*render::findTechnique(name), render::defaultDrawMode()));
        configs.back().pipeline.msaa = 4;
    }
    for (render::RenderSettings& c : configs) c.section = f.section;
    return configs;
}

std::string nameOf(const render::RenderSettings& s) {
    return std::string(s.pipeline.technique->name) + " + " + s.pipeline.mode->name + " msaa " +
           std::to_string(s.pipeline.msaa);
}

scene::PartSet idsIn(const std::vector<uint32_t>& ids, uint32_t partCount, uint32_t x0, uint32_t y0,
                     uint32_t x1, uint32_t y1) {
    scene::PartSet set(partCount);
    for (uint32_t y = y0; y <= y1; ++y)
        for (uint32_t x = x0; x <= x1; ++x)
            if (ids[size_t(y) * W + x] != NONE) set.insert(ids[size_t(y) * W + x]);
    return set;
}

// The edge rule of shared.h (EdgePush) on the CPU: what colour each pixel takes, or none.
enum class Line { None, Edge, Hovered, Selected };

std::vector<Line> expectedLines(const std::vector<uint32_t>& ids, uint32_t width,
                                const scene::PartSet& selected, uint32_t hovered) {
    auto at = [&](int x, int y) {
        x = std::clamp(x, 0, int(W) - 1);
        y = std::clamp(y, 0, int(H) - 1);
        return ids[size_t(y) * W + size_t(x)];
    };
    // Whether the window of width w at (x, y) holds an ID for which `a` and one for which
    // `b` hold.
    auto window = [&](int x, int y, int w, auto a, auto b) {
        bool hasA = false, hasB = false;
        for (int dy = -w / 2; dy <= (w + 1) / 2; ++dy)
            for (int dx = -w / 2; dx <= (w + 1) / 2; ++dx) {
                const uint32_t id = at(x + dx, y + dy);
                hasA = hasA || a(id);
                hasB = hasB || b(id);
            }
        return hasA && hasB;
    };
    std::vector<Line> lines(size_t(W) * H, Line::None);
    const int w = int(width);
    for (int y = 0; y < int(H); ++y)
        for (int x = 0; x < int(W); ++x) {
            const uint32_t first = at(x - w / 2, y - w / 2);
            auto isSelected = [&](uint32_t id) { return id != NONE && selected.contains(id); };
            Line& line = lines[size_t(y) * W + size_t(x)];
            if (window(x, y, w + 2, isSelected, [&](uint32_t id) { return !isSelected(id); }))
                line = Line::Selected;
            else if (hovered != NONE && window(
                                            x, y, w + 1, [&](uint32_t id) { return id == hovered; },
                                            [&](uint32_t id) { return id != hovered; }))
                line = Line::Hovered;
            else if (window(
                         x, y, w, [&](uint32_t id) { return id != first; },
                         [](uint32_t) { return true; }))
                line = Line::Edge;
        }
    return lines;
}

// The first pixel from (x, y) on along its row inside a 5x5 block of one part.
app::Options::Pixel interiorPixel(const std::vector<uint32_t>& ids, uint32_t x, uint32_t y) {
    for (; x + 2 < W; ++x) {
        const uint32_t id = ids[size_t(y) * W + x];
        bool inside = id != NONE;
        for (uint32_t dy = y - 2; dy <= y + 2; ++dy)
            for (uint32_t dx = x - 2; dx <= x + 2; ++dx)
                inside = inside && ids[size_t(dy) * W + dx] == id;
        if (inside) return {x, y};
    }
    return {0, 0};
}

glm::u8vec3 bytes(glm::vec3 color) {
    return glm::u8vec3(glm::round(color * 255.0f));
}

} // namespace

// With edges on, exactly the pixels the CPU rule marks change, each to its line's colour;
// everything else is the image without edges, byte for byte. A box selection makes the
// selected outline and the last pick the hovered one; the widths take turns.
TEST_P(IdPasses, EdgesFollowTheRuleOnTheIdImageForEveryTechnique) {
    Fixture& f = fixture(GetParam());
    const auto plainConfigs = configurations(f);
    std::vector<render::RenderSettings> edgeConfigs = plainConfigs;
    for (size_t i = 0; i < edgeConfigs.size(); ++i) {
        edgeConfigs[i].edges.on = true;
        edgeConfigs[i].edges.width = 1 + uint32_t(i % 3);
    }
    app::Options o = testing_support::headlessOptions(W, H);
    o.selectRect = render::PartSetQuery{{100, 60}, {130, 85}};
    o.picks = {interiorPixel(f.ids, 60, 80)};
    const auto plain = app::renderHeadlessSequence(o, f.loaded.scene, f.camera, plainConfigs);
    const auto edged = app::renderHeadlessSequence(o, f.loaded.scene, f.camera, edgeConfigs);
    EXPECT_EQ(plain.front().validationMessages, 0u);
    EXPECT_EQ(edged.front().validationMessages, 0u);
    const render::EdgeSettings& colors = edgeConfigs.front().edges;
    for (size_t c = 0; c < edgeConfigs.size(); ++c) {
        const std::string name =
            nameOf(edgeConfigs[c]) + " width " + std::to_string(edgeConfigs[c].edges.width);
        const app::HeadlessResult& r = edged[c];
        // The pass draws into the colour only.
        ASSERT_TRUE(sameIds(r.ids, plain[c].ids, W)) << name;
        ASSERT_TRUE(r.rectParts && !r.rectParts->empty()) << name;
        ASSERT_TRUE(r.picks.front().part.has_value()) << name;
        const auto lines =
            expectedLines(r.ids, edgeConfigs[c].edges.width, *r.rectParts, *r.picks.front().part);
        size_t counts[4] = {}, wrong = 0;
        for (size_t i = 0; i < lines.size(); ++i) {
            ++counts[size_t(lines[i])];
            const glm::u8vec3 got(r.color[4 * i], r.color[4 * i + 1], r.color[4 * i + 2]);
            const glm::u8vec3 before(plain[c].color[4 * i], plain[c].color[4 * i + 1],
                                     plain[c].color[4 * i + 2]);
            glm::u8vec3 want = before;
            if (lines[i] == Line::Edge) want = bytes(colors.color);
            if (lines[i] == Line::Hovered) want = bytes(colors.hoverColor);
            if (lines[i] == Line::Selected) want = bytes(colors.selectColor);
            if (got != want && wrong++ < 3)
                ADD_FAILURE() << name << ": pixel " << i % W << "," << i / W << " line "
                              << int(lines[i]);
        }
        EXPECT_EQ(wrong, 0u) << name;
        // The rule drew all three kinds of line here, so none of them can silently vanish.
        EXPECT_GT(counts[size_t(Line::Edge)], 50u) << name; // the cut scene, width 3: 77
        EXPECT_GT(counts[size_t(Line::Hovered)], 0u) << name;
        EXPECT_GT(counts[size_t(Line::Selected)], 20u) << name;
        EXPECT_GT(counts[size_t(Line::None)], 10000u) << name;
    }
}

// --select-rect and --visible-parts: the parts are exactly the IDs in that rectangle, or
// the whole image, of the ID image; the GPU's count agrees with its bitset.
TEST_P(IdPasses, PartSetsEqualTheIdsInTheRectangleForEveryTechnique) {
    Fixture& f = fixture(GetParam());
    const uint32_t partCount = f.loaded.scene.uniquePartCount();
    const auto configs = configurations(f);
    for (const render::PartSetQuery& rect :
         {render::PartSetQuery{{37, 21}, {181, 118}}, render::PartSetQuery{{0, 0}, {0, 0}},
          render::PartSetQuery{{120, 75}, {W - 1, H - 1}}}) {
        app::Options o = testing_support::headlessOptions(W, H);
        o.selectRect = rect;
        o.visibleParts = true;
        const auto results = app::renderHeadlessSequence(o, f.loaded.scene, f.camera, configs);
        EXPECT_EQ(results.front().validationMessages, 0u);
        for (size_t c = 0; c < configs.size(); ++c) {
            const app::HeadlessResult& r = results[c];
            const std::string name = nameOf(configs[c]);
            ASSERT_TRUE(r.rectParts && r.visibleParts) << name;
            const auto inRect =
                idsIn(r.ids, partCount, rect.min.x, rect.min.y, rect.max.x, rect.max.y);
            EXPECT_EQ(r.rectParts->ids(), inRect.ids()) << name;
            EXPECT_EQ(r.rectCount, inRect.size()) << name;
            const auto all = idsIn(r.ids, partCount, 0, 0, W - 1, H - 1);
            EXPECT_EQ(r.visibleParts->ids(), all.ids()) << name;
            EXPECT_EQ(r.visibleCount, all.size()) << name;
            EXPECT_GT(all.size(), 100u) << name; // the scene fills the view
        }
    }
}

namespace {

// Up to six pixels showing a part of `middle` (hidden below) behind which lies another part,
// at the pixel's centre and at sample 0 of 4x.
std::vector<app::Options::Pixel> pixelsBehindTheMiddle(const Fixture& f,
                                                       const scene::PartSet& middle,
                                                       const scene::RayCaster& caster,
                                                       const glm::dmat4& viewProj) {
    std::vector<app::Options::Pixel> through;
    for (uint32_t y = 52; y < 100 && through.size() < 6; y += 7)
        for (uint32_t x = 92; x < 150 && through.size() < 6; x += 11) {
            bool hits = true;
            for (glm::vec2 at : {glm::vec2(0.5f), glm::vec2(0.375f, 0.125f)})
                hits = hits &&
                       caster.cast(scene::pixelRay(viewProj, glm::vec2(W, H), glm::vec2(x, y) + at),
                                   &middle, &f.section);
            if (middle.contains(f.ids[size_t(y) * W + x]) && hits) through.push_back({x, y});
        }
    return through;
}

// With `middle` hidden, `r` shows none of it and keeps the part of every pixel that `own`
// (the same configuration with nothing hidden) shows outside it.
void expectHiddenGoneAndTheRestKept(const app::HeadlessResult& r, const std::vector<uint32_t>& own,
                                    const scene::PartSet& middle, const std::string& name) {
    size_t shown = 0, kept = 0;
    for (size_t i = 0; i < r.ids.size(); ++i) {
        shown += middle.contains(r.ids[i]);
        if (!middle.contains(own[i])) kept += r.ids[i] == own[i];
    }
    EXPECT_EQ(shown, 0u) << name;
    EXPECT_EQ(kept, r.ids.size() -
                        size_t(std::count_if(own.begin(), own.end(),
                                             [&](uint32_t id) { return middle.contains(id); })))
        << name;
}

// Picks where hidden parts were find a part outside them: the one the CPU ray cast that skips
// them meets at sample 0 (Vulkan's standard 4x pattern puts it off centre), and at 1x the one
// the ID image shows.
void expectPicksGoThrough(const app::HeadlessResult& r, const Fixture& f,
                          const scene::PartSet& middle, const scene::RayCaster& caster,
                          const glm::dmat4& viewProj, uint32_t msaa, const std::string& name) {
    for (const auto& pick : r.picks) {
        const std::string where =
            name + " at " + std::to_string(pick.pixel.x) + "," + std::to_string(pick.pixel.y);
        const glm::vec2 sample =
            glm::vec2(pick.pixel) + (msaa == 4 ? glm::vec2(0.375f, 0.125f) : glm::vec2(0.5f));
        const auto hit =
            caster.cast(scene::pixelRay(viewProj, glm::vec2(W, H), sample), &middle, &f.section);
        ASSERT_TRUE(pick.part.has_value()) << where;
        EXPECT_FALSE(middle.contains(*pick.part)) << where;
        if (msaa == 1) {
            EXPECT_EQ(*pick.part, r.ids[size_t(pick.pixel.y) * W + pick.pixel.x]) << where;
        }
        ASSERT_TRUE(hit.has_value()) << where;
        EXPECT_EQ(*pick.part, hit->uniquePartId) << where;
    }
}

// Isolating `middle`: only its parts are drawn, and where they were visible they stay.
void expectIsolatingKeepsOnlyTheMiddle(const Fixture& f, const scene::PartSet& middle,
                                       const std::vector<render::RenderSettings>& configs) {
    app::Options isolate = testing_support::headlessOptions(W, H);
    isolate.isolate = middle.ids();
    const auto isolated = app::renderHeadlessSequence(isolate, f.loaded.scene, f.camera, configs);
    EXPECT_EQ(isolated.front().validationMessages, 0u);
    for (size_t c = 0; c < configs.size(); ++c) {
        if (configs[c].pipeline.msaa != 1) continue;
        const auto& ids = isolated[c].ids;
        for (size_t i = 0; i < ids.size(); ++i) {
            ASSERT_TRUE(ids[i] == NONE || middle.contains(ids[i])) << nameOf(configs[c]);
            if (middle.contains(f.ids[i])) {
                ASSERT_EQ(ids[i], f.ids[i]) << nameOf(configs[c]);
            }
        }
    }
}

} // namespace

// Hiding the parts seen in the middle of the view: none of them reaches the ID image, every
// other pixel keeps its part, the hidden pixels show what a CPU ray cast that skips them
// hits, and picks there find it. Isolating keeps only the isolated parts. Every technique
// draws the same images.
TEST_P(IdPasses, HiddenPartsVanishAndPicksGoThroughForEveryTechnique) {
    Fixture& f = fixture(GetParam());
    const scene::Scene& scene = f.loaded.scene;
    const scene::PartSet middle = idsIn(f.ids, scene.uniquePartCount(), 90, 50, 150, 100);
    ASSERT_GT(middle.size(), 10u);
    const auto configs = configurations(f);

    const scene::RayCaster caster(scene);
    const glm::dmat4 viewProj = f.camera.viewProjection(float(W) / float(H));
    app::Options o = testing_support::headlessOptions(W, H);
    o.hide = middle.ids();
    o.picks = pixelsBehindTheMiddle(f, middle, caster, viewProj);
    ASSERT_GE(o.picks.size(), 3u);
    const auto hidden = app::renderHeadlessSequence(o, scene, f.camera, configs);
    EXPECT_EQ(hidden.front().validationMessages, 0u);
    // Each configuration's own image with nothing hidden: lavapipe may rasterize a sliver
    // face of a geometry or mesh shader path a pixel apart from the vertex path's.
    const auto shownAll = app::renderHeadlessSequence(testing_support::headlessOptions(W, H), scene,
                                                      f.camera, configs);
    size_t firstOwnPath = 0;
    for (size_t c = 0; c < configs.size() && !firstOwnPath; ++c)
        if (configs[c].pipeline.technique->stage == render::LookupStage::Geometry) firstOwnPath = c;
    for (size_t c = 0; c < configs.size(); ++c) {
        const app::HeadlessResult& r = hidden[c];
        const std::string name = nameOf(configs[c]);
        if (configs[c].pipeline.msaa == 1) {
            expectHiddenGoneAndTheRestKept(r, shownAll[c].ids, middle, name);
            // Every technique draws the same image as the first of its rasterization path:
            // lavapipe rasterizes primitives from a geometry or mesh shader apart from the
            // vertex path, and at a sliver face seen edge-on the two may differ by a pixel
            // (seen without hiding too, at other sizes); here one such face is revealed.
            const bool ownPath =
                configs[c].pipeline.technique->stage == render::LookupStage::Geometry ||
                configs[c].pipeline.technique->usesMeshShader();
            const size_t first = ownPath ? firstOwnPath : 0;
            EXPECT_TRUE(testing_support::sameIdsAs(*configs[c].pipeline.technique, r.ids,
                                                   hidden[first].ids, scene, f.camera, {W, H}, 1))
                << name << " against " << nameOf(configs[first]);
        }
        ASSERT_EQ(r.picks.size(), o.picks.size()) << name;
        expectPicksGoThrough(r, f, middle, caster, viewProj, configs[c].pipeline.msaa, name);
        if (HasFatalFailure()) return;
    }
    // Parts behind the hidden ones show through.
    size_t revealed = 0;
    for (size_t i = 0; i < f.ids.size(); ++i)
        revealed += middle.contains(f.ids[i]) && hidden.front().ids[i] != NONE;
    EXPECT_GT(revealed, 100u);
    expectIsolatingKeepsOnlyTheMiddle(f, middle, configs);
}

// Showing everything again (an empty hidden set) goes back to the pipeline without the
// hiding variant and to the unhidden image.
// Picks, box selection, edges and hiding, at full detail, at the coarsest level of detail, in
// ortho and cut by a section plane.
INSTANTIATE_TEST_SUITE_P(Lavapipe, IdPasses,
                         ::testing::Values(Detail::Full, Detail::Coarsest, Detail::Ortho,
                                           Detail::Sectioned),
                         detailName);

// The coarsest level and the section draw other images than full detail: the cases above
// test other geometry, not the same one thrice.
TEST(IdPassesLevels, TheCoarsestLevelAndTheSectionAreOtherImages) {
    EXPECT_FALSE(sameIds(fixture(Detail::Full).ids, fixture(Detail::Coarsest).ids, W));
    EXPECT_FALSE(sameIds(fixture(Detail::Full).ids, fixture(Detail::Sectioned).ids, W));
    EXPECT_LT(fixture(Detail::Coarsest).loaded.scene.drawnTriangleCount(),
              fixture(Detail::Full).loaded.scene.drawnTriangleCount());
}

TEST(Hide, ShowingAllRestoresTheImage) {
    Fixture& f = fixture(Detail::Full);
    app::Options o = testing_support::headlessOptions(W, H);
    app::Offscreen rig(*new vk::Instance({true, {}, false}), o); // the instance lives on
    rig.renderer.setScene(f.loaded.scene, o.live.render);
    const VkPipeline plain = rig.renderer.pipeline();
    scene::PartSet hidden(f.loaded.scene.uniquePartCount());
    hidden.insert(0);
    rig.renderer.setHidden(hidden);
    EXPECT_NE(rig.renderer.pipeline(), plain);
    rig.renderer.setHidden(scene::PartSet(f.loaded.scene.uniquePartCount()));
    EXPECT_EQ(rig.renderer.pipeline(), plain); // the same one, from the cache
}
