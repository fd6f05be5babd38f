// test_section_face.cpp - a section plane put in a selected planar face, as the viewer puts
// it (scene::planeAtFace): the face is kept whole where it bounds what the plane keeps, and
// cut whole with flip, pixel by pixel and by every technique, never a mix of face and cap;
// the CPU ray cast agrees.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/headless.h"
#include "app/scene_source.h"
#include "render/technique.h"
#include "scene/face_info.h"
#include "scene/raycast.h"
#include "test_data.h"
#include "test_support.h"

namespace {

constexpr uint32_t W = 320, H = 200;

struct FaceCut {
    app::LoadedScene loaded;
    uint32_t face = 0; // unique part ID of the planar face
    scene::SurfaceInfo plane;
    scene::Bounds box; // the face's
    scene::Camera camera;
};

// The model's largest planar face.
FaceCut largestPlanarFace(const char* model) {
    FaceCut c;
    app::SceneSettings source;
    source.model = model;
    c.loaded = app::loadScene(source);
    const scene::Scene& s = c.loaded.scene;
    double largest = 0.0;
    for (uint32_t id = 0; id < s.uniquePartCount(); ++id) {
        const auto report = scene::faceReport(s, id);
        if (!report || report->surface.kind != scene::SurfaceKind::Plane) continue;
        if (report->surface.area <= largest) continue;
        largest = report->surface.area;
        c.face = id;
        c.plane = report->surface;
        c.box = report->bbox;
    }
    EXPECT_GT(largest, 0.0) << model;
    return c;
}

// A camera framing the face from its outward side: along its normal, where eye-relative
// coordinates in the plane round alike, or `tilt` off it, where they round every which way
// (the view that showed the face speckled). The near and far planes take in the whole model.
scene::Camera cameraOn(const FaceCut& c, double tilt) {
    const glm::dvec3 n = c.plane.normal;
    const glm::dvec3 up = std::abs(n.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
    const glm::dvec3 side = glm::normalize(glm::cross(n, up));
    const glm::dvec3 direction = glm::normalize(n + tilt * (side + 0.6 * glm::cross(side, n)));
    scene::Camera camera =
        scene::fitCamera(c.box, direction, up, glm::radians(45.0f), double(W) / H);
    scene::fitPlanes(camera, c.loaded.scene.bounds());
    return camera;
}

// Every part-ID technique; the compute rasterizer takes every meshlet it can draw.
std::vector<render::RenderSettings> everyTechnique(const scene::Section& section) {
    std::vector<render::RenderSettings> configs;
    for (const render::Technique* t : render::partIdTechniques()) {
        configs.push_back(testing_support::settingsFor(*t, render::defaultDrawMode()));
        configs.back().raster.all = true;
        configs.back().section = section;
    }
    return configs;
}

app::HeadlessResult render(app::Options o, const FaceCut& c) {
    const app::HeadlessResult r = app::renderHeadless(o, c.loaded.scene, c.camera);
    EXPECT_EQ(r.validationMessages, 0u);
    return r;
}

glm::u8vec3 colorAt(const app::HeadlessResult& r, size_t i) {
    return {r.color[4 * i], r.color[4 * i + 1], r.color[4 * i + 2]};
}

// The CPU ray cast follows the same rule: through the inside of the footprint (its border
// pixels depend on where in the pixel one looks) it meets the face, not as a cap, or with
// flip goes through it.
void expectRayCastAgrees(const FaceCut& c, const scene::Section& section,
                         const std::vector<uint32_t>& aloneIds, const std::string& name) {
    const scene::RayCaster caster(c.loaded.scene);
    const glm::dmat4 viewProj = c.camera.viewProjection(double(W) / H);
    const bool flip = section.planes[0].flip;
    size_t inside = 0, wrong = 0;
    for (uint32_t y = 1; y + 1 < H; ++y)
        for (uint32_t x = 1; x + 1 < W; ++x) {
            const size_t i = size_t(y) * W + x;
            if (aloneIds[i] != c.face || aloneIds[i - 1] != c.face || aloneIds[i + 1] != c.face ||
                aloneIds[i - W] != c.face || aloneIds[i + W] != c.face)
                continue;
            ++inside;
            const scene::Ray ray =
                scene::pixelRay(viewProj, glm::dvec2(W, H), glm::dvec2(x, y) + 0.5);
            const auto hit = caster.cast(ray, nullptr, &section);
            const bool onFace = hit && hit->uniquePartId == c.face;
            if ((flip ? onFace : !onFace || hit->cap) && wrong++ < 3)
                ADD_FAILURE() << name << ": the ray cast at " << x << "," << y << " meets "
                              << (hit ? int64_t(hit->uniquePartId) : -1);
        }
    EXPECT_GT(inside, 1000u) << name;
    EXPECT_EQ(wrong, 0u) << name;
}

// Without flip the plane keeps the solid the face bounds: each technique shows the face on
// every pixel of its footprint (where it shows drawn alone), in the face's own shading, not
// the cap's. With flip it cuts the face: each technique draws the image the cut draws with
// the face hidden.
void expectFaceWholeOrGone(const FaceCut& c, const std::string& view) {
    app::Options o = testing_support::headlessOptions(W, H);
    o.isolate = {c.face};
    const app::HeadlessResult alone = render(o, c);
    o.isolate.clear();
    std::vector<size_t> footprint;
    for (size_t i = 0; i < alone.ids.size(); ++i)
        if (alone.ids[i] == c.face) footprint.push_back(i);
    ASSERT_GT(footprint.size(), size_t(W) * H / 50) << view << ": the face is seen large";

    for (bool flip : {false, true}) {
        scene::Section section;
        section.add(scene::planeAtFace(c.plane, flip));
        o.live.render.section = section;
        if (flip) o.hide = {c.face};
        const app::HeadlessResult expected = render(o, c);
        o.hide.clear();
        expectRayCastAgrees(c, section, alone.ids, (flip ? "flip on " : "on ") + view);
        const auto results =
            app::renderHeadlessSequence(o, c.loaded.scene, c.camera, everyTechnique(section));
        EXPECT_EQ(results.front().validationMessages, 0u);
        for (size_t t = 0; t < results.size(); ++t) {
            const app::HeadlessResult& r = results[t];
            const std::string name = std::string(render::partIdTechniques()[t]->name) +
                                     (flip ? " flip" : "") + " on " + view;
            size_t wrong = 0;
            for (size_t i : footprint) {
                const bool right =
                    flip ? r.ids[i] == expected.ids[i] && colorAt(r, i) == colorAt(expected, i)
                         : r.ids[i] == c.face && colorAt(r, i) == colorAt(alone, i);
                if (!right && wrong++ < 3)
                    ADD_FAILURE() << name << ": pixel " << i % W << "," << i / W << " shows "
                                  << r.ids[i] << " grey " << int(colorAt(r, i).x);
            }
            EXPECT_EQ(wrong, 0u) << name << ": of " << footprint.size() << " pixels";
            if (flip) {
                EXPECT_EQ(r.ids, expected.ids) << name;
            }
        }
    }
}

// From along the face's normal and from off it.
void expectFaceWholeOrGone(const char* model) {
    REQUIRE_DATA(model);
    FaceCut c = largestPlanarFace(model);
    for (double tilt : {0.0, 0.4}) {
        c.camera = cameraOn(c, tilt);
        expectFaceWholeOrGone(c, std::string(model) + (tilt > 0.0 ? ", tilted" : ""));
    }
}

} // namespace

TEST(SectionAtFace, MotorFaceIsWholeOrGoneWithFlip) {
    expectFaceWholeOrGone("/usr/share/opencascade/data/occ/Motor-c.brep");
}

TEST(SectionAtFace, LinkrodsFaceIsWholeOrGoneWithFlip) {
    expectFaceWholeOrGone("/usr/share/opencascade/data/step/linkrods.step");
}
