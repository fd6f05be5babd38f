// test_empty_parts.cpp - parts without triangles (scene/scene.h Part::empty) in the scene model
// and what is derived from it, on a small scene built here and the same scene with empty parts
// at the start, middle and end of every geometry and an object of only empty parts
// (empty_parts_scene.h): validation, IDs, bounds, clusters, draw lists and ID data, derived
// geometry, ray casts, the assembly tree, X-ray's draws and the exploded view.
#include <gtest/gtest.h>

#include "empty_parts_scene.h"
#include "render/draw_list.h"
#include "render/xray.h"
#include "scene/assembly_tree.h"
#include "scene/bounds.h"
#include "scene/camera.h"
#include "scene/explode.h"
#include "scene/raycast.h"
#include "test_support.h"

using namespace scene;
using testing_support::kEmptyPart;
using testing_support::WithEmptyParts;

namespace {

const WithEmptyParts& emptyScene() {
    static const WithEmptyParts made =
        testing_support::withEmptyParts(testing_support::fourObjectScene());
    return made;
}

// The plain scene's ID of each part of the scene with empty parts (kEmptyPart for those).
uint32_t plainOf(uint32_t id) {
    return emptyScene().plainId.at(id);
}

void expectSameBox(const Bounds& a, const Bounds& b) {
    EXPECT_EQ(a.min, b.min);
    EXPECT_EQ(a.max, b.max);
}

} // namespace

TEST(EmptyParts, ValidateAcceptsThemAndStillNamesInconsistencies) {
    const Scene& s = emptyScene().scene;
    EXPECT_NO_THROW(validate(s));
    const Geometry& box = s.geometries[0];
    ASSERT_TRUE(s.parts[box.firstPart].empty());
    // An empty part must start where the triangles before it end.
    Scene moved = s;
    moved.parts[box.firstPart + 4].firstTriangle += 1; // the middle one, after 3 parts
    EXPECT_THROW(validate(moved), std::invalid_argument);
    Scene lastMoved = s;
    lastMoved.parts[box.firstPart + box.partCount - 1].firstTriangle = 0;
    EXPECT_THROW(validate(lastMoved), std::invalid_argument);
    // A part that lost its triangles leaves the geometry's uncovered.
    Scene lost = s;
    lost.parts[box.firstPart + 1].triangleCount = 0;
    EXPECT_THROW(validate(lost), std::invalid_argument);
    // A geometry still needs a part, and one without triangles has no vertices.
    Scene noParts = s;
    noParts.geometries.back().partCount = 0;
    EXPECT_THROW(validate(noParts), std::invalid_argument);
    Scene strayVertices = s;
    strayVertices.geometries.back().vertexCount = 4;
    strayVertices.geometries.back().firstVertex = 0;
    EXPECT_THROW(validate(strayVertices), std::invalid_argument);
}

TEST(EmptyParts, KeepTheirIdsAndAreDescribedWithNoTriangles) {
    const WithEmptyParts& e = emptyScene();
    const Scene& s = e.scene;
    const Scene plain = testing_support::fourObjectScene();
    const PartSet empty = emptyParts(s);
    // 3 empty parts in each of four objects (box, turned, box: start, middle, end; the square:
    // start and end) and the 3 of the object not meshed.
    EXPECT_EQ(empty.size(), 3u + 3u + 2u + 3u + 3u);
    EXPECT_EQ(s.uniquePartCount(), plain.uniquePartCount() + empty.size());
    EXPECT_TRUE(emptyParts(plain).empty());
    for (uint32_t id = 0; id < s.uniquePartCount(); ++id) {
        const auto info = describePart(s, id);
        ASSERT_TRUE(info) << id;
        EXPECT_EQ(empty.contains(id), plainOf(id) == kEmptyPart) << id;
        if (plainOf(id) == kEmptyPart) {
            EXPECT_EQ(info->triangleCount, 0u) << id;
            continue;
        }
        const auto was = describePart(plain, plainOf(id));
        EXPECT_EQ(info->triangleCount, was->triangleCount) << id;
        EXPECT_EQ(info->path, was->path) << id;
        EXPECT_EQ(info->face, was->face) << id;
    }
    // The turned part's empty first part keeps its face; the object not meshed its name.
    const uint32_t turned = s.objects[2].uniquePartOffset;
    EXPECT_EQ(describePart(s, turned)->face, testing_support::kEmptyPartFace);
    EXPECT_EQ(describePart(s, turned + 1)->face, 10u);
    EXPECT_EQ(describePart(s, s.objects[e.emptyObject].uniquePartOffset + 2)->name, "not meshed");
}

