// test_draw_list.cpp - each technique's draw list and per-draw data, checked against the
// scene without a GPU: draw count formulae, ID buffer offsets, sorting, stats.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "app/scene_source.h"
#include "render/draw_list.h"
#include "scene/copies.h"
#include "scene/procedural.h"

using namespace render;

namespace {

const scene::Scene& smallTwice() {
    static const scene::Scene s = scene::replicate(scene::makeProcedural({"small", 1}), 2);
    return s;
}

} // namespace

TEST(DrawList, CountsFollowTheFormulae) {
    const scene::Scene& s = smallTwice();
    for (uint32_t batch : {1u, 5u, 16u, 32u}) {
        size_t batches = 0;
        for (const auto& o : s.objects)
            batches += (s.geometries[o.geometry].partCount + batch - 1) / batch;
        for (const auto& t : techniques()) {
            const size_t draws = buildDrawList(s, t, {batch, true}).ranges.size();
            switch (t.split) {
            case DrawSplit::PerPart:
                EXPECT_EQ(draws, s.uniquePartCount()) << t.name;
                break;
            case DrawSplit::PerObject:
                EXPECT_EQ(draws, s.objects.size()) << t.name;
                break;
            case DrawSplit::PerBatch:
                EXPECT_EQ(draws, batches) << t.name << " batch " << batch;
                break;
            }
        }
    }
}

TEST(DrawList, DrawDataPointsAtEachDrawsIds) {
    const scene::Scene& s = smallTwice();
    for (const auto& t : techniques()) {
        DrawList list = buildDrawList(s, t, {16, true});
        ASSERT_EQ(list.data.size(), list.ranges.size());
        const uint32_t* words = reinterpret_cast<const uint32_t*>(list.idBytes.data());
        for (uint32_t i = 0; i < list.data.size(); ++i) {
            const gpu::DrawData& d = list.data[i];
            const DrawItem& r = list.ranges[i];
            ASSERT_EQ(d.drawIndex, i);
            ASSERT_EQ(d.objectIndex, r.object);
            ASSERT_EQ(d.firstPart, r.firstPart);
            ASSERT_EQ(d.partCount, r.partCount);
            const scene::Geometry& g = s.geometries[s.objects[r.object].geometry];
            const scene::Part& first = s.parts[g.firstPart + r.firstPart];
            if (t.ids == IdBuffer::PartTriangleCounts) {
                // The batch's counts start at its first part and hold each part's triangles.
                for (uint32_t p = 0; p < r.partCount; ++p)
                    ASSERT_EQ(words[d.idsOffset + p],
                              s.parts[g.firstPart + r.firstPart + p].triangleCount);
            } else if (t.ids == IdBuffer::PartTriangleOffsets) {
                ASSERT_EQ(words[d.idsOffset], 0u);
                ASSERT_EQ(words[d.idsOffset + d.partCount], g.triangleCount);
            } else if (t.ids == IdBuffer::TrianglePartIds) {
                // The last triangle's stored part is the geometry's last part.
                const uint32_t byte = d.idsOffset + (g.triangleCount - 1) * d.idsWidth;
                uint32_t value = 0;
                for (uint32_t b = 0; b < d.idsWidth; ++b)
                    value |= uint32_t(list.idBytes[byte + b]) << (8 * b);
                ASSERT_EQ(value, g.partCount - 1);
            } else {
                ASSERT_TRUE(list.idBytes.empty());
            }
            ASSERT_EQ(r.firstIndex, g.firstIndex + 3 * first.firstTriangle);
        }
    }
}

