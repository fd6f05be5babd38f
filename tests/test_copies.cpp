// test_copies.cpp - --copy-axes: copies laid out on a grid over 1, 2 or 3 chosen axes; the
// bounds grow only along those, and unique part IDs stay unique and contiguous.
#include <gtest/gtest.h>

#include <set>

#include "scene/copies.h"
#include "scene/procedural/generator.h"

using namespace scene;

TEST(CopyAxes, ParsesSetsOfXyzAndRefusesTheRest) {
    EXPECT_EQ(parseCopyAxes("x"), uint32_t(COPY_X));
    EXPECT_EQ(parseCopyAxes("xy"), COPY_XY);
    EXPECT_EQ(parseCopyAxes("zx"), uint32_t(COPY_X | COPY_Z));
    EXPECT_EQ(parseCopyAxes("xyz"), uint32_t(COPY_X | COPY_Y | COPY_Z));
    for (const char* bad : {"", "w", "xx", "xyzx", "X", "x y"})
        EXPECT_THROW(parseCopyAxes(bad), std::invalid_argument) << bad;
    EXPECT_THROW(replicate(makeAssembly(), 2, 0), std::invalid_argument);
}

TEST(CopyAxes, BoundsGrowOnlyAlongTheChosenAxesAndIdsStayUniqueAndContiguous) {
    const Scene s = makeAssembly();
    const Bounds b = s.bounds();
    for (const char* text : {"x", "y", "z", "xy", "xz", "yz", "xyz"})
        for (uint32_t copies : {2u, 5u, 8u, 27u}) {
            const uint32_t axes = parseCopyAxes(text);
            const Scene many = replicate(s, copies, axes);
            validate(many);
            ASSERT_EQ(many.objects.size(), copies * s.objects.size());
            const Bounds m = many.bounds();
            for (int a = 0; a < 3; ++a) {
                const bool chosen = axes & (1u << a);
                EXPECT_NEAR(m.min[a], b.min[a], 1e-4f) << text << " " << copies << " axis " << a;
                // 2 copies on a 2x2 grid fill one row only; from 8 on, every chosen axis has
                // copies further out (2x2x2, 3x3, 8x1).
                if (chosen && copies >= 8)
                    EXPECT_GT(m.max[a], b.max[a]) << text << " " << copies << " " << a;
                else if (chosen)
                    EXPECT_GE(m.max[a], b.max[a]) << text << " " << copies << " " << a;
                else
                    EXPECT_NEAR(m.max[a], b.max[a], 1e-4f) << text << " " << copies << " " << a;
            }
            // Every ID from 0 to copies * parts - 1 exactly once, copy after copy.
            std::set<uint32_t> ids;
            uint32_t next = 0;
            for (const Object& o : many.objects) {
                EXPECT_EQ(o.uniquePartOffset, next);
                const uint32_t parts = many.geometries[o.geometry].partCount;
                for (uint32_t p = 0; p < parts; ++p) EXPECT_TRUE(ids.insert(next + p).second);
                next += parts;
            }
            EXPECT_EQ(ids.size(), size_t(copies) * s.uniquePartCount());
            EXPECT_EQ(many.uniquePartCount(), copies * s.uniquePartCount());
        }
}

TEST(CopyAxes, GridIsAsCompactAsItCanBe) {
    const Scene s = makeAssembly();
    const glm::dvec3 step = (s.bounds().max - s.bounds().min) * 1.1;
    // 27 copies over xyz: a 3x3x3 block, so the last copy sits two steps out on each axis.
    const Scene cube = replicate(s, 27, parseCopyAxes("xyz"));
    const glm::vec3 last =
        glm::vec3(cube.objects.back().world[3]) - glm::vec3(s.objects.back().world[3]);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(last[a], 2.0f * step[a], 1e-3f) << a;
    // The default (xy) is the grid of before: copy 3 of 4 at column 1, row 1.
    const Scene grid = replicate(s, 4);
    const glm::vec3 third =
        glm::vec3(grid.objects[3 * s.objects.size()].world[3]) - glm::vec3(s.objects[0].world[3]);
    EXPECT_NEAR(third.x, step.x, 1e-3f);
    EXPECT_NEAR(third.y, step.y, 1e-3f);
    EXPECT_NEAR(third.z, 0.0f, 1e-6f);
}

TEST(CopyAxes, CopiesKeepNamesAndPrefixTheirPaths) {
    const Scene s = makeAssembly();
    const Scene many = replicate(s, 5, parseCopyAxes("xy"));
    const size_t n = s.objects.size();
    std::set<std::string> paths;
    for (size_t i = 0; i < many.objects.size(); ++i) {
        const Object& original = s.objects[i % n];
        EXPECT_EQ(many.objects[i].name, original.name) << i;
        const size_t copy = i / n;
        EXPECT_EQ(many.objects[i].path,
                  copy ? "copy " + std::to_string(copy) + "/" + original.path : original.path)
            << i;
        EXPECT_TRUE(paths.insert(many.objects[i].path).second) << many.objects[i].path;
    }
    EXPECT_EQ(many.objects[0].path, "assembly/base plate");
    EXPECT_EQ(many.objects[n].path, "copy 1/assembly/base plate");
    EXPECT_EQ(many.objects[4 * n + 6].path, "copy 4/assembly/top plate/bolt M10 #1");
}