TEST(EmptyParts, BoundsClustersAndFitsPassThemBy) {
    const Scene& s = emptyScene().scene;
    const Scene plain = testing_support::fourObjectScene();
    expectSameBox(s.bounds(), plain.bounds());
    const std::vector<Bounds> boxes = partBounds(s), plainBoxes = partBounds(plain);
    const Clusters clusters = partClusters(s, 16), plainClusters = partClusters(plain, 16);
    // Clusters come in Scene::parts order: the same runs, with the parts' new local numbers.
    ASSERT_EQ(clusters.boxes.size(), plainClusters.boxes.size());
    for (size_t c = 0; c < clusters.boxes.size(); ++c) {
        expectSameBox(clusters.boxes[c], plainClusters.boxes[c]);
        EXPECT_FALSE(isEmpty(clusters.boxes[c]));
        EXPECT_EQ(clusters.firstTriangle[c], plainClusters.firstTriangle[c]);
        EXPECT_EQ(clusters.triangleCount[c], plainClusters.triangleCount[c]);
    }
    for (const Object& o : s.objects) {
        const Geometry& g = s.geometries[o.geometry];
        for (uint32_t p = 0; p < g.partCount; ++p) {
            const uint32_t id = plainOf(o.uniquePartOffset + p), part = g.firstPart + p;
            if (id == kEmptyPart) {
                EXPECT_TRUE(isEmpty(boxes[part]));
                EXPECT_EQ(clusters.first[part + 1], clusters.first[part]);
                continue;
            }
            const auto ref = plain.locate(id);
            const uint32_t plainPart = plain.geometries[o.geometry].firstPart + ref->localPart;
            expectSameBox(boxes[part], plainBoxes[plainPart]);
            for (uint32_t c = clusters.first[part]; c < clusters.first[part + 1]; ++c)
                EXPECT_EQ(clusters.localPart[c], p);
        }
    }
    // A fit to empty parts alone finds nothing to fit; with them, what the others give.
    const PartSet empty = emptyParts(s);
    EXPECT_TRUE(isEmpty(partsWorldBounds(s, empty)));
    PartSet all = empty;
    all.invert();
    PartSet plainAll(plain.uniquePartCount());
    plainAll.invert();
    all.insertAll(empty);
    expectSameBox(partsWorldBounds(s, all), partsWorldBounds(plain, plainAll));
    // Nothing meshed at all: the scene's box is a point, which cameras fit.
    Scene none = s;
    for (Object& o : none.objects) o.geometry = none.objects[emptyScene().emptyObject].geometry;
    expectSameBox(none.bounds(), Bounds{});
}

// Every technique's draws, in every mode: the plain scene's draws and triangles, none of them
// of empty parts alone; and its ID data names the parts the plain scene's names.
TEST(EmptyParts, DrawListsDrawWhatThePlainSceneDraws) {
    const Scene& s = emptyScene().scene;
    const Scene plain = testing_support::fourObjectScene();
    for (const render::Technique& t : render::techniques())
        for (const render::DrawMode& m : render::drawModes()) {
            render::PipelineKey key;
            key.technique = &t;
            key.mode = &m;
            key.searchBatch = 4;
            const render::DerivedGeometry derived = render::buildDerivedGeometry(s, t);
            const render::DerivedGeometry plainDerived = render::buildDerivedGeometry(plain, t);
            const render::DrawList list = render::buildDrawList(s, key, {}, derived.view());
            const render::DrawList plainList =
                render::buildDrawList(plain, key, {}, plainDerived.view());
            const auto stats = render::statsFor(list, m, derived.view());
            const auto plainStats = render::statsFor(plainList, m, plainDerived.view());
            EXPECT_EQ(stats.draws, plainStats.draws) << t.name << " " << m.name;
            EXPECT_EQ(stats.triangles, plainStats.triangles) << t.name << " " << m.name;
            for (const render::DrawItem& d : list.ranges) {
                EXPECT_GT(d.indexCount, 0u) << t.name;
                const Geometry& g = s.geometries[d.geometry];
                if (t.split == render::DrawSplit::PerObject) continue; // whole geometries
                EXPECT_FALSE(s.parts[g.firstPart + d.firstPart].empty()) << t.name;
                EXPECT_FALSE(s.parts[g.firstPart + d.firstPart + d.partCount - 1].empty());
            }
        }
}

