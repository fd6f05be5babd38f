// test_raster_rules.cpp - the rules a compute rasterizer must follow to draw the hardware's
// ID image (issue 46), written down as tests/cpu_raster.h and checked against lavapipe's
// rasterizer with validation on: small triangles, each its own part at its own depth, through
// the tests' flat camera at 1x (the pixel centre) and 4x MSAA (the ID image is sample 0's, at
// Vulkan's standard position). With corners on an eighth-pixel grid (exact on any subpixel
// grid, and many edges through sample positions) every pixel agrees; with corners anywhere,
// a pixel may differ only where its sample lies within one subpixel step of an edge (the
// driver's rounding of the corners), and the count of those is printed. The bottom-right rule
// in place of the top-left one disagrees: the scenes test the rule. The GLSL copy of the rules
// (shaders/raster.glsl), run by a compute shader with 64-bit atomics into a buffer a sample
// each, draws the same images, and with its rule turned around it does not.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <random>

#include <fstream>

#include "app/offscreen.h"
#include "cpu_raster.h"
#include "render/pipeline.h"
#include "render/technique.h"
#include "scene/mesh_builder.h"
#include "shader_copy.h"
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
    o.live.render = testing_support::settingsFor(*render::findTechnique("vertex-fs"),
                                                 render::defaultDrawMode());
    o.live.render.culling.mode = render::CullMode::Off;
    o.live.render.pipeline.msaa = msaa;
    vk::Instance instance({true, {}, false});
    Drawn drawn;
    {
        app::Offscreen rig(instance, o);
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(rig.device.physical(), &props);
        drawn.subpixelBits = props.limits.subPixelPrecisionBits;
        rig.renderer.setScene(s, o.live.render);
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

// A compute shader over raster.glsl: a thread per triangle (8 floats: corners in pixels,
// depth, ID bits), each covered sample's 64-bit visibility sample atomicMax'ed.
const char* const kRasterTest = R"(#version 460
#include "buffers.glsl"
#include "raster.glsl"
layout(local_size_x = 64) in;
layout(buffer_reference, std430, buffer_reference_align = 8) buffer SamplesRef {
    uint64_t values[];
};
layout(push_constant, std430) uniform Block {
    uint64_t trianglesAddress;
    uint64_t samplesAddress;
    uvec2 extent;
    vec2 offset;
    uint count;
    uint bits;
};
void main() {
    uint t = gl_GlobalInvocationID.x;
    if (t >= count) return;
    FloatsRef f = FloatsRef(trianglesAddress);
    vec2 corners[3];
    for (uint k = 0u; k < 3u; ++k) corners[k] = vec2(f.values[8u * t + 2u * k], f.values[8u * t + 2u * k + 1u]);
    float depth = f.values[8u * t + 6u];
    uint id = floatBitsToUint(f.values[8u * t + 7u]);
    RasterSetup s = rasterSetup(corners, vec3(depth), bits);
    ivec2 lo = min(s.corner[0], min(s.corner[1], s.corner[2]));
    ivec2 hi = max(s.corner[0], max(s.corner[1], s.corner[2]));
    ivec2 off = snapToGrid(offset, bits);
    int one = 1 << bits;
    ivec2 first = max((lo - off + one - 1) / one, ivec2(0));
    ivec2 last = min((hi - off) / one, ivec2(extent) - 1);
    for (int y = first.y; y <= last.y; ++y)
        for (int x = first.x; x <= last.x; ++x) {
            float z;
            if (rasterCovers(s, ivec2(x, y) * one + off, z))
                atomicMax(SamplesRef(samplesAddress).values[y * int(extent.x) + x], visibilitySample(z, id));
        }
}
)";

struct RasterPush {
    uint64_t trianglesAddress, samplesAddress;
    glm::uvec2 extent;
    glm::vec2 offset;
    uint32_t count, bits;
};

