// test_census.cpp - the visibility census on lavapipe, over a scene whose hidden parts are
// known by construction (census_scene.h): exactly those parts are never seen; the GPU's
// totals equal a count over the same views' ID images read back; the ID images agree with
// a CPU ray cast; hidden parts and a section are respected; the exterior written as glTF
// loads back with the seen parts.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>

#include "app/census.h"
#include "app/census_run.h"
#include "app/offscreen.h"
#include "app/scene_source.h"
#include "census_scene.h"
#include "render/technique.h"
#include "scene/exterior.h"
#include "scene/gltf/gltf_writer.h"
#include "scene/raycast.h"
#include "test_support.h"

namespace {

constexpr uint32_t kViews = 42, kSize = 128;

// The census's own choice on a device with mesh shaders (app/census.cpp), as lavapipe 25 is;
// RespectsHiddenPartsAndTheSection draws with the registries' first rows instead.
app::Options censusOptions(const char* technique = "visbuffer-compute",
                           const char* mode = "mdi-baseinstance") {
    app::Options o = testing_support::headlessOptions(kSize, kSize);
    o.census = {kViews, kSize};
    o.live.render.pipeline.technique = render::findTechnique(technique);
    o.live.render.pipeline.mode = render::findDrawMode(mode);
    return o;
}

struct Drawn {
    scene::Census census;
    std::vector<std::vector<uint32_t>> ids; // per view
    std::vector<scene::Camera> cameras;     // per view
    uint32_t validationMessages = 0;
};

// The census drawn view by view as `idview --census` draws it, with every view's ID image
// read back beside it.
Drawn drawWithImages(const app::Options& o, const scene::Scene& s, const scene::PartSet& hidden) {
    Drawn drawn;
    vk::Instance instance({true, {}, false});
    {
        app::Offscreen rig(instance, o);
        app::uploadScene(rig.renderer, "census scene", s, o.live.render);
        rig.renderer.setHidden(hidden);
        rig.renderer.setSelection(scene::PartSet(s.uniquePartCount()));
        const render::CensusPass pass(rig.device, rig.compiler, rig.renderer.driverCache());
        app::CensusRun run(rig.device, rig.renderer, pass, s.uniquePartCount(), s.bounds(),
                           o.census, 0.0f);
        std::vector<std::unique_ptr<app::Readback>> images;
        for (uint32_t v = 0; v < run.views(); ++v) {
            images.push_back(std::make_unique<app::Readback>(rig.device, rig.extent));
            const app::Readback& image = *images.back();
            run.step(rig.slots, v, [&](VkCommandBuffer cmd) { image.record(cmd, run.targets()); });
            drawn.cameras.push_back(run.camera(v));
        }
        rig.slots.finish();
        drawn.census = run.result();
        for (const auto& image : images) drawn.ids.push_back(image->idValues());
    }
    drawn.validationMessages = instance.validationMessages();
    return drawn;
}

class Census : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        made_ = std::make_unique<testing_support::CensusScene>(testing_support::makeCensusScene());
        drawn_ = std::make_unique<Drawn>(drawWithImages(
            censusOptions(), made_->scene, scene::PartSet(made_->scene.uniquePartCount())));
    }
    static void TearDownTestSuite() {
        drawn_.reset();
        made_.reset();
    }
    static std::unique_ptr<testing_support::CensusScene> made_;
    static std::unique_ptr<Drawn> drawn_;
};
std::unique_ptr<testing_support::CensusScene> Census::made_;
std::unique_ptr<Drawn> Census::drawn_;

uint32_t directionsWithZAbove(double z) {
    uint32_t n = 0;
    for (const glm::dvec3& d : scene::censusDirections(kViews)) n += d.z > z;
    return n;
}

TEST_F(Census, NeverSeesExactlyTheEnclosedParts) {
    const scene::Scene& s = made_->scene;
    const scene::Census& census = drawn_->census;
    EXPECT_EQ(drawn_->validationMessages, 0u);
    ASSERT_EQ(census.parts.size(), s.uniquePartCount());
    EXPECT_EQ(census.views, kViews);
    const scene::PartSet none(s.uniquePartCount());
    for (uint32_t part = 0; part < s.uniquePartCount(); ++part)
        EXPECT_EQ(census.seen(part), !made_->neverSeen.contains(part)) << "part " << part;
    const scene::PartSet never = scene::neverSeenParts(s, census, none);
    EXPECT_EQ(never.ids(), std::vector<uint32_t>(made_->neverSeen.begin(), made_->neverSeen.end()));
    const scene::CensusSummary sum = scene::summarize(s, census, none);
    EXPECT_EQ(sum.partsNeverSeen, made_->neverSeen.size());
    EXPECT_EQ(sum.objectsNeverSeen, 1u); // the cube inside the closed box
    EXPECT_EQ(sum.objectTrianglesNeverSeen, 12u);
    EXPECT_EQ(sum.trianglesNeverSeen, 2u * made_->neverSeen.size());
}

// Down the 2 x 2 shaft, 2 deep above the pin: within 30 degrees of +z some of the pin's top
// shows whichever way the view leans; from 54.7 degrees (the diagonal's limit) none does.
TEST_F(Census, SeesThePinOnlyDownItsShaft) {
    const uint32_t views = drawn_->census.parts[made_->pinTop].views;
    EXPECT_GE(views, directionsWithZAbove(std::cos(glm::radians(30.0))));
    EXPECT_LE(views, directionsWithZAbove(1.0 / std::sqrt(3.0)));
    EXPECT_GT(views, 0u);
}

