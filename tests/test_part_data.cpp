// test_part_data.cpp - derived per-part data and draw lists checked against the scene they
// come from, and model copies.
#include <gtest/gtest.h>

#include "scene/copies.h"
#include "scene/procedural/generator.h"
#include "scene/mesh_builder.h"
#include "scene/part_data.h"

using namespace scene;

namespace {

// A geometry with `parts` parts of 1, 2, 3, ... triangles (fans of a polygon).
uint32_t addFanGeometry(Scene& s, uint32_t parts) {
    MeshBuilder mb;
    for (uint32_t p = 0; p < parts; ++p) {
        mb.beginPart();
        uint32_t c = mb.addVertex({0, 0, float(p)}, {0, 0, 1});
        for (uint32_t t = 0; t <= (p % 5) + 1; ++t)
            mb.addVertex({std::cos(t * 0.3f), std::sin(t * 0.3f), float(p)}, {0, 0, 1});
        for (uint32_t t = 0; t < (p % 5) + 1; ++t) mb.addTriangle(c, c + 1 + t, c + 2 + t);
    }
    return mb.finish(s, "fan " + std::to_string(parts));
}

Scene mixedScene() {
    Scene s;
    addMaterial(s, "m", {1, 1, 1, 1});
    const uint32_t few = addFanGeometry(s, 7);    // 8-bit part indices
    const uint32_t many = addFanGeometry(s, 300); // 16-bit part indices
    addObject(s, few, 0, glm::mat4(1));
    addObject(s, many, 0, glm::mat4(1));
    addObject(s, few, 0, glm::mat4(2));
    validate(s);
    return s;
}

} // namespace

TEST(PartData, TrianglePartIdsNameEachTrianglesPart) {
    Scene s = mixedScene();
    TrianglePartIds ids = buildTrianglePartIds(s);
    ASSERT_EQ(ids.geometries.size(), 2u);
    EXPECT_EQ(ids.geometries[0].elementBytes, 1u);
    EXPECT_EQ(ids.geometries[1].elementBytes, 2u);
    EXPECT_EQ(ids.geometries[1].byteOffset % 4, 0u);
    EXPECT_EQ(ids.bytes.size() % 4, 0u);
    for (uint32_t g = 0; g < s.geometries.size(); ++g)
        for (uint32_t p = 0; p < s.geometries[g].partCount; ++p) {
            const Part& part = s.parts[s.geometries[g].firstPart + p];
            for (uint32_t t = 0; t < part.triangleCount; ++t)
                ASSERT_EQ(ids.partOf(g, part.firstTriangle + t), p);
        }
    EXPECT_EQ(partIndexBytes(256), 1u);
    EXPECT_EQ(partIndexBytes(257), 2u);
    EXPECT_EQ(partIndexBytes(65536), 2u);
    EXPECT_EQ(partIndexBytes(65537), 4u);
    EXPECT_EQ(idDataBytes(s, 16).trianglePartIds, ids.bytes.size());
}

TEST(PartData, CountsArePaddedForTheFixedSearchLoop) {
    Scene s = mixedScene();
    for (uint32_t search : {1u, 4u, 16u, 32u}) {
        PartTriangleCounts c = buildPartTriangleCounts(s, search);
        EXPECT_EQ(c.counts.size(), s.parts.size() + search - 1);
        EXPECT_EQ(idDataBytes(s, search).partTriangleCounts, 4 * c.counts.size());
        // The loop reads search entries from the start of every batch of every draw.
        for (const DrawRange& d : drawsPerBatch(s, search)) {
            const uint32_t g = s.objects[d.object].geometry;
            const uint32_t start = c.geometryOffsets[g] + d.firstPart;
            ASSERT_LE(start + search, c.counts.size());
            uint32_t sum = 0;
            for (uint32_t i = 0; i < d.partCount; ++i) sum += c.counts[start + i];
            EXPECT_EQ(3 * sum, d.indexCount);
        }
        for (uint32_t i = s.parts.size(); i < c.counts.size(); ++i) EXPECT_EQ(c.counts[i], 0u);
    }
    EXPECT_THROW(buildPartTriangleCounts(s, 0), std::invalid_argument);
}

