// test_raycast.cpp - the CPU reference the GPU tests trust: pixel rays and nearest hits.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/generator.h"
#include "scene/raycast.h"

using namespace scene;

TEST(Raycast, PixelRayPassesThroughTheProjectedPoint) {
    Camera camera = tilesCamera();
    const glm::vec2 size(320, 200);
    const glm::mat4 viewProj = camera.viewProjection(size.x / size.y);
    const glm::vec3 point(1.3f, -0.7f, -0.5f);
    glm::vec4 clip = viewProj * glm::vec4(point, 1);
    glm::vec2 pixel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * size;
    Ray ray = pixelRay(viewProj, size, pixel);
    glm::vec3 toPoint = point - ray.origin;
    float along = glm::dot(toPoint, glm::normalize(ray.direction));
    EXPECT_LT(glm::length(toPoint - along * glm::normalize(ray.direction)), 1e-4f);
    EXPECT_GT(ray.origin.z, 10.0f); // starts at the near plane, in front of the camera
}

TEST(Raycast, NearestSurfaceWinsAndGapsShowWhatIsBehind) {
    Scene s = makeTiles();
    const glm::vec3 eye = tilesCamera().eye;
    auto hitAt = [&](glm::vec3 target) { return raycast(s, {eye, (target - eye) * 2.0f}); };
    // Tile (row 1, col 2) of the second sheet: sheet origin (0.2, -0.4), tile origin (2, 1).
    auto tile = hitAt({0.2f + 2.4f, -0.4f + 1.4f, 0});
    ASSERT_TRUE(tile);
    EXPECT_EQ(tile->uniquePartId, 12u + 1 * 4 + 2);
    EXPECT_EQ(tile->object, 1u);
    EXPECT_EQ(tile->localPart, 6u);
    // Between two tiles the back plate (listed last) is hit.
    auto plate = hitAt({0.2f + 0.9f, -0.4f + 1.4f, 0});
    ASSERT_TRUE(plate);
    EXPECT_EQ(plate->uniquePartId, 24u);
    EXPECT_FALSE(hitAt({20.0f, 0, 0})); // beside everything
    EXPECT_LT(tile->t, plate->t);
}

TEST(Raycast, HonoursObjectTransforms) {
    Scene s = makeTiles();
    s.objects[0].world = glm::translate(glm::mat4(1), {0, 0, 5}); // pull sheet 0 forward
    const glm::vec3 eye(0, 0, 20);
    auto hit = raycast(s, {eye, glm::vec3(0.4f, 0.4f, 0) - eye});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->uniquePartId, 0u);
    EXPECT_NEAR(hit->t, 15.0f / 20.0f, 1e-5f);
}
