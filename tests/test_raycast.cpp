// test_raycast.cpp - the CPU reference the GPU tests trust: pixel rays and nearest hits.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/procedural/generator.h"
#include "scene/raycast.h"

using namespace scene;

TEST(Raycast, PixelRayPassesThroughTheProjectedPoint) {
    Camera camera = tilesCamera();
    const glm::dvec2 size(320, 200);
    const glm::dmat4 viewProj = camera.viewProjection(size.x / size.y);
    const glm::dvec3 point(1.3, -0.7, -0.5);
    glm::dvec4 clip = viewProj * glm::dvec4(point, 1);
    glm::dvec2 pixel = (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * size;
    Ray ray = pixelRay(viewProj, size, pixel);
    glm::dvec3 toPoint = point - ray.origin;
    double along = glm::dot(toPoint, glm::normalize(ray.direction));
    EXPECT_LT(glm::length(toPoint - along * glm::normalize(ray.direction)), 1e-4);
    EXPECT_GT(ray.origin.z, 10.0); // starts at the near plane, in front of the camera
}

TEST(Raycast, NearestSurfaceWinsAndGapsShowWhatIsBehind) {
    Scene s = makeTiles();
    const glm::dvec3 eye = tilesCamera().eye;
    auto hitAt = [&](glm::dvec3 target) { return raycast(s, {eye, (target - eye) * 2.0}); };
    // Tile (row 1, col 2) of the second sheet: sheet origin (0.2, -0.4), tile origin (2, 1).
    auto tile = hitAt({0.2 + 2.4, -0.4 + 1.4, 0});
    ASSERT_TRUE(tile);
    EXPECT_EQ(tile->uniquePartId, 12u + 1 * 4 + 2);
    EXPECT_EQ(tile->object, 1u);
    EXPECT_EQ(tile->localPart, 6u);
    // Between two tiles the back plate (listed last) is hit.
    auto plate = hitAt({0.2 + 0.9, -0.4 + 1.4, 0});
    ASSERT_TRUE(plate);
    EXPECT_EQ(plate->uniquePartId, 24u);
    EXPECT_FALSE(hitAt({20.0, 0, 0})); // beside everything
    EXPECT_LT(tile->t, plate->t);
}

TEST(Raycast, HonoursObjectTransforms) {
    Scene s = makeTiles();
    s.objects[0].world = glm::translate(glm::dmat4(1), {0, 0, 5}); // pull sheet 0 forward
    const glm::dvec3 eye(0, 0, 20);
    auto hit = raycast(s, {eye, glm::dvec3(0.4, 0.4, 0) - eye});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->uniquePartId, 0u);
    EXPECT_NEAR(hit->t, 15.0 / 20.0, 1e-5);
}

// Section planes: the flag's form, and which side a plane keeps.
TEST(Section, ParsesAxisValueAndFlip) {
    const SectionPlane x = parseSectionPlane("x,1.5");
    EXPECT_TRUE(x.on);
    EXPECT_EQ(x.normal, glm::dvec3(1, 0, 0));
    EXPECT_DOUBLE_EQ(x.offset, 1.5);
    EXPECT_FALSE(x.flip);
    const SectionPlane z = parseSectionPlane("z,-20,flip");
    EXPECT_EQ(z.normal, glm::dvec3(0, 0, 1));
    EXPECT_DOUBLE_EQ(z.offset, -20.0);
    EXPECT_TRUE(z.flip);
    for (const char* bad : {"", "x", "x,", "w,1", "xy,1", "x,1,fl", "x,one", "x,1e999", "x,nan",
                            "x,1,flip,flip", ",1", "X,1"})
        EXPECT_THROW(parseSectionPlane(bad), std::invalid_argument) << bad;
}

TEST(Section, KeepsTheSideAtMostTheValueOrTheOtherWhenFlipped) {
    const SectionPlane y = axisPlane(1, 2.0);
    EXPECT_TRUE(y.keeps({9, 2.0f, 9}));
    EXPECT_TRUE(y.keeps({0, 1.9f, 0}));
    EXPECT_FALSE(y.keeps({0, 2.1f, 0}));
    const SectionPlane flipped = axisPlane(1, 2.0f, true);
    EXPECT_FALSE(flipped.keeps({0, 1.9f, 0}));
    EXPECT_TRUE(flipped.keeps({0, 2.1f, 0}));
    SectionPlane off = y;
    off.on = false;
    EXPECT_TRUE(off.keeps({0, 1e6f, 0}));
    // Several planes: a point stays where every plane keeps it.
    Section section;
    EXPECT_FALSE(section.any());
    section.planes[0] = axisPlane(0, 0.0f);
    section.planes[2] = axisPlane(2, 1.0f, true);
    EXPECT_TRUE(section.any());
    EXPECT_TRUE(section.keeps({-1, 5, 2}));
    EXPECT_FALSE(section.keeps({1, 5, 2}));
    EXPECT_FALSE(section.keeps({-1, 5, 0}));
}