// An independent count over the very images the census counted: pixels, views and the
// largest view of every part, exactly.
TEST_F(Census, TotalsEqualACountOverTheViewsImages) {
    const uint32_t parts = made_->scene.uniquePartCount();
    std::vector<scene::CensusPart> expected(parts);
    for (const std::vector<uint32_t>& ids : drawn_->ids) {
        std::vector<uint32_t> view(parts, 0);
        for (uint32_t id : ids)
            if (id < parts) ++view[id];
        for (uint32_t p = 0; p < parts; ++p) {
            if (view[p] == 0) continue;
            expected[p].pixels += view[p];
            expected[p].views += 1;
            expected[p].largest = std::max(expected[p].largest, view[p]);
        }
    }
    for (uint32_t p = 0; p < parts; ++p) {
        const scene::CensusPart& got = drawn_->census.parts[p];
        EXPECT_EQ(got.pixels, expected[p].pixels) << "part " << p;
        EXPECT_EQ(got.views, expected[p].views) << "part " << p;
        EXPECT_EQ(got.largest, expected[p].largest) << "part " << p;
    }
}

// A sample of views: every pixel whose four neighbours show the same thing (a part's
// inside, or background) shows what a ray through its centre meets first.
TEST_F(Census, ImagesAgreeWithARayCast) {
    const scene::RayCaster caster(made_->scene);
    size_t checked = 0, wrong = 0;
    for (uint32_t v : {0u, 13u, 21u, 34u, 41u}) {
        const std::vector<uint32_t>& ids = drawn_->ids[v];
        const glm::dmat4 viewProj = drawn_->cameras[v].viewProjection(1.0);
        for (uint32_t y = 1; y + 1 < kSize; ++y)
            for (uint32_t x = 1; x + 1 < kSize; ++x) {
                const size_t i = size_t(y) * kSize + x;
                const uint32_t id = ids[i];
                if (ids[i - 1] != id || ids[i + 1] != id || ids[i - kSize] != id ||
                    ids[i + kSize] != id)
                    continue;
                const auto hit = caster.cast(
                    scene::pixelRay(viewProj, glm::dvec2(kSize), glm::dvec2(x, y) + 0.5));
                const uint32_t cast = hit ? hit->uniquePartId : gpu::BACKGROUND_ID;
                ++checked;
                if (cast != id && wrong++ < 5)
                    ADD_FAILURE() << "view " << v << " pixel " << x << "," << y << ": image " << id
                                  << ", ray cast " << cast;
            }
    }
    EXPECT_GT(checked, 30000u);
    EXPECT_EQ(wrong, 0u);
}

// Hiding the closed box, or cutting it open, shows the cube inside; the hidden box counts
// as hidden, not as never seen.
TEST_F(Census, RespectsHiddenPartsAndTheSection) {
    const scene::Scene& s = made_->scene;
    const scene::Object& shell = s.objects[made_->shell];
    const scene::Object& inner = s.objects[made_->inner];
    scene::PartSet hidden(s.uniquePartCount());
    for (uint32_t p = 0; p < 6; ++p) hidden.insert(shell.uniquePartOffset + p);
    const scene::Census opened =
        drawWithImages(censusOptions("per-draw", "push"), s, hidden).census;
    for (uint32_t p = 0; p < 6; ++p) {
        EXPECT_TRUE(opened.seen(inner.uniquePartOffset + p)) << p;
        EXPECT_FALSE(opened.seen(shell.uniquePartOffset + p)) << p;
    }
    const scene::CensusSummary sum = scene::summarize(s, opened, hidden);
    EXPECT_EQ(sum.partsHidden, 6u);
    EXPECT_EQ(sum.partsNeverSeen, made_->neverSeen.size() - 6);

    app::Options cut = censusOptions("per-draw", "push");
    // Keeps y <= 2: the box's +y face (y = 4) goes, the inner cube (y from -1 to 1) stays.
    cut.live.render.section.planes[0] = scene::axisPlane(1, 2.0);
    const scene::Census halved = drawWithImages(cut, s, scene::PartSet(s.uniquePartCount())).census;
    EXPECT_TRUE(halved.seen(inner.uniquePartOffset + 2));  // the inner cube's +y face
    EXPECT_FALSE(halved.seen(inner.uniquePartOffset + 3)); // its -y face, behind the cube
    EXPECT_FALSE(halved.seen(shell.uniquePartOffset + 2));
}

// The seen parts written as glTF load back as exactly those parts, with their objects' names.
TEST_F(Census, ExteriorWrittenAsGltfLoadsBackWithTheSeenParts) {
    const scene::Scene& s = made_->scene;
    const scene::PartSet seen = scene::seenParts(drawn_->census);
    const auto path = std::filesystem::temp_directory_path() / "idview-census-exterior.glb";
    scene::writeGlb(scene::keptParts(s, seen), path.string());
    app::SceneSettings source;
    source.model = path.string();
    const app::LoadedScene back = app::loadScene(source);
    EXPECT_EQ(back.scene.uniquePartCount(), seen.size());
    const std::vector<uint8_t> objects = scene::seenObjects(s, drawn_->census);
    std::vector<std::string> names;
    for (size_t o = 0; o < s.objects.size(); ++o)
        if (objects[o]) names.push_back(s.objects[o].name);
    ASSERT_EQ(back.scene.objects.size(), names.size());
    for (size_t o = 0; o < names.size(); ++o) EXPECT_EQ(back.scene.objects[o].name, names[o]);
    EXPECT_EQ(back.scene.drawnTriangleCount(),
              s.drawnTriangleCount() - 2 * made_->neverSeen.size());
    std::filesystem::remove(path);
}

} // namespace
