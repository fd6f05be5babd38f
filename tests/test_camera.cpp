// test_camera.cpp - the camera's maths in both projections: the standard views against
// FreeCAD's own camera rotations, fitting that keeps every corner of the bounds in view,
// switching projections keeping the target's size, pixel rays and unprojection round trips
// in both projections (reversed depth, perspective to infinity), the near plane from the scene,
// and the world box of selected parts that F fits.
#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>
#include <map>

#include "scene/bounds.h"
#include "scene/camera.h"
#include "scene/procedural/generator.h"
#include "scene/standard_view.h"

namespace {

scene::Bounds box(glm::vec3 min, glm::vec3 max) {
    scene::Bounds b;
    b.min = min;
    b.max = max;
    return b;
}

// FreeCAD's Gui/Camera.cpp: each standard view as the rotation (x, y, z, w) of a camera that
// looks down its -Z with +Y up. Written out from FreeCAD's source, not from our table.
const std::map<std::string, glm::quat>& freecadRotations() {
    const float r = std::sqrt(0.5f);
    static const std::map<std::string, glm::quat> rotations = {
        {"top", glm::quat(1, 0, 0, 0)}, // glm::quat is (w, x, y, z)
        {"bottom", glm::quat(0, 1, 0, 0)},
        {"front", glm::quat(r, r, 0, 0)},
        {"back", glm::quat(0, 0, r, r)}, // FreeCAD's "rear"
        {"right", glm::quat(0.5f, 0.5f, 0.5f, 0.5f)},
        {"left", glm::quat(-0.5f, -0.5f, 0.5f, 0.5f)},
        {"isometric", glm::quat(0.820473f, 0.424708f, 0.17592f, 0.339851f)},
    };
    return rotations;
}

// The camera's forward and up directions as its view matrix has them.
glm::vec3 forwardOf(const scene::Camera& c) {
    const glm::mat4 v = c.view();
    return -glm::vec3(v[0][2], v[1][2], v[2][2]);
}
glm::vec3 upOf(const scene::Camera& c) {
    const glm::mat4 v = c.view();
    return glm::vec3(v[0][1], v[1][1], v[2][1]);
}

void expectNear(glm::vec3 a, glm::vec3 b, float tolerance, const std::string& what) {
    EXPECT_LT(glm::length(a - b), tolerance)
        << what << ": (" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x << ", " << b.y
        << ", " << b.z << ")";
}

// Every corner of `bounds` projects inside the image and the depth range.
void expectContains(const scene::Camera& camera, const scene::Bounds& bounds, float aspect,
                    const std::string& what) {
    const glm::dmat4 viewProj = camera.viewProjection(aspect);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? bounds.max.x : bounds.min.x,
                          (corner & 2) ? bounds.max.y : bounds.min.y,
                          (corner & 4) ? bounds.max.z : bounds.min.z);
        const glm::vec4 clip = viewProj * glm::vec4(p, 1.0f);
        ASSERT_GT(clip.w, 0.0f) << what;
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        EXPECT_LE(std::abs(ndc.x), 1.0f + 1e-4f) << what << ", corner " << corner;
        EXPECT_LE(std::abs(ndc.y), 1.0f + 1e-4f) << what << ", corner " << corner;
        EXPECT_GE(ndc.z, -1e-5f) << what << ", corner " << corner;
        EXPECT_LE(ndc.z, 1.0f + 1e-5f) << what << ", corner " << corner;
    }
}

scene::Camera opening(const scene::Bounds& bounds, float aspect) {
    return scene::fitCamera(bounds, glm::vec3(0.9f, -1.6f, 1.2f), {0, 0, 1}, glm::radians(40.0f),
                            aspect);
}

} // namespace

TEST(StandardView, EveryViewLooksAsFreeCADsCamera) {
    ASSERT_EQ(scene::standardViews().size(), freecadRotations().size());
    const scene::Bounds bounds = box({-1, -2, -3}, {4, 5, 6});
    const scene::Camera start = opening(bounds, 1.5f);
    for (const scene::StandardView& view : scene::standardViews()) {
        const glm::quat q = freecadRotations().at(view.name);
        const scene::Camera turned = scene::turnedTo(start, view, {0, 0, 1});
        expectNear(forwardOf(turned), q * glm::vec3(0, 0, -1), 1e-5f, view.name);
        expectNear(upOf(turned), q * glm::vec3(0, 1, 0), 1e-5f, view.name);
        // Around the same target at the same distance: a fitted view stays fitted.
        EXPECT_EQ(turned.target, start.target) << view.name;
        EXPECT_NEAR(glm::length(turned.eye - turned.target), glm::length(start.eye - start.target),
                    1e-4f)
            << view.name;
    }
    EXPECT_EQ(scene::findStandardView("sideways"), nullptr);
    std::string names;
    for (const scene::StandardView& view : scene::standardViews())
        names += (names.empty() ? "" : ", ") + std::string(view.name);
    EXPECT_EQ(scene::standardViewNames(), names);
}

