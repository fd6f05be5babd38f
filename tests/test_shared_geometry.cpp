// test_shared_geometry.cpp - copies of a scene share its geometry (scene/shared_array.h): model
// copies and the exploded view hold the same vertices, indices, parts, geometries and
// materials as the scene they came from, and a copy that changes one gets its own.
#include <gtest/gtest.h>

#include <utility>

#include "scene/copies.h"
#include "scene/explode.h"
#include "scene/procedural/generator.h"

using namespace scene;

namespace {

// Whether `a` and `b` hold the very same heavy arrays (not equal ones: the same memory).
void expectSharedGeometry(const Scene& a, const Scene& b) {
    EXPECT_EQ(a.vertices.data(), b.vertices.data());
    EXPECT_EQ(a.indices.data(), b.indices.data());
    EXPECT_EQ(a.parts.data(), b.parts.data());
    EXPECT_EQ(a.geometries.data(), b.geometries.data());
    EXPECT_EQ(a.materials.data(), b.materials.data());
    EXPECT_TRUE(a.vertices.shares(b.vertices));
    EXPECT_TRUE(a.geometries.shares(b.geometries));
}

} // namespace

TEST(SharedGeometry, CopiesShareEveryArrayButTheObjects) {
    const Scene rest = makeAssembly();
    const Scene many = replicate(rest, 16);
    expectSharedGeometry(rest, many);
    EXPECT_EQ(many.objects.size(), 16 * rest.objects.size());
    validate(many);

    const Scene exploded = explodedScene(many, 0.6f);
    expectSharedGeometry(many, exploded);
    EXPECT_NE(exploded.objects.data(), many.objects.data());
    EXPECT_GT(exploded.bounds().radius(), many.bounds().radius()); // the placements moved
}

TEST(SharedGeometry, ReadingACopyNeverCopiesItsArrays) {
    Scene rest = makeAssembly();
    Scene copy = rest; // both non-const: only what the reads below take decides
    const Scene& reader = copy;
    double sum = 0.0;
    for (const Vertex& v : reader.vertices) sum += v.position.x;
    for (const Geometry& g : reader.geometries) sum += g.partCount;
    sum += reader.indices[0] + reader.parts.back().triangleCount + reader.bounds().radius();
    sum += describePart(reader, 0)->triangleCount;
    validate(reader);
    EXPECT_GT(sum, 0.0);
    expectSharedGeometry(rest, copy);
}

TEST(SharedGeometry, AChangeDetachesOnlyTheCopyThatMadeIt) {
    const Scene rest = makeAssembly();
    Scene copy = rest;
    const Scene& read = copy; // reads through it take nothing of their own
    const Vertex* restVertices = rest.vertices.data();
    const size_t count = rest.vertices.size();

    copy.vertices[0].position.x += 1.0f; // non-const access: the copy gets its own vertices
    EXPECT_NE(read.vertices.data(), restVertices);
    EXPECT_EQ(rest.vertices.data(), restVertices);
    EXPECT_EQ(read.vertices[0].position.x, rest.vertices[0].position.x + 1.0f);
    // The other arrays stay shared until they change too; even a non-const read detaches.
    EXPECT_EQ(read.indices.data(), rest.indices.data());
    copy.geometries.push_back(read.geometries[0]);
    EXPECT_NE(read.geometries.data(), rest.geometries.data());
    EXPECT_EQ(rest.geometries.size() + 1, read.geometries.size());
    EXPECT_EQ(rest.vertices.size(), count);
    EXPECT_NE(copy.indices.data(), rest.indices.data());
    // A copy that owns its array alone changes it in place.
    const Vertex* own = read.vertices.data();
    copy.vertices[1].position.y = 7.0f;
    EXPECT_EQ(read.vertices.data(), own);
}

TEST(SharedGeometry, ClearInsertAndEraseOnASharedArray) {
    SharedArray<int> a = std::vector<int>{1, 2, 3, 4};
    SharedArray<int> b = a;
    b.clear(); // emptied without copying, and without emptying `a`
    EXPECT_TRUE(b.empty());
    EXPECT_EQ(a, (std::vector<int>{1, 2, 3, 4}));

    SharedArray<int> c = a;
    // An iterator taken from the shared buffer still says where, once `c` has its own.
    const auto at = std::as_const(c).begin() + 2;
    c.insert(at, {9, 9});
    EXPECT_EQ(c, (std::vector<int>{1, 2, 9, 9, 3, 4}));
    SharedArray<int> d = a;
    d.erase(std::as_const(d).begin() + 1);
    EXPECT_EQ(d, (std::vector<int>{1, 3, 4}));
    EXPECT_EQ(a, (std::vector<int>{1, 2, 3, 4}));

    // take() moves an array that is not shared, and copies one that is.
    const int* buffer = d.data();
    std::vector<int> taken = d.take();
    EXPECT_EQ(taken.data(), buffer);
    EXPECT_TRUE(d.empty());
    SharedArray<int> e = a;
    EXPECT_EQ(e.take(), a.get());
    EXPECT_EQ(a.size(), 4u);
}
