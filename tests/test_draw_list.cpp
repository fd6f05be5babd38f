// test_draw_list.cpp - each technique's draw list and per-draw data, checked against the
// scene without a GPU: draw count formulae, ID buffer offsets, sorting, stats.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "render/draw_list.h"
#include "scene/copies.h"
#include "scene/procedural/procedural.h"

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

// The derived geometry of smallTwice(), built once.
const scene::PartVertices& partVertices() {
    static const scene::PartVertices p = scene::buildPartVertices(smallTwice());
    return p;
}
// Every mesh technique draws the meshlets of the part vertices.
const scene::Meshlets& meshlets() {
    static const scene::Meshlets m = scene::buildMeshlets(smallTwice(), &partVertices());
    return m;
}
DerivedPrimitives derivedFor(const Technique& t) {
    DerivedPrimitives d;
    if (t.usesPartVertices()) d.partVertices = &partVertices();
    if (t.usesMeshShader()) d.meshlets = &meshlets();
    return d;
}

// The draw list of smallTwice() for `key`, with the derived geometry its technique needs.
DrawList listFor(const PipelineKey& key, const DrawSettings& settings = drawn()) {
    return buildDrawList(smallTwice(), key, settings, derivedFor(*key.technique));
}

// The value at `element` of a packed part-index array (1, 2 or 4 bytes, little-endian).
uint32_t packedAt(const DrawList& list, const gpu::DrawData& d, uint32_t element) {
    const uint32_t byte = d.idsOffset + element * d.idsWidth;
    uint32_t value = 0;
    for (uint32_t b = 0; b < d.idsWidth; ++b) value |= uint32_t(list.idBytes[byte + b]) << (8 * b);
    return value;
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
            const size_t draws = listFor(keyFor(t, batch)).ranges.size();
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
        DrawList list = listFor(keyFor(t));
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
                ASSERT_EQ(packedAt(list, d, g.triangleCount - 1), g.partCount - 1);
            } else if (t.ids == IdBuffer::VertexPartIds) {
                // Every triangle's first (rotated) vertex holds the triangle's part.
                const scene::PartVertices& pv = partVertices();
                const uint32_t geometry = s.objects[r.object].geometry;
                ASSERT_EQ(r.vertexOffset, int32_t(pv.firstVertex[geometry]));
                ASSERT_EQ(d.firstElement, pv.firstVertex[geometry]);
                const auto parts = scene::trianglePartsOf(s, geometry);
                for (uint32_t tri = 0; tri < g.triangleCount; ++tri) {
                    const uint32_t lead = pv.indices[g.firstIndex + 3 * tri];
                    ASSERT_EQ(packedAt(list, d, lead), parts[tri]) << t.name << " triangle " << tri;
                }
            } else if (t.ids == IdBuffer::MeshletTrianglePartIds) {
                // Each meshlet triangle's stored part is its source triangle's part.
                const scene::Meshlets& m = meshlets();
                const uint32_t geometry = s.objects[r.object].geometry;
                ASSERT_EQ(d.firstElement, m.firstMeshlet[geometry]);
                ASSERT_EQ(list.meshletCounts[i], m.meshletCount[geometry]);
                const auto parts = scene::trianglePartsOf(s, geometry);
                const uint32_t base = m.geometryFirstTriangle[geometry];
                for (uint32_t k = 0; k < g.triangleCount; ++k)
                    ASSERT_EQ(packedAt(list, d, k), parts[m.sourceTriangle[base + k]]) << k;
            } else if (t.ids == IdBuffer::MeshletVertexPartIds) {
                // Each meshlet triangle's first corner stores the part of its source triangle.
                const scene::Meshlets& m = meshlets();
                const uint32_t geometry = s.objects[r.object].geometry;
                ASSERT_EQ(d.firstElement, m.firstMeshlet[geometry]);
                const auto parts = scene::trianglePartsOf(s, geometry);
                const uint32_t base = m.geometryFirstVertex[geometry];
                for (uint32_t k = 0; k < m.meshletCount[geometry]; ++k) {
                    const scene::Meshlet& meshlet = m.meshlets[m.firstMeshlet[geometry] + k];
                    ASSERT_EQ(meshlet.firstVertex, base + meshlet.firstLocalVertex);
                    for (uint32_t i = 0; i < meshlet.triangleCount; ++i) {
                        const uint32_t at = meshlet.firstTriangle + i;
                        // Indexed by the absolute meshlet vertex (DrawData::idsOffset).
                        const uint32_t lead = meshlet.firstVertex + m.corners[3 * at];
                        ASSERT_EQ(packedAt(list, d, lead), parts[m.sourceTriangle[at]]) << at;
                    }
                }
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
    DrawList list = listFor(keyFor(search));
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
    EXPECT_EQ(base.perDrawBytes, sizeof(gpu::DrawData) * list.ranges.size());
    EXPECT_EQ(base.indirectBytes, 20 * list.ranges.size());
    EXPECT_EQ(attr.indirectBytes, 24 * list.ranges.size());
}

// The benchmark's floors: one per kind of pipeline, one draw per object and no ID data; each
// technique is measured against the floor of its own kind.
TEST(DrawList, FloorsDrawOncePerObjectWithoutIdData) {
    const render::Technique& noId = render::floorTechnique();
    EXPECT_EQ(render::findTechnique(noId.name), &noId);
    EXPECT_FALSE(noId.usesMeshShader());
    size_t floors = 0;
    for (const Technique& t : techniques()) {
        const Technique& floor = floorOf(t);
        EXPECT_TRUE(floor.isFloor()) << t.name;
        EXPECT_EQ(floor.primitives == Primitives::Meshlets, t.usesMeshShader()) << t.name;
        if (!t.isFloor()) continue;
        ++floors;
        EXPECT_EQ(&floor, &t);
        const auto list = listFor(keyFor(t));
        EXPECT_EQ(list.ranges.size(), smallTwice().objects.size()) << t.name;
        EXPECT_TRUE(list.idBytes.empty()) << t.name;
    }
    EXPECT_EQ(floors, 2u); // vertex and mesh pipelines
    EXPECT_EQ(render::partIdTechniques().size() + floors, techniques().size());
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
                const DrawList list = listFor(keyFor(t), drawn(true, fraction));
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