// The in-plane rule: a surface parallel to the plane and within the tolerance of it is kept
// where its outward normal faces the side cut away, on either side of the plane by rounding;
// flip turns the answer over. Elsewhere, or not parallel, the point's side decides.
TEST(Section, KeepsASurfaceInThePlaneWholeByItsOutwardNormal) {
    const double tolerance = inPlaneTolerance(10.0);
    EXPECT_GT(tolerance, 1e-5);
    EXPECT_LT(tolerance, 1e-3);
    const glm::dvec3 up(0, 1, 0), slanted(0, 1, 0.1); // 5.7 degrees off: not parallel
    for (bool flip : {false, true}) {
        const SectionPlane y = axisPlane(1, 2.0, flip);
        const glm::dvec3 away = flip ? -up : up; // towards the side cut away
        for (double off : {-0.5 * tolerance, 0.0, 0.5 * tolerance}) {
            const glm::dvec3 p(3, 2.0 + off, -1);
            EXPECT_TRUE(y.keeps(p, 7.0 * away, tolerance)) << flip << " " << off;
            EXPECT_FALSE(y.keeps(p, -away, tolerance)) << flip << " " << off;
            if (off != 0.0) {
                EXPECT_EQ(y.keeps(p, slanted, tolerance), y.keeps(p)) << off;
            }
            EXPECT_EQ(y.keeps(p, glm::dvec3(0.0), tolerance), y.keeps(p)) << off;
        }
        for (double off : {-2.0 * tolerance, 2.0 * tolerance})
            EXPECT_EQ(y.keeps({3, 2.0 + off, -1}, -away, tolerance), y.keeps({3, 2.0 + off, -1}));
    }
    SectionPlane off = axisPlane(1, 2.0);
    off.on = false;
    EXPECT_TRUE(off.keeps({0, 2.0, 0}, {0, -1, 0}, 10.0)); // an off plane has no surface in it
}

// The ray goes through what a plane cuts away, and meeting a surface from behind (its
// normals face away) is a cap: the tiles face the +z camera, so from -z they are caps.
TEST(Raycast, SectionsCutAwayAndBackFacesAreCaps) {
    const Scene s = makeTiles();
    const glm::vec3 target(0.2f + 2.4f, -0.4f + 1.4f, 0); // a tile of the second sheet
    const glm::vec3 front(target.x, target.y, 20), back(target.x, target.y, -20);
    const auto seen = raycast(s, {front, (target - front) * 2.0f});
    ASSERT_TRUE(seen);
    EXPECT_EQ(seen->uniquePartId, 12u + 1 * 4 + 2);
    EXPECT_FALSE(seen->cap);
    const RayCaster caster(s);
    const auto behind = caster.cast({back, (target - back) * 2.0f}); // the plate, from behind
    ASSERT_TRUE(behind);
    EXPECT_EQ(behind->uniquePartId, 24u);
    EXPECT_TRUE(behind->cap);
    // Cutting z > -0.5 away leaves the plate (z = -1) to the front ray, seen from the front.
    Section section;
    section.planes[0] = axisPlane(2, -0.5f);
    const auto cut = caster.cast({front, (target - front) * 2.0f}, nullptr, &section);
    ASSERT_TRUE(cut);
    EXPECT_EQ(cut->uniquePartId, 24u);
    EXPECT_FALSE(cut->cap);
    EXPECT_GT(cut->t, seen->t);
    // Flipped, it keeps only the tiles: the back ray now meets a tile from behind.
    section.planes[0].flip = true;
    const auto flipped = caster.cast({back, (target - back) * 2.0f}, nullptr, &section);
    ASSERT_TRUE(flipped);
    EXPECT_EQ(flipped->uniquePartId, 12u + 1 * 4 + 2);
    EXPECT_TRUE(flipped->cap);
}
