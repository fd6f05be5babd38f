// test_draw_list.cpp - each technique's draw list and per-draw data, checked against the
// scene without a GPU: draw count formulae, ID buffer offsets, sorting, stats.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

PipelineKey keyFor(const Technique& technique, uint32_t batch = 16) {
    PipelineKey key;
    key.technique = &technique;
    key.searchBatch = batch;
    return key;
}

DrawSettings drawn(bool sorted = true, float visible = 1.0f) {
    return {sorted, visible};
}

// The first technique of the registry that `matches`.
template <typename Pred>
const Technique& firstWith(Pred matches) {
    for (const auto& t : techniques())
        if (matches(t)) return t;
    throw std::logic_error("no such technique in the registry");
}

} // namespace

TEST(DrawList, CountsFollowTheFormulae) {
    const scene::Scene& s = smallTwice();
    for (uint32_t batch : {1u, 5u, 16u, 32u}) {
        size_t batches = 0;
        for (const auto& o : s.objects)
            batches += (s.geometries[o.geometry].partCount + batch - 1) / batch;
        for (const auto& t : techniques()) {
            const size_t draws = buildDrawList(s, keyFor(t, batch), drawn()).ranges.size();
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
        DrawList list = buildDrawList(s, keyFor(t), drawn());
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
    const Technique& perDraw =
        firstWith([](const Technique& t) { return t.split == DrawSplit::PerPart; });
    auto key = [&](const DrawItem& d) {
        const auto& o = s.objects[d.object];
        return std::pair(o.geometry, o.material);
    };
    DrawList sorted = buildDrawList(s, keyFor(perDraw), drawn(true));
    EXPECT_TRUE(
        std::is_sorted(sorted.ranges.begin(), sorted.ranges.end(),
                       [&](const DrawItem& a, const DrawItem& b) { return key(a) < key(b); }));
    DrawList scene = buildDrawList(s, keyFor(perDraw), drawn(false));
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
    const Technique& search = firstWith([](const Technique& t) { return t.readsSearchBatch(); });
    DrawList list = buildDrawList(s, keyFor(search), drawn());
    auto modeWith = [](bool indirect, bool attribute) {
        for (const auto& m : drawModes())
            if (m.indirect == indirect && m.drawIndexAttribute == attribute) return &m;
        throw std::logic_error("no such mode in the registry");
    };
    RenderStats push = statsFor(list, *modeWith(false, false));
    RenderStats base = statsFor(list, *modeWith(true, false));
    RenderStats attr = statsFor(list, *modeWith(true, true));
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
    app::SceneSettings source;
    source.builtin = "assembly";
    const scene::Scene scene = app::loadScene(source).scene;
    const render::Technique& noId = render::floorTechnique();
    EXPECT_EQ(render::findTechnique(noId.name), &noId);
    // The one floor, in the registry with the rest, and not among the part-ID techniques.
    EXPECT_EQ(std::count_if(techniques().begin(), techniques().end(),
                            [](const Technique& t) { return t.isFloor(); }),
              1);
    EXPECT_EQ(render::partIdTechniques().size() + 1, techniques().size());
    const auto list = render::buildDrawList(scene, keyFor(noId), drawn());
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
                const DrawList list = buildDrawList(s, keyFor(t), drawn(true, fraction));
                const RenderStats stats = statsFor(list, m);
                const size_t draws = t.split == DrawSplit::PerPart     ? parts
                                     : t.split == DrawSplit::PerObject ? objects
                                                                       : batches;
                EXPECT_EQ(stats.draws, draws) << t.name << " " << fraction;
                EXPECT_EQ(stats.triangles, triangles) << t.name << " " << fraction;
                for (const DrawItem& d : list.ranges) EXPECT_LT(d.object, objects) << t.name;
            }
    }
    EXPECT_EQ(statsFor(buildDrawList(s, PipelineKey{}, DrawSettings{}), drawModes()[0]).triangles,
              s.drawnTriangleCount());
}

// The pipeline cache keys on the effective key: what the technique does not read is reset, and
// passthrough holds only where a geometry stage meets a device that offers it.
TEST(PipelineKey, EffectiveKeyKeepsOnlyWhatTheTechniqueReads) {
    for (const auto& t : techniques()) {
        PipelineKey key = keyFor(t, 7);
        key.nsearch = {5, true, 3, 9};
        key.gsPassthrough = true;
        for (bool device : {false, true}) {
            const PipelineKey e = key.effective(device);
            EXPECT_EQ(e.technique, &t);
            EXPECT_EQ(e.searchBatch, t.readsSearchBatch() ? 7u : PipelineKey{}.searchBatch)
                << t.name;
            EXPECT_EQ(e.nsearch, t.narySearch ? key.nsearch : NarySearch{}) << t.name;
            EXPECT_EQ(e.gsPassthrough, device && t.stage == LookupStage::Geometry) << t.name;
            EXPECT_EQ(e.effective(device), e); // settled
        }
        key.gsPassthrough = false; // --gs-ordinary wins over the device
        EXPECT_FALSE(key.effective(true).gsPassthrough) << t.name;
    }
}
