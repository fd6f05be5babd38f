// test_cad_closed_render.cpp - no background shows through a closed CAD model, on lavapipe
// with validation on: the closed occt-misc samples (closed_cad_files.h), every level of detail
// side by side, at two sizes and from several sides.
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <sstream>

#include "app/headless.h"
#include "app/scene_source.h"
#include "closed_cad_files.h"
#include "scene/camera_path.h"
#include "scene/lod.h"
#include "scene/raycast.h"
#include "test_data.h"
#include "test_support.h"

namespace {

// Whether one object's triangles cover the pixel's centre on all four sides, by the CPU's ray
// cast 0.02 pixel from it diagonally: background there shows through a seam of that object
// (where the centre ray itself hits, the GPU missed a covered sample; where it misses too, the
// mesh has a sliver less than 0.04 pixel wide there). Enclosed background pixels that fail
// this are openings of the model or between objects: the tip of a notch thinner than a pixel
// (the claw of hammer.brep, whose mesh is closed, shows one or two at 1280x720, 2560x1440 and
// 3840x2160 alike) or two copies side by side whose outlines almost touch. Drawn with one face
// of each shape collapsed (the CPU casting against the whole), 3,799 pixels over the files
// fail this test.
bool covered(const scene::RayCaster& caster, const glm::mat4& viewProj, uint32_t w, uint32_t h,
             size_t pixel) {
    constexpr float d = 0.02f;
    const glm::vec2 centre(float(pixel % w) + 0.5f, float(pixel / w) + 0.5f);
    std::optional<uint32_t> object;
    for (glm::vec2 side :
         {glm::vec2(-d, -d), glm::vec2(d, -d), glm::vec2(-d, d), glm::vec2(d, d)}) {
        const auto hit = caster.cast(scene::pixelRay(viewProj, glm::vec2(w, h), centre + side));
        if (!hit || (object && *object != hit->object)) return false;
        object = hit->object;
    }
    return true;
}

// The model's copy k drawn at level of detail k (geometryAtLevel), side by side on a grid.
app::LoadedScene everyLevelSideBySide(const std::string& path) {
    app::SceneSettings source;
    source.model = path;
    source.lodLevels = scene::maxLevels;
    source.copies = scene::maxLevels;
    app::LoadedScene loaded = app::loadScene(source);
    const size_t perCopy = loaded.scene.objects.size() / scene::maxLevels;
    for (size_t i = 0; i < loaded.scene.objects.size(); ++i) {
        scene::Object& o = loaded.scene.objects[i];
        o.geometry = scene::geometryAtLevel(loaded.scene, o.geometry, uint32_t(i / perCopy));
    }
    scene::validate(loaded.scene);
    return loaded;
}

} // namespace

// Every closed sample with its levels side by side, orbited in a few frames at two sizes: no
// background pixel enclosed by the parts where the triangles cover it.
TEST(CadClosedSolids, NoBackgroundShowsThroughAClosedModel) {
    const std::vector<std::string> files = testing_support::closedCadFiles();
    ASSERT_FALSE(files.empty()) << testing_support::missingData(testing_support::kOcctData);
    constexpr uint32_t frames = 3;
    for (const std::string& path : files) {
        const app::LoadedScene loaded = everyLevelSideBySide(path);
        const scene::RayCaster caster(loaded.scene);
        for (auto [w, h] : {std::pair<uint32_t, uint32_t>{1280, 720}, {480, 270}}) {
            app::Options o = testing_support::headlessOptions(w, h, frames);
            o.cameraPath = scene::CameraPath::Orbit;
            o.keepEveryFrame = true;
            const float aspect = float(w) / float(h);
            const scene::Camera start = app::initialCamera(loaded, aspect);
            const auto r = app::renderHeadless(o, loaded.scene, start);
            EXPECT_EQ(r.validationMessages, 0u) << path;
            ASSERT_EQ(r.frames.size(), frames) << path;
            for (uint32_t f = 0; f < frames; ++f) {
                const scene::Camera camera =
                    scene::cameraOnPath(o.cameraPath, start, loaded.scene.bounds(), f, frames);
                const glm::dmat4 viewProj = camera.viewProjection(aspect);
                const std::vector<size_t> enclosed =
                    testing_support::enclosedBackground(r.frames[f].ids, w, h);
                std::ostringstream cracks;
                size_t count = 0;
                for (size_t pixel : enclosed)
                    if (covered(caster, viewProj, w, h, pixel) && ++count <= 8)
                        cracks << " (" << pixel % w << "," << pixel / w << ")";
                EXPECT_EQ(count, 0u) << path << " " << w << "x" << h << " frame " << f << " of "
                                     << enclosed.size() << " enclosed:" << cracks.str();
            }
        }
    }
}
