// test_raster_rules.cpp - the rules a compute rasterizer must follow to draw the hardware's
// ID image (issue 46), written down as tests/cpu_raster.h and checked against lavapipe's
// rasterizer with validation on: small triangles, each its own part at its own depth, through
// the tests' flat camera at 1x (the pixel centre) and 4x MSAA (the ID image is sample 0's, at
// Vulkan's standard position). With corners on an eighth-pixel grid (exact on any subpixel
// grid, and many edges through sample positions) every pixel agrees; with corners anywhere,
// a pixel may differ only where its sample lies within one subpixel step of an edge (the
// driver's rounding of the corners), and the count of those is printed. The bottom-right rule
// in place of the top-left one disagrees: the scenes test the rule.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

#include "app/offscreen.h"
#include "cpu_raster.h"
#include "render/technique.h"
#include "scene/mesh_builder.h"
#include "test_support.h"

namespace {

using testing_support::CpuRaster;
using testing_support::RasterRules;
using testing_support::RasterTriangle;

constexpr uint32_t W = 96, H = 64;
constexpr uint32_t NONE = gpu::BACKGROUND_ID;

// `count` triangles within a few pixels each, scattered over the image, corners on a grid of
// 1/`grid` pixel (0: anywhere), at depths that never tie, drawn in order.
std::vector<RasterTriangle> randomTriangles(uint32_t count, uint32_t grid, uint32_t seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> centre(2.0, double(W) - 2.0), spread(-4.0, 4.0);
    // Depths in a shuffled order, so that a later triangle is as often nearer as not.
    std::vector<uint32_t> rank(count);
    for (uint32_t i = 0; i < count; ++i) rank[i] = i;
    std::shuffle(rank.begin(), rank.end(), random);
    std::vector<RasterTriangle> triangles;
    for (uint32_t i = 0; i < count; ++i) {
        RasterTriangle t{};
        const glm::dvec2 c(centre(random), centre(random) * H / W);
        for (glm::dvec2& corner : t.corner) {
            corner = c + glm::dvec2(spread(random), spread(random));
            if (grid) corner = glm::round(corner * double(grid)) / double(grid);
            corner = glm::clamp(corner, glm::dvec2(0.0), glm::dvec2(W, H));
        }
        // The flat camera's depth is 1 - z, z in [0.1, 0.9): exact in float, never tied.
        t.depth = 1.0 - (0.1 + 0.8 * double(rank[i]) / double(count));
        t.id = i;
        triangles.push_back(t);
    }
    return triangles;
}

// One object, a part per triangle, in the flat camera's clip space (x = 2 px / W - 1, y
// likewise, z = 1 - depth).
scene::Scene sceneOf(const std::vector<RasterTriangle>& triangles) {
    scene::Scene s;
    const uint32_t grey = scene::addMaterial(s, "grey", {0.5f, 0.5f, 0.5f, 1});
    scene::MeshBuilder mb;
    for (const RasterTriangle& t : triangles) {
        glm::vec3 corners[3];
        for (int k = 0; k < 3; ++k)
            corners[k] = glm::vec3(float(2.0 * t.corner[k].x / W - 1.0),
                                   float(2.0 * t.corner[k].y / H - 1.0), float(1.0 - t.depth));
        mb.addFlatFace(corners);
    }
    scene::addObject(s, mb.finish(s, "triangles"), grey, glm::mat4(1.0f), "triangles");
    scene::validate(s);
    return s;
}

struct Drawn {
    std::vector<uint32_t> ids;
    uint32_t subpixelBits = 0;
};

// The hardware's ID image: vertex-fs in push mode, culling off.
Drawn draw(const scene::Scene& s, uint32_t msaa) {
    app::Options o = testing_support::headlessOptions(W, H);
    o.render = testing_support::settingsFor(*render::findTechnique("vertex-fs"),
                                            render::defaultDrawMode());
    o.render.culling.mode = render::CullMode::Off;
    o.render.pipeline.msaa = msaa;
    vk::Instance instance({true, {}, false});
    Drawn drawn;
    {
        app::Offscreen rig(instance, o);
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(rig.device.physical(), &props);
        drawn.subpixelBits = props.limits.subPixelPrecisionBits;
        rig.renderer.setScene(s, o.render);
        uint64_t frame = 0;
        drawn.ids = testing_support::renderIds(rig, frame);
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
    return drawn;
}

glm::dvec2 sampleZero(uint32_t msaa) {
    return msaa == 4 ? glm::dvec2(0.375, 0.125) : glm::dvec2(0.5);
}

// Pixels where `cpu` and the hardware differ, and of those the ones a subpixel step explains:
// the sample lies that close to an edge of the triangle either one shows.
struct Differences {
    size_t all = 0, explained = 0;
};
Differences compare(const std::vector<RasterTriangle>& triangles, const std::vector<uint32_t>& cpu,
                    const std::vector<uint32_t>& gpu, uint32_t msaa, const RasterRules& rules) {
    Differences d;
    for (uint32_t y = 0; y < H; ++y)
        for (uint32_t x = 0; x < W; ++x) {
            const size_t i = size_t(y) * W + x;
            if (cpu[i] == gpu[i]) continue;
            ++d.all;
            const glm::dvec2 sample = glm::dvec2(x, y) + sampleZero(msaa);
            bool near = false;
            for (uint32_t id : {cpu[i], gpu[i]})
                if (id != NONE && id < triangles.size())
                    near = near || CpuRaster(triangles[id], rules).nearEdge(sample);
            d.explained += near;
        }
    return d;
}

class RasterRulesTest : public ::testing::TestWithParam<uint32_t> {}; // MSAA

TEST_P(RasterRulesTest, TheCpuRulesDrawTheHardwaresIdImage) {
    const uint32_t msaa = GetParam();
    for (uint32_t grid : {8u, 0u}) {
        const std::vector<RasterTriangle> triangles = randomTriangles(800, grid, 46 + grid);
        const Drawn drawn = draw(sceneOf(triangles), msaa);
        ASSERT_EQ(drawn.ids.size(), size_t(W) * H);
        RasterRules rules;
        rules.subpixelBits = drawn.subpixelBits;
        const auto cpu = testing_support::rasterize(triangles, W, H, sampleZero(msaa), rules, NONE);
        size_t shown = 0;
        for (uint32_t id : cpu) shown += id != NONE;
        EXPECT_GT(shown, size_t(W) * H / 3) << "the triangles cover too little to compare";
        const Differences d = compare(triangles, cpu, drawn.ids, msaa, rules);
        std::printf("[ raster   ] %ux, corners %s: %zu pixels differ, %zu of them within a "
                    "subpixel step of an edge (%u subpixel bits)\n",
                    msaa, grid ? "on the 1/8 px grid" : "anywhere", d.all, d.explained,
                    drawn.subpixelBits);
        EXPECT_EQ(d.all, d.explained) << "pixels no rule explains";
        if (grid) {
            EXPECT_EQ(d.all, 0u) << "on the grid no rounding can differ";
        }

        // The mutation: the bottom-right rule draws another image of the grid scene.
        if (!grid) continue;
        RasterRules turned = rules;
        turned.topLeft = false;
        const auto wrong =
            testing_support::rasterize(triangles, W, H, sampleZero(msaa), turned, NONE);
        const size_t mutated = compare(triangles, wrong, drawn.ids, msaa, rules).all;
        std::printf("[ raster   ] %ux, the bottom-right rule: %zu pixels differ\n", msaa, mutated);
        EXPECT_GT(mutated, 0u) << "the scene has no sample on an edge: it cannot test the rule";
    }
}

INSTANTIATE_TEST_SUITE_P(Lavapipe, RasterRulesTest, ::testing::Values(1u, 4u),
                         [](const auto& info) { return "msaa" + std::to_string(info.param); });

} // namespace