// A Y-up model (glTF): FreeCAD's Z becomes Y and its Y becomes -Z, so front looks along -Z
// (glTF's front faces +Z), top down -Y, right along -X.
TEST(StandardView, AYUpModelKeepsItsUpAxisUp) {
    const scene::Camera start =
        scene::fitCamera(box({-1, -1, -1}, {1, 1, 1}), {1, 1, 1}, {0, 1, 0}, 0.7f, 1.0f);
    auto turned = [&](const char* name) {
        return scene::turnedTo(start, *scene::findStandardView(name), {0, 1, 0});
    };
    expectNear(forwardOf(turned("front")), {0, 0, -1}, 1e-5f, "front");
    expectNear(upOf(turned("front")), {0, 1, 0}, 1e-5f, "front up");
    expectNear(forwardOf(turned("top")), {0, -1, 0}, 1e-5f, "top");
    expectNear(upOf(turned("top")), {0, 0, -1}, 1e-5f, "top up");
    expectNear(forwardOf(turned("right")), {-1, 0, 0}, 1e-5f, "right");
    expectNear(forwardOf(turned("isometric")), glm::normalize(glm::vec3(-1, -1, -1)), 1e-5f,
               "isometric");
}

// Fitted from any standard view, in either projection and any window shape, the whole box is
// in view, depth range included.
TEST(Camera, FitKeepsTheBoundsInViewInBothProjections) {
    for (float size : {1e-3f, 1.0f, 5e3f})
        for (float aspect : {0.5f, 1.6f, 3.0f})
            for (const scene::StandardView& view : scene::standardViews())
                for (bool ortho : {false, true}) {
                    const scene::Bounds bounds =
                        box(glm::vec3(10, -3, 2) * size, glm::vec3(12, 1, 2.5f) * size);
                    scene::Camera camera =
                        scene::turnedTo(opening(bounds, aspect), view, {0, 0, 1});
                    camera.ortho = ortho;
                    scene::fitPlanes(camera, bounds);
                    expectContains(camera, bounds, aspect,
                                   std::string(view.name) + (ortho ? " ortho" : "") + " size " +
                                       std::to_string(size) + " aspect " + std::to_string(aspect));
                }
}

// In ortho the planes take in the whole sphere even with the eye among the parts (behind it
// too), which perspective cannot.
TEST(Camera, OrthoPlanesReachBehindAnEyeInsideTheBounds) {
    const scene::Bounds bounds = box({-10, -10, -10}, {10, 10, 10});
    scene::Camera camera;
    camera.eye = {0, -2, 0};
    camera.target = {0, 0, 0};
    camera.ortho = true;
    scene::fitPlanes(camera, bounds);
    EXPECT_LT(camera.nearPlane, 0.0f);
    const glm::dmat4 viewProj = camera.viewProjection(1.0f);
    const glm::vec4 behind = viewProj * glm::vec4(0, -15, 0, 1); // behind the eye, inside
    EXPECT_GE(behind.z / behind.w, 0.0f);
    EXPECT_EQ(behind.w, 1.0f);
}

// Switching keeps the target's apparent size: points on the plane through the target,
// facing the camera, land on the same pixels in both projections.
TEST(Camera, SwitchingProjectionKeepsTheTargetsSize) {
    scene::Camera camera = opening(box({-1, -1, -1}, {1, 1, 1}), 1.6);
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    for (glm::dvec2 offset :
         {glm::dvec2(0.3, 0.0), glm::dvec2(-0.2, 0.45), glm::dvec2(0.6, -0.5)}) {
        const glm::dvec4 p(camera.target + offset.x * right + offset.y * up, 1.0);
        camera.ortho = false;
        const glm::dvec4 perspective = camera.viewProjection(1.6) * p;
        camera.ortho = true;
        const glm::dvec4 ortho = camera.viewProjection(1.6) * p;
        EXPECT_EQ(ortho.w, 1.0);
        expectNear(glm::dvec3(glm::dvec2(perspective) / perspective.w, 0),
                   glm::dvec3(glm::dvec2(ortho), 0), 1e-5, "projected");
    }
    // And the view is as tall as the perspective one at the target: 2 d tan(fov / 2).
    EXPECT_DOUBLE_EQ(camera.orthoHeight(),
                     2.0 * glm::length(camera.target - camera.eye) * std::tan(0.5 * camera.fovY));
}

