// visibility_scenes.h - the scenes the visibility buffer's tests draw (test_visibility.cpp,
// test_compute_raster.cpp): the procedural small scene twice, 2CylinderEngine by components,
// a glTF whose parts share vertices, and an IGES file with a part per face, all with every
// level of detail built.
#pragma once

#include <filesystem>
#include <string>

#include "app/scene_source.h"
#include "scene/lod.h"
#include "shared_vertex_gltf.h"
#include "test_data.h"

namespace testing_support {

inline app::LoadedScene loadNamed(const std::string& name) {
    app::SceneSettings source;
    const char* engine =
        "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
    if (name == "small") {
        source.builtin = "procedural:preset=small,seed=1";
        source.copies = 2;
    } else if (name == "engine") {
        source.model = requiredData(engine);
        source.parts = scene::PartMode::Components;
    } else if (name == "shared-vertices") {
        source.model = testing_support::writeSharedVertexGltf(
                           std::filesystem::temp_directory_path() / "idview-visibility")
                           .string();
    } else {
        source.model =
            requiredData("/usr/share/opencascade/data/iges/bearing.iges"); // a part per face
    }
    source.lodLevels = scene::maxLevels;
    return app::loadScene(source);
}

} // namespace testing_support