TEST(PartData, RunningOffsetsBracketEveryPart) {
    Scene s = mixedScene();
    PartTriangleOffsets o = buildPartTriangleOffsets(s);
    EXPECT_EQ(o.offsets.size(), s.parts.size() + s.geometries.size());
    EXPECT_EQ(idDataBytes(s, 16).partTriangleOffsets, 4 * o.offsets.size());
    for (uint32_t g = 0; g < s.geometries.size(); ++g) {
        const uint32_t* run = &o.offsets[o.geometryOffsets[g]];
        EXPECT_EQ(run[0], 0u);
        EXPECT_EQ(run[s.geometries[g].partCount], s.geometries[g].triangleCount);
        for (uint32_t p = 0; p < s.geometries[g].partCount; ++p)
            EXPECT_EQ(run[p + 1] - run[p], s.parts[s.geometries[g].firstPart + p].triangleCount);
    }
}

TEST(PartData, DrawListsCoverEveryTriangleOnce) {
    Scene s = mixedScene();
    const uint32_t perObjectParts[] = {7, 300, 7};
    auto perPart = drawsPerPart(s);
    auto perObject = drawsPerObject(s);
    auto perBatch = drawsPerBatch(s, 16);
    EXPECT_EQ(perPart.size(), s.uniquePartCount());
    EXPECT_EQ(perObject.size(), s.objects.size());
    EXPECT_EQ(perBatch.size(), 1u + (300 + 15) / 16 + 1u);
    for (const auto* list : {&perPart, &perObject, &perBatch}) {
        uint64_t indices = 0;
        std::vector<uint32_t> parts(s.objects.size(), 0);
        for (const DrawRange& d : *list) {
            const Geometry& g = s.geometries[s.objects[d.object].geometry];
            EXPECT_EQ(d.firstPart, parts[d.object]); // consecutive, no gaps or overlaps
            parts[d.object] += d.partCount;
            EXPECT_EQ(d.vertexOffset, int32_t(g.firstVertex));
            EXPECT_EQ(d.firstIndex,
                      g.firstIndex + 3 * s.parts[g.firstPart + d.firstPart].firstTriangle);
            indices += d.indexCount;
        }
        for (uint32_t o = 0; o < s.objects.size(); ++o) EXPECT_EQ(parts[o], perObjectParts[o]);
        EXPECT_EQ(indices, 3 * s.drawnTriangleCount());
    }
}

TEST(Copies, ReplicateSharesGeometryAndGivesNewIds) {
    Scene s = makeAssembly();
    Scene three = replicate(s, 3);
    EXPECT_EQ(three.geometries.size(), s.geometries.size());
    EXPECT_EQ(three.vertices.size(), s.vertices.size());
    EXPECT_EQ(three.objects.size(), 3 * s.objects.size());
    EXPECT_EQ(three.uniquePartCount(), 3 * s.uniquePartCount());
    validate(three);
    const Bounds b = s.bounds();
    for (uint32_t copy = 0; copy < 3; ++copy)
        for (uint32_t o = 0; o < s.objects.size(); ++o) {
            const Object& a = s.objects[o];
            const Object& c = three.objects[copy * s.objects.size() + o];
            EXPECT_EQ(c.geometry, a.geometry);
            EXPECT_EQ(c.uniquePartOffset, a.uniquePartOffset + copy * s.uniquePartCount());
            glm::vec3 shift = glm::vec3(c.world[3]) - glm::vec3(a.world[3]);
            EXPECT_FLOAT_EQ(shift.z, 0.0f);
            if (copy == 1) {
                EXPECT_NEAR(shift.x, (b.max.x - b.min.x) * 1.1f, 1e-4f);
            }
        }
    // Copies do not overlap: their bounds are disjoint along the grid.
    Scene second = three;
    second.objects.assign(three.objects.begin() + s.objects.size(),
                          three.objects.begin() + 2 * s.objects.size());
    EXPECT_GT(second.bounds().min.x, b.max.x);
    EXPECT_THROW(replicate(s, 0), std::invalid_argument);
}