// In ortho every pixel's ray has the view's direction, starts on the near plane under the
// pixel and passes through what projects there; unprojecting a pixel's depth gives the point.
TEST(Camera, OrthoPixelRaysAreParallelAndUnprojectRoundTrips) {
    scene::Camera camera = scene::turnedTo(opening(box({-2, -1, 0}, {3, 2, 1}), 1.5),
                                           *scene::findStandardView("isometric"), {0, 0, 1});
    camera.ortho = true;
    scene::fitPlanes(camera, box({-2, -1, 0}, {3, 2, 1}));
    const glm::dvec2 size(300, 200);
    const glm::dmat4 viewProj = camera.viewProjection(size.x / size.y);
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    for (const glm::dvec3 point :
         {glm::dvec3(0.5, 0.2, 0.3), glm::dvec3(-1.7, 1.5, 0.9), glm::dvec3(2.5, -0.8, 0.1)}) {
        const glm::dvec4 clip = viewProj * glm::dvec4(point, 1.0);
        const glm::dvec2 pixel = (glm::dvec2(clip) * 0.5 + 0.5) * size;
        const scene::Ray ray = scene::pixelRay(viewProj, size, pixel);
        expectNear(glm::normalize(ray.direction), forward, 1e-5, "ray direction");
        const glm::dvec4 origin = viewProj * glm::dvec4(ray.origin, 1.0);
        EXPECT_NEAR(origin.z, 1.0, 1e-5); // on the near plane (reversed depth: 1)
        const glm::dvec3 toPoint = point - ray.origin;
        const double along = glm::dot(toPoint, forward);
        EXPECT_LT(glm::length(toPoint - along * forward), 1e-4);
        expectNear(scene::unprojectPixel(viewProj, size, pixel, clip.z), point, 1e-4,
                   "unprojected");
    }
}

// Perspective depth is reversed with the far plane at infinity: 1 at the near plane, near /
// distance beyond it; every pixel's ray starts on the near plane and goes on without end
// (the CPU ray cast reaches anything in view), and unprojecting a pixel's depth gives the
// point back to float precision relative to its distance, a kilometre away too.
TEST(Camera, PerspectiveDepthIsReversedToInfinityAndUnprojectsFarPoints) {
    scene::Camera camera;
    camera.eye = {3, -2, 1};
    camera.target = {3, 10, 1};
    camera.nearPlane = 0.5;
    const glm::dvec2 size(300, 200);
    const glm::dmat4 viewProj = camera.viewProjection(size.x / size.y);
    const glm::dvec4 atNear = viewProj * glm::dvec4(3, -1.5, 1, 1);
    EXPECT_NEAR(atNear.z / atNear.w, 1.0, 1e-6);
    double lastDepth = 1.0;
    for (double distance : {1.0, 40.0, 1e3, 1e6}) {
        const glm::dvec3 point = camera.eye + glm::dvec3(0.3, 1.0, -0.2) * distance;
        const glm::dvec4 clip = viewProj * glm::dvec4(point, 1.0);
        const double depth = clip.z / clip.w;
        EXPECT_LT(depth, lastDepth) << "farther must be less deep";
        EXPECT_GT(depth, 0.0);
        lastDepth = depth;
        const glm::dvec2 pixel = (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * size;
        const scene::Ray ray = scene::pixelRay(viewProj, size, pixel);
        EXPECT_TRUE(std::isinf(ray.end));
        const glm::dvec4 origin = viewProj * glm::dvec4(ray.origin, 1.0);
        EXPECT_NEAR(origin.z / origin.w, 1.0, 1e-5); // on the near plane
        const double length = glm::length(point - camera.eye);
        expectNear(scene::unprojectPixel(viewProj, size, pixel, depth), point, 1e-5 * length,
                   "unprojected at " + std::to_string(distance));
        expectNear(ray.origin + scene::rayParameterAtDepth(viewProj, depth) * ray.direction, point,
                   1e-5 * length, "along the ray");
    }
}

// The near plane comes from the scene and the eye: the scene's nearest depth when it lies
// wholly in front, whatever the far plane; a floor relative to its size from inside it.
TEST(Camera, NearPlaneFollowsTheScenesNearestPoint) {
    scene::Camera camera;
    camera.eye = {0, -1000, 0};
    camera.target = {0, 0, 0};
    scene::fitPlanes(camera, box({-1, -10, -1}, {1, 5000, 1}));
    EXPECT_LE(camera.nearPlane, 990.0);
    EXPECT_GT(camera.nearPlane, 980.0);
    camera.eye = {0, 0, 0};
    camera.target = {0, 10, 0};
    scene::fitPlanes(camera, box({-1, -10, -1}, {1, 5000, 1}));
    EXPECT_GT(camera.nearPlane, 0.0);
    EXPECT_LT(camera.nearPlane, 0.1);
}

// F fits the world box of the selected parts' triangles: two tiles of makeTiles, placed by
// their sheets (generator.cpp: tiles of 0.8 on a 1.0 grid, sheets at x -4 and 0.2, y -0.4).
TEST(Camera, SelectedPartsWorldBounds) {
    const scene::Scene s = scene::makeTiles();
    scene::PartSet parts(s.uniquePartCount());
    EXPECT_TRUE(scene::isEmpty(scene::partsWorldBounds(s, parts)));
    parts.insert(12 + 1 * 4 + 2); // sheet 2, row 1, column 2
    scene::Bounds b = scene::partsWorldBounds(s, parts);
    expectNear(b.min, {2.2f, 0.6f, 0.0f}, 1e-5f, "min");
    expectNear(b.max, {3.0f, 1.4f, 0.0f}, 1e-5f, "max");
    parts.insert(0); // sheet 1, row 0, column 0
    b = scene::partsWorldBounds(s, parts);
    expectNear(b.min, {-4.0f, -0.4f, 0.0f}, 1e-5f, "min");
    expectNear(b.max, {3.0f, 1.4f, 0.0f}, 1e-5f, "max");
}