TEST(EmptyParts, IdDataAndDerivedGeometryNameTheSameParts) {
    const WithEmptyParts& e = emptyScene();
    const Scene& s = e.scene;
    const Scene plain = testing_support::fourObjectScene();
    const TrianglePartIds ids = buildTrianglePartIds(s);
    const PartTriangleOffsets offsets = buildPartTriangleOffsets(s);
    const PartVertices vertices = buildPartVertices(s), plainVertices = buildPartVertices(plain);
    const Meshlets meshlets = buildMeshlets(s, &vertices);
    const Meshlets plainMeshlets = buildMeshlets(plain, &plainVertices);
    EXPECT_EQ(vertices.indices, plainVertices.indices);
    EXPECT_EQ(meshlets.vertices, plainMeshlets.vertices);
    EXPECT_EQ(meshlets.sourceTriangle, plainMeshlets.sourceTriangle);
    EXPECT_EQ(meshlets.meshletCount.back(), 0u); // the geometry not meshed
    for (uint32_t o = 0; o < s.objects.size(); ++o) {
        if (o == e.emptyObject) continue;
        const uint32_t gi = s.objects[o].geometry;
        const Geometry& g = s.geometries[gi];
        // The same part, named in either scene's IDs.
        const uint32_t offset = s.objects[o].uniquePartOffset;
        const uint32_t plainOffset = plain.objects[o < e.emptyObject ? o : o - 1].uniquePartOffset;
        auto same = [&](uint32_t local, uint32_t plainLocal) {
            return plainOf(offset + local) == plainOffset + plainLocal;
        };
        const std::vector<uint32_t> plainParts = trianglePartsOf(plain, gi);
        const uint32_t* running = &offsets.offsets[offsets.geometryOffsets[gi]];
        for (uint32_t t = 0; t < g.triangleCount; ++t) {
            const uint32_t part = ids.partOf(gi, t);
            EXPECT_TRUE(same(part, plainParts[t])) << "object " << o << " triangle " << t;
            // What the offset searches find: the last part starting at or before t.
            uint32_t last = 0;
            while (last + 1 < g.partCount && running[last + 1] <= t) ++last;
            EXPECT_EQ(last, part) << "object " << o << " triangle " << t;
            const uint32_t lead = vertices.indices[g.firstIndex + 3 * t];
            EXPECT_EQ(vertices.localPart[vertices.firstVertex[gi] + lead], part);
            const uint32_t m = meshlets.geometryFirstTriangle[gi] + t;
            EXPECT_TRUE(same(meshlets.localPart[m], plainMeshlets.localPart[m]));
        }
    }
}

TEST(EmptyParts, RaysHitWhatThePlainSceneShowsAndNeverAnEmptyPart) {
    const Scene& s = emptyScene().scene;
    const Scene plain = testing_support::fourObjectScene();
    const RayCaster caster(s), plainCaster(plain);
    const glm::dvec2 size(64, 40);
    const Camera camera =
        fitCamera(plain.bounds(), {0.1, -1.0, 0.8}, {0, 0, 1}, glm::radians(45.0f), 1.6);
    const glm::dmat4 viewProj = camera.viewProjection(size.x / size.y);
    size_t hits = 0;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 64; ++x) {
            const Ray ray = pixelRay(viewProj, size, {x + 0.5, y + 0.5});
            const auto hit = caster.cast(ray), plainHit = plainCaster.cast(ray);
            ASSERT_EQ(bool(hit), bool(plainHit)) << x << "," << y;
            if (!hit) continue;
            ++hits;
            EXPECT_EQ(plainOf(hit->uniquePartId), plainHit->uniquePartId) << x << "," << y;
            EXPECT_EQ(hit->t, plainHit->t);
        }
    EXPECT_GT(hits, 100u);
}

TEST(EmptyParts, TreeSelectionsAndXrayHoldThemButDrawNone) {
    const WithEmptyParts& e = emptyScene();
    const Scene& s = e.scene;
    const Scene plain = testing_support::fourObjectScene();
    // The object not meshed is a node of its own with its three IDs.
    const std::vector<TreeRow> rows = treeRows(assemblyTree(s, "root"));
    size_t found = 0;
    for (const TreeRow& row : rows)
        if (row.object == e.emptyObject) {
            ++found;
            const PartRanges own = {{s.objects[e.emptyObject].uniquePartOffset, 3}};
            EXPECT_EQ(row.parts, own);
        }
    EXPECT_EQ(found, 1u);
    // A selection of the whole box takes its empty parts too; X-ray draws its triangles in one.
    const uint32_t box = s.objects[0].uniquePartOffset, boxParts = s.geometries[0].partCount;
    const PartSet boxSet = partSetOf(partsAround(s, box + 1, 1), s.uniquePartCount());
    EXPECT_EQ(boxSet.countIn(box, boxParts), boxParts);
    const auto draws = render::translucentDraws(s, boxSet);
    ASSERT_EQ(draws.size(), 1u);
    EXPECT_EQ(draws[0].indexCount, 3 * s.geometries[0].triangleCount);
    PartSet everything(s.uniquePartCount());
    everything.invert();
    PartSet plainEverything(plain.uniquePartCount());
    plainEverything.invert();
    EXPECT_EQ(render::translucentDraws(s, everything).size(),
              render::translucentDraws(plain, plainEverything).size());
    EXPECT_TRUE(render::translucentDraws(s, emptyParts(s)).empty());
    // The exploded view moves every object as without them; the one not meshed stays put.
    const std::vector<glm::vec4> offsets = explodeOffsets(s), plainOffsets = explodeOffsets(plain);
    for (uint32_t o = 0; o < plain.objects.size(); ++o)
        EXPECT_EQ(offsets[o < e.emptyObject ? o : o + 1], plainOffsets[o]) << o;
}
