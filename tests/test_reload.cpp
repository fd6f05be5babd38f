// test_reload.cpp - shaders reloaded from disk while running (the viewer's R): an edit takes
// effect, in the scene pass, the culling and the visibility buffer's shading pass; a broken
// shader reports file and line and the last good pipeline keeps drawing.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "app/offscreen.h"
#include "app/scene_source.h"
#include "image_compare.h"
#include "render/technique.h"
#include "test_support.h"
#include "vk/shader_compiler.h"

namespace {

namespace fs = std::filesystem;

using testing_support::renderIds;
using testing_support::sameIds;

void replaceInFile(const fs::path& path, const std::string& from, const std::string& to) {
    std::ifstream in(path);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from << " not in " << path;
    text.replace(at, from.size(), to);
    std::ofstream(path) << text;
}

// Options drawing the tiles scene (its parts cover known pixels at an identity camera) at
// 64x48 with the shaders of a fresh copy in a folder of its own, `name` plus the process ID.
app::Options copiedShaders(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / (name + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::copy(IDVIEW_SOURCE_SHADER_DIR, dir, fs::copy_options::recursive);
    app::Options o;
    o.live.scene.builtin = "tiles";
    o.width = 64;
    o.height = 48;
    o.shaderDir = dir.string();
    return o;
}

size_t covered(const std::vector<uint32_t>& ids) {
    return ids.size() - size_t(std::count(ids.begin(), ids.end(), gpu::BACKGROUND_ID));
}

TEST(ShaderReload, EditsTakeEffectAndBrokenShadersKeepTheLastGoodPipeline) {
    const app::Options o = copiedShaders("idview-reload-");
    const fs::path dir = o.shaderDir;
    const app::LoadedScene loaded = app::loadScene(o.live.scene);
    // The last part-ID technique with a lookup file of its own whose scene pass writes the
    // part (a visibility buffer writes a payload, and its shading pass the part), in an
    // indirect mode.
    const render::Technique* technique = nullptr;
    for (const render::Technique* t : render::partIdTechniques())
        if (t->lookupFile && !t->isVisibilityBuffer()) technique = t;
    ASSERT_NE(technique, nullptr);
    vk::Instance instance({true, {}});
    {
        app::Offscreen rig(instance, o);
        rig.renderer.setScene(loaded.scene,
                              testing_support::settingsFor(*technique, render::drawModes().back()));
        uint64_t frame = 0;
        const auto before = renderIds(rig, frame);
        ASSERT_GT(covered(before), 0u);

        // A valid edit: every ID one higher, visible after the reload only.
        replaceInFile(dir / "scene.frag", "outPartId = uniquePartId;",
                      "outPartId = uniquePartId + 1u;");
        EXPECT_TRUE(sameIds(renderIds(rig, frame), before, o.width)); // not reloaded yet
        rig.renderer.reloadShaders();
        const auto edited = renderIds(rig, frame);
        for (size_t i = 0; i < before.size(); ++i) {
            if (before[i] != gpu::BACKGROUND_ID) {
                ASSERT_EQ(edited[i], before[i] + 1) << i;
            }
        }

        // A broken technique file: the error names file and line; the edited pipeline stays.
        const fs::path broken = dir / technique->lookupFile;
        std::ofstream(broken, std::ios::app) << "\nthis is not GLSL;\n";
        try {
            rig.renderer.reloadShaders();
            FAIL() << "a broken shader reloaded";
        } catch (const vk::ShaderError& e) {
            EXPECT_NE(std::string(e.what()).find(broken.filename().string() + ":"),
                      std::string::npos)
                << e.what();
        }
        EXPECT_TRUE(sameIds(renderIds(rig, frame), edited, o.width));
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
    fs::remove_all(dir);
}

// An edit of the culling shaders takes effect at once, in a still view whose history would
// otherwise draw what the old shaders let through.
TEST(ShaderReload, CullingEditsTakeEffectInAStillView) {
    const app::Options o = copiedShaders("idview-reload-cull-");
    const fs::path dir = o.shaderDir;
    const app::LoadedScene loaded = app::loadScene(o.live.scene);
    vk::Instance instance({true, {}});
    {
        app::Offscreen rig(instance, o);
        const render::Technique* vertexFs = render::findTechnique("vertex-fs");
        ASSERT_NE(vertexFs, nullptr);
        render::RenderSettings settings =
            testing_support::settingsFor(*vertexFs, render::drawModes().back());
        settings.culling.mode = render::CullMode::Occlusion;
        rig.renderer.setScene(loaded.scene, settings);
        uint64_t frame = 0;
        std::vector<uint32_t> ids;
        for (int i = 0; i < 4; ++i) ids = renderIds(rig, frame);
        ASSERT_GT(covered(ids), 0u);

        // Every box outside the frustum: once culled again, nothing is drawn.
        replaceInFile(dir / "cull.glsl", "view.outside = outsideAll != 0u;",
                      "view.outside = true;");
        rig.renderer.reloadShaders();
        for (uint32_t id : renderIds(rig, frame)) ASSERT_EQ(id, gpu::BACKGROUND_ID);
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
    fs::remove_all(dir);
}

// The visibility buffer's parts come from its shading pass: an edit there takes effect too.
TEST(ShaderReload, VisibilityShadingEditsTakeEffect) {
    const app::Options o = copiedShaders("idview-reload-vis-");
    const fs::path dir = o.shaderDir;
    const app::LoadedScene loaded = app::loadScene(o.live.scene);
    vk::Instance instance({true, {}});
    {
        app::Offscreen rig(instance, o);
        const render::Technique* visbuffer = render::findTechnique("visbuffer");
        ASSERT_NE(visbuffer, nullptr);
        rig.renderer.setScene(loaded.scene,
                              testing_support::settingsFor(*visbuffer, render::drawModes().back()));
        uint64_t frame = 0;
        const auto before = renderIds(rig, frame);
        ASSERT_GT(covered(before), 0u);
        replaceInFile(dir / "visibility.comp", "uint id = object.uniquePartOffset + localPart;",
                      "uint id = object.uniquePartOffset + localPart + 1u;");
        rig.renderer.reloadShaders();
        const auto edited = renderIds(rig, frame);
        for (size_t i = 0; i < before.size(); ++i) {
            if (before[i] != gpu::BACKGROUND_ID) {
                ASSERT_EQ(edited[i], before[i] + 1) << i;
            }
        }
    }
    EXPECT_EQ(instance.validationMessages(), 0u);
    fs::remove_all(dir);
}

} // namespace
