// test_scene.cpp - the scene model: unique part IDs, part ranges, validation, generators.
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include "scene/procedural/generator.h"
#include "scene/mesh_builder.h"

using namespace scene;

TEST(Scene, BoxHasSixPartsWithTheirOwnVertices) {
    Scene s;
    MeshBuilder mb;
    mb.addBox({0, 0, 0}, {1, 2, 3});
    uint32_t g = mb.finish(s, "box");
    addMaterial(s, "m", {1, 1, 1, 1});
    addObject(s, g, 0, glm::mat4(1));
    validate(s);
    const Geometry& geo = s.geometries[g];
    EXPECT_EQ(geo.partCount, 6u);
    EXPECT_EQ(geo.triangleCount, 12u);
    EXPECT_EQ(geo.vertexCount, 24u); // 4 per face: faces share no vertex, so edges stay hard
    for (uint32_t p = 0; p < geo.partCount; ++p) {
        const Part& part = s.parts[geo.firstPart + p];
        EXPECT_EQ(part.firstTriangle, 2 * p);
        EXPECT_EQ(part.triangleCount, 2u);
        for (uint32_t i = 0; i < 6; ++i) {
            uint32_t v = s.indices[geo.firstIndex + 3 * part.firstTriangle + i];
            EXPECT_GE(v, 4 * p);
            EXPECT_LT(v, 4 * p + 4);
        }
    }
    Bounds b = s.bounds();
    EXPECT_FLOAT_EQ(b.min.z, -1.5f);
    EXPECT_FLOAT_EQ(b.max.y, 1.0f);
}

TEST(Scene, UniquePartIdsFollowObjectsAndLocateBack) {
    Scene s = makeAssembly();
    uint32_t expectedOffset = 0;
    for (const Object& o : s.objects) {
        EXPECT_EQ(o.uniquePartOffset, expectedOffset);
        expectedOffset += s.geometries[o.geometry].partCount;
    }
    EXPECT_EQ(s.uniquePartCount(), expectedOffset);
    for (uint32_t id = 0; id < s.uniquePartCount(); ++id) {
        auto ref = s.locate(id);
        ASSERT_TRUE(ref) << id;
        EXPECT_EQ(s.objects[ref->object].uniquePartOffset + ref->localPart, id);
        EXPECT_LT(ref->localPart, s.geometries[s.objects[ref->object].geometry].partCount);
    }
    EXPECT_FALSE(s.locate(s.uniquePartCount()));
    EXPECT_FALSE(s.locate(gpu::BACKGROUND_ID));
}

TEST(Scene, AssemblyInstancesGeometries) {
    Scene s = makeAssembly();
    std::vector<uint32_t> uses(s.geometries.size(), 0);
    for (const Object& o : s.objects) uses[o.geometry]++;
    uint32_t bolt = 0;
    for (uint32_t g = 0; g < s.geometries.size(); ++g)
        if (s.geometries[g].name == "bolt M10") bolt = g;
    EXPECT_EQ(uses[bolt], 24u);
    EXPECT_EQ(s.geometries[bolt].partCount, 11u); // 6 flanks + 2 caps, mantle + 2 caps
    EXPECT_EQ(s.drawnTriangleCount(), [&] {
        uint64_t t = 0;
        for (const Object& o : s.objects) t += s.geometries[o.geometry].triangleCount;
        return t;
    }());
}

TEST(Scene, ValidateNamesInconsistencies) {
    Scene s = makeTiles();
    validate(s);
    Scene badIndex = s;
    badIndex.indices[0] = 999;
    EXPECT_THROW(validate(badIndex), std::invalid_argument);
    Scene gap = s;
    gap.parts[1].firstTriangle += 1;
    EXPECT_THROW(validate(gap), std::invalid_argument);
    Scene overlap = s;
    overlap.objects[1].uniquePartOffset = 0;
    EXPECT_THROW(validate(overlap), std::invalid_argument);
    Scene missing = s;
    missing.objects[0].material = 7;
    try {
        validate(missing);
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("object 0"), std::string::npos) << e.what();
    }
}

TEST(Scene, TilesLayoutIsAsDocumented) {
    Scene s = makeTiles();
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_EQ(s.uniquePartCount(), 25u); // 2 x 12 tiles + the back plate
    EXPECT_EQ(s.objects[2].uniquePartOffset, 24u);
    EXPECT_EQ(sceneNames().size(), 2u);
    EXPECT_THROW(makeScene("nope"), std::invalid_argument);
}

TEST(Scene, AssemblyObjectsHaveNamesAndDescribePartReturnsThem) {
    const Scene s = makeAssembly();
    ASSERT_EQ(s.objects.size(), 32u);
    EXPECT_EQ(s.objects[0].path, "assembly/base plate");
    EXPECT_EQ(s.objects[1].path, "assembly/top plate");
    EXPECT_EQ(s.objects[5].path, "assembly/column #4");
    EXPECT_EQ(s.objects[29].path, "assembly/top plate/bolt M10 #24");
    EXPECT_EQ(s.objects[31].path, "assembly/top plate/angle bracket #2");
    // The last part of the first bolt names the bolt's object.
    const Object& bolt = s.objects[6];
    const auto info =
        describePart(s, bolt.uniquePartOffset + s.geometries[bolt.geometry].partCount - 1);
    ASSERT_TRUE(info);
    EXPECT_EQ(info->object, 6u);
    EXPECT_EQ(info->name, "bolt M10 #1");
    EXPECT_EQ(info->path, "assembly/top plate/bolt M10 #1");
    const Scene tiles = makeTiles();
    ASSERT_EQ(tiles.objects.size(), 3u);
    EXPECT_EQ(describePart(tiles, 12)->name, "tile sheet #2"); // 12 tiles a sheet
    EXPECT_EQ(describePart(tiles, 12)->path, "tiles/tile sheet #2");
    EXPECT_EQ(describePart(tiles, 24)->path, "tiles/back plate");
}

TEST(Scene, NameCounterNumbersEachKindFromOne) {
    NameCounter names;
    EXPECT_EQ(names.next("bolt M10"), "bolt M10 #1");
    EXPECT_EQ(names.next("nut M10"), "nut M10 #1");
    EXPECT_EQ(names.next("bolt M10"), "bolt M10 #2");
    EXPECT_EQ(joinPath("", "car"), "car");
    EXPECT_EQ(joinPath("car/chassis", "floor pan"), "car/chassis/floor pan");
}
