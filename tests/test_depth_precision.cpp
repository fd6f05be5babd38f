// test_depth_precision.cpp - reversed depth keeps faces apart that a conventional depth buffer
// merges: two faces 0.1 mm apart, 1 km from the camera, in a millimetre scene that also holds a
// part a couple of metres from the eye (so the near plane must stay that close).
#include <gtest/gtest.h>

#include <algorithm>

#include "app/headless.h"
#include "scene/camera.h"
#include "scene/mesh_builder.h"
#include "test_support.h"

namespace {

constexpr uint32_t W = 96, H = 64;
constexpr float kDistance = 1.0e6f; // mm from the eye to the front face
constexpr float kGap = 0.1f;        // mm from the front face to the one behind it
constexpr float kFrontHalf = 1.0e5f, kBackHalf = 2.0e5f; // half sizes: the back one shows around

// A square facing -y (the camera) at y, `half` on each side of the y axis.
uint32_t facingSquare(scene::Scene& s, float y, float half, const char* name) {
    scene::MeshBuilder mb;
    const glm::vec3 corners[] = {
        {-half, y, -half}, {half, y, -half}, {half, y, half}, {-half, y, half}};
    mb.addFlatFace(corners);
    return mb.finish(s, name);
}

struct GapScene {
    scene::Scene scene;
    uint32_t front = 0, back = 0; // unique part IDs
};

// The back face is added first or last: where two depths tie, the face drawn first stays, so
// with the back face first only a depth that tells them apart lets the front one show. Draws
// go in geometry order (render/draw_list.cpp sorts them so), hence geometries in that order.
GapScene gapScene(bool backFirst) {
    GapScene g;
    scene::Scene& s = g.scene;
    s.unit = {"mm", "the test"};
    const uint32_t grey = scene::addMaterial(s, "grey", {0.5f, 0.5f, 0.5f, 1});
    for (bool isBack : {backFirst, !backFirst}) {
        const uint32_t geometry = isBack ? facingSquare(s, kGap, kBackHalf, "back")
                                         : facingSquare(s, 0.0f, kFrontHalf, "front");
        const uint32_t object =
            scene::addObject(s, geometry, grey, glm::mat4(1.0f), isBack ? "back" : "front");
        (isBack ? g.back : g.front) = s.objects[object].uniquePartOffset; // a face is one part
    }
    // A post 1.87 m in front of the eye, far to its side (out of view): the scene begins
    // there, so no fixed ratio of the far plane may put the near plane past it.
    scene::MeshBuilder post;
    post.addBox({5.0e5f, -kDistance + 1900.0f, 0.0f}, {100.0f, 60.0f, 100.0f});
    const uint32_t postGeometry = post.finish(s, "post");
    scene::addObject(s, postGeometry, grey, glm::mat4(1.0f), "post");
    scene::validate(s);
    return g;
}

scene::Camera gapCamera(const scene::Scene& s) {
    scene::Camera camera;
    camera.eye = {0.0f, -kDistance, 0.0f};
    camera.target = {0.0f, 0.0f, 0.0f};
    camera.up = {0.0f, 0.0f, 1.0f};
    camera.fovY = glm::radians(45.0f);
    scene::fitPlanes(camera, s.bounds());
    return camera;
}

// The pixel rectangle [lo, hi) whose pixel centres lie inside the square of half size
// `half` at the origin, at least a pixel from its edges.
void innerPixels(const glm::mat4& viewProj, float half, glm::ivec2& lo, glm::ivec2& hi) {
    const auto pixelOf = [&](glm::vec3 p) {
        const glm::vec4 clip = viewProj * glm::vec4(p, 1.0f);
        return (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(W, H);
    };
    const glm::vec2 a = pixelOf({-half, 0.0f, -half}), b = pixelOf({half, 0.0f, half});
    lo = glm::ivec2(glm::ceil(glm::min(a, b) + 1.0f));
    hi = glm::ivec2(glm::floor(glm::max(a, b) - 1.0f));
}

} // namespace

// The front face covers every pixel of its own, the back one shows around it, in either
// drawing order, culling off (the list's order) and on.
TEST(DepthPrecision, FacesATenthOfAMillimetreApartAKilometreAwayStayDistinct) {
    for (bool backFirst : {true, false})
        for (render::CullMode cull : {render::CullMode::Off, render::CullMode::Occlusion}) {
            const GapScene g = gapScene(backFirst);
            const scene::Camera camera = gapCamera(g.scene);
            const std::string name =
                std::string(backFirst ? "back first" : "front first") +
                (cull == render::CullMode::Off ? ", culling off" : ", occlusion");
            app::Options o = testing_support::headlessOptions(W, H);
            o.live.render.culling.mode = cull;
            const app::HeadlessResult r = app::renderHeadless(o, g.scene, camera);
            EXPECT_EQ(r.validationMessages, 0u) << name;
            ASSERT_EQ(r.ids.size(), size_t(W) * H) << name;
            const glm::mat4 viewProj = camera.viewProjection(float(W) / float(H));
            glm::ivec2 frontLo, frontHi, backLo, backHi;
            innerPixels(viewProj, kFrontHalf, frontLo, frontHi);
            innerPixels(viewProj, kBackHalf, backLo, backHi);
            ASSERT_GT(frontHi.x - frontLo.x, 4) << name;
            ASSERT_GT(frontHi.y - frontLo.y, 4) << name;
            size_t frontPixels = 0, frontWrong = 0, backPixels = 0;
            for (int y = backLo.y; y < backHi.y; ++y)
                for (int x = backLo.x; x < backHi.x; ++x) {
                    const uint32_t id = r.ids[size_t(y) * W + size_t(x)];
                    const bool inFront =
                        x >= frontLo.x && x < frontHi.x && y >= frontLo.y && y < frontHi.y;
                    const bool nearFrontEdge = x >= frontLo.x - 3 && x < frontHi.x + 3 &&
                                               y >= frontLo.y - 3 && y < frontHi.y + 3;
                    if (inFront) {
                        ++frontPixels;
                        frontWrong += id != g.front;
                    } else if (!nearFrontEdge) {
                        EXPECT_EQ(id, g.back) << name << " at " << x << "," << y;
                        ++backPixels;
                    }
                }
            EXPECT_GT(frontPixels, 20u) << name;
            EXPECT_GT(backPixels, 20u) << name;
            EXPECT_EQ(frontWrong, 0u) << name << ": pixels of the front face showing the back one";
        }
}

// The near plane comes from the scene: just before the post, the scene's nearest point.
TEST(DepthPrecision, NearPlaneIsTheScenesNearestDepth) {
    const GapScene g = gapScene(true);
    const scene::Camera camera = gapCamera(g.scene);
    EXPECT_LE(camera.nearPlane, 1870.0f);
    EXPECT_GT(camera.nearPlane, 1800.0f);
}