// What the compute shader draws of `triangles` at the sample `msaa`'s sample 0 lies at, with
// the shaders in `dir`: a part ID per pixel.
std::vector<uint32_t> computeRaster(const std::vector<RasterTriangle>& triangles, uint32_t msaa,
                                    const std::filesystem::path& dir, uint32_t& bits) {
    std::ofstream(dir / "raster_test.comp") << kRasterTest;
    app::Options o = testing_support::headlessOptions(W, H);
    o.shaderDir = dir.string();
    vk::Instance instance({true, {}, false});
    std::vector<uint32_t> ids(size_t(W) * H, NONE);
    {
        app::Offscreen rig(instance, o);
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(rig.device.physical(), &props);
        bits = props.limits.subPixelPrecisionBits;
        const VkBufferUsageFlags use =
            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
        vk::Buffer input = vk::hostBuffer(rig.device, triangles.size() * 32, use, "triangles");
        vk::Buffer samples =
            vk::hostBuffer(rig.device, ids.size() * 8, use | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                           "visibility samples");
        auto* f = static_cast<float*>(input.mapped());
        for (const RasterTriangle& t : triangles) {
            for (const glm::dvec2& c : t.corner) {
                *f++ = float(c.x);
                *f++ = float(c.y);
            }
            *f++ = float(t.depth);
            std::memcpy(f++, &t.id, 4);
        }
        const render::ComputePipeline pass = render::createComputePipeline(
            rig.device, rig.compiler, rig.renderer.driverCache(), "raster_test.comp",
            sizeof(RasterPush), VK_NULL_HANDLE, "raster test");
        const glm::dvec2 offset = sampleZero(msaa);
        const RasterPush push{input.address(),   samples.address(),          {W, H},
                              glm::vec2(offset), uint32_t(triangles.size()), bits};
        render::FrameSlot& slot = rig.slots.begin(0);
        vkCmdFillBuffer(slot.cmd, samples.handle(), 0, VK_WHOLE_SIZE, 0);
        vk::memoryBarrier(slot.cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                          VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
        vkCmdBindPipeline(slot.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.pipeline.get());
        vkCmdPushConstants(slot.cmd, pass.layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push,
                           &push);
        vkCmdDispatch(slot.cmd, (push.count + 63) / 64, 1, 1);
        vk::memoryBarrier(slot.cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                          VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                          VK_ACCESS_HOST_READ_BIT);
        rig.slots.submit(slot);
        rig.slots.finish();
        const auto* values = static_cast<const uint64_t*>(samples.mapped());
        for (size_t i = 0; i < ids.size(); ++i)
            if (values[i] != 0) ids[i] = ~uint32_t(values[i]);
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
    return ids;
}

TEST_P(RasterRulesTest, TheComputeRulesDrawTheHardwaresIdImage) {
    const uint32_t msaa = GetParam();
    // A copy of its own: the MSAA cases may run at once, and each edits its copy.
    const std::filesystem::path dir = testing_support::shaderCopy(
        "raster-rules-" + std::to_string(msaa) + "-" + std::to_string(getpid()));
    std::vector<RasterTriangle> onGrid;
    Drawn gridDrawn;
    RasterRules rules;
    for (uint32_t grid : {0u, 8u}) {
        const std::vector<RasterTriangle> triangles = randomTriangles(800, grid, 47 + grid);
        const Drawn drawn = draw(sceneOf(triangles), msaa);
        uint32_t bits = 0;
        const auto ids = computeRaster(triangles, msaa, dir, bits);
        EXPECT_EQ(bits, drawn.subpixelBits);
        rules.subpixelBits = bits;
        const Differences d = compare(triangles, ids, drawn.ids, msaa, rules);
        std::printf("[ raster   ] %ux, compute shader, corners %s: %zu pixels differ from the "
                    "hardware, %zu of them within a subpixel step of an edge\n",
                    msaa, grid ? "on the 1/8 px grid" : "anywhere", d.all, d.explained);
        EXPECT_EQ(d.all, d.explained) << "pixels no rule explains";
        if (grid) {
            EXPECT_EQ(d.all, 0u) << "on the grid no rounding can differ";
            onGrid = triangles;
            gridDrawn = drawn;
        }
    }
    // The rule turned around in the shader: another image of the grid scene.
    testing_support::replaceInFile(dir / "raster.glsl", "return d.y < 0 || (d.y == 0 && d.x > 0);",
                                   "return !(d.y < 0 || (d.y == 0 && d.x > 0));");
    uint32_t bits = 0;
    const auto turned = computeRaster(onGrid, msaa, dir, bits);
    const size_t mutated = compare(onGrid, turned, gridDrawn.ids, msaa, rules).all;
    std::printf("[ raster   ] %ux, compute shader with the bottom-right rule: %zu pixels "
                "differ\n",
                msaa, mutated);
    EXPECT_GT(mutated, 0u) << "the turned rule drew the same image";
    std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Lavapipe, RasterRulesTest, ::testing::Values(1u, 4u),
                         [](const auto& info) { return "msaa" + std::to_string(info.param); });

} // namespace