TEST(DrawList, SortedByGeometryThenMaterialUnlessAskedNot) {
    const scene::Scene& s = smallTwice();
    const Technique& perDraw = *findTechnique("per-draw");
    auto key = [&](const DrawItem& d) {
        const auto& o = s.objects[d.object];
        return std::pair(o.geometry, o.material);
    };
    DrawList sorted = buildDrawList(s, perDraw, {16, true});
    EXPECT_TRUE(
        std::is_sorted(sorted.ranges.begin(), sorted.ranges.end(),
                       [&](const DrawItem& a, const DrawItem& b) { return key(a) < key(b); }));
    DrawList scene = buildDrawList(s, perDraw, {16, false});
    EXPECT_TRUE(
        std::is_sorted(scene.ranges.begin(), scene.ranges.end(),
                       [](const DrawItem& a, const DrawItem& b) { return a.object < b.object; }));
    EXPECT_EQ(sorted.ranges.size(), scene.ranges.size());
    EXPECT_FALSE(
        std::equal(sorted.ranges.begin(), sorted.ranges.end(), scene.ranges.begin(),
                   [](const DrawItem& a, const DrawItem& b) { return a.object == b.object; }));
}

TEST(DrawList, StatsCountWhatEachModeUploads) {
    const scene::Scene& s = smallTwice();
    DrawList list = buildDrawList(s, *findTechnique("search-fs"), {16, true});
    RenderStats push = statsFor(list, *findDrawMode("push"));
    RenderStats base = statsFor(list, *findDrawMode("mdi-baseinstance"));
    RenderStats attr = statsFor(list, *findDrawMode("mdi-attribute"));
    EXPECT_EQ(push.draws, list.ranges.size());
    EXPECT_EQ(push.pipelines, 1u);
    EXPECT_EQ(push.idBufferBytes, 4 * (s.parts.size() + 15));
    EXPECT_EQ(push.perDrawBytes, 0u);
    EXPECT_EQ(base.perDrawBytes, 24 * list.ranges.size());
    EXPECT_EQ(base.indirectBytes, 20 * list.ranges.size());
    EXPECT_EQ(attr.indirectBytes, 24 * list.ranges.size());
}

// The benchmark's floor: one draw per object and no ID data.
TEST(DrawList, NoIdDrawsOncePerObjectWithoutIdData) {
    app::Options source;
    source.scene = "assembly";
    const scene::Scene scene = app::loadScene(source).scene;
    const render::Technique& noId = render::noIdTechnique();
    EXPECT_EQ(render::findTechnique("no-id"), &noId);
    const auto list = render::buildDrawList(scene, noId, {});
    EXPECT_EQ(list.ranges.size(), scene.objects.size());
    EXPECT_TRUE(list.idBytes.empty());
}

// --visible: only the first ceil(F * objects) objects are drawn, whatever the technique; draws
// and triangles follow from those objects alone.
TEST(DrawList, VisibleFractionDrawsTheFirstObjects) {
    const scene::Scene& s = smallTwice();
    EXPECT_EQ(visibleObjectCount(0.0f, 10), 0u);
    EXPECT_EQ(visibleObjectCount(0.1f, 10), 1u); // not 2: 0.1f is a hair above 0.1
    EXPECT_EQ(visibleObjectCount(0.25f, 10), 3u);
    EXPECT_EQ(visibleObjectCount(1.0f, 10), 10u);
    for (float fraction : {0.0f, 0.25f, 1.0f}) {
        const size_t objects = size_t(std::ceil(double(fraction) * double(s.objects.size())));
        size_t parts = 0, batches = 0;
        uint64_t triangles = 0;
        for (size_t o = 0; o < objects; ++o) {
            const scene::Geometry& g = s.geometries[s.objects[o].geometry];
            parts += g.partCount;
            batches += (g.partCount + 15) / 16;
            triangles += g.triangleCount;
        }
        for (const auto& t : techniques())
            for (const auto& m : drawModes()) {
                const DrawList list = buildDrawList(s, t, {16, true, fraction});
                const RenderStats stats = statsFor(list, m);
                const size_t draws = t.split == DrawSplit::PerPart     ? parts
                                     : t.split == DrawSplit::PerObject ? objects
                                                                       : batches;
                EXPECT_EQ(stats.draws, draws) << t.name << " " << fraction;
                EXPECT_EQ(stats.triangles, triangles) << t.name << " " << fraction;
                for (const DrawItem& d : list.ranges) EXPECT_LT(d.object, objects) << t.name;
            }
    }
    EXPECT_EQ(statsFor(buildDrawList(s, techniques()[0], {}), drawModes()[0]).triangles,
              s.drawnTriangleCount());
}
