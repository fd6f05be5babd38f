// generator.cpp - the built-in procedural scenes.
#include "scene/procedural/generator.h"

#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

#include "scene/mesh_builder.h"

namespace scene {

static uint32_t boltGeometry(Scene& scene) {
    MeshBuilder mb;
    mb.addPrism({0, 0}, 0.10f, 0.0f, 0.07f, 6, false);   // hex head: 6 flanks + 2 caps
    mb.addPrism({0, 0}, 0.055f, -0.30f, 0.0f, 16, true); // shank: one smooth mantle + caps
    return mb.finish(scene, "bolt M10");
}

Scene makeAssembly() {
    Scene scene;
    const uint32_t steel = addMaterial(scene, "steel", {0.62f, 0.64f, 0.68f, 1});
    const uint32_t paint = addMaterial(scene, "blue paint", {0.16f, 0.32f, 0.62f, 1});
    const uint32_t brass = addMaterial(scene, "brass", {0.78f, 0.62f, 0.28f, 1});

    MeshBuilder mb;
    mb.addBox({0, 0, 0}, {4.0f, 3.0f, 0.2f});
    const uint32_t plate = mb.finish(scene, "plate 4x3");
    mb.addPrism({0, 0}, 0.18f, 0.0f, 1.5f, 24, true);
    const uint32_t column = mb.finish(scene, "column");
    const uint32_t bolt = boltGeometry(scene);
    mb.addBox({0, 0, 0.3f}, {0.12f, 0.8f, 0.6f});
    mb.addBox({0.21f, 0, 0.03f}, {0.3f, 0.8f, 0.06f});
    const uint32_t bracket = mb.finish(scene, "angle bracket");

    // Names: "base plate", "top plate", "column #1".."#4"; the bolts ("bolt M10 #1".."#24")
    // and brackets ("angle bracket #1", "#2") sit on the top plate, which their paths say.
    const std::string root = "assembly", top = joinPath(root, "top plate");
    NameCounter names;
    const glm::mat4 identity(1.0f);
    addNamedObject(scene, plate, paint, identity, root, "base plate");
    addNamedObject(scene, plate, paint, glm::translate(identity, {0, 0, 1.7f}), root, "top plate");
    for (float x : {-1.6f, 1.6f})
        for (float y : {-1.1f, 1.1f})
            names.add(scene, column, steel, glm::translate(identity, {x, y, 0.1f}), root);
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 4; ++j)
            names.add(scene, bolt, brass,
                      glm::translate(identity, {-1.25f + 0.5f * i, -0.9f + 0.6f * j, 1.8f}), top);
    names.add(scene, bracket, steel, glm::translate(identity, {-1.9f, 0, 1.8f}), top);
    names.add(scene, bracket, steel,
              glm::rotate(glm::translate(identity, {1.9f, 0, 1.8f}), float(M_PI), {0, 0, 1}), top);
    validate(scene);
    return scene;
}

Scene makeTiles() {
    Scene scene;
    const uint32_t grey = addMaterial(scene, "grey", {0.5f, 0.5f, 0.5f, 1});
    MeshBuilder mb;
    // 4 x 3 tiles of 0.8 with a 0.2 gap: the sheet spans x 0..3.8, y 0..2.8.
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 4; ++col) {
            float x = col * 1.0f, y = row * 1.0f;
            glm::vec3 quad[4] = {
                {x, y, 0}, {x + 0.8f, y, 0}, {x + 0.8f, y + 0.8f, 0}, {x, y + 0.8f, 0}};
            mb.addFlatFace(quad);
        }
    const uint32_t sheet = mb.finish(scene, "tile sheet");
    glm::vec3 back[4] = {{-4.5f, -2, 0}, {4.5f, -2, 0}, {4.5f, 5, 0}, {-4.5f, 5, 0}};
    mb.addFlatFace(back);
    const uint32_t plate = mb.finish(scene, "back plate");

    // Names: "tile sheet #1" (left), "tile sheet #2" (right), "back plate"; paths "tiles/...".
    NameCounter names;
    const glm::mat4 identity(1.0f);
    names.add(scene, sheet, grey, glm::translate(identity, {-4.0f, -0.4f, 0}), "tiles");
    names.add(scene, sheet, grey, glm::translate(identity, {0.2f, -0.4f, 0}), "tiles");
    addNamedObject(scene, plate, grey, glm::translate(identity, {0, 0, -1.0f}), "tiles",
                   "back plate");
    validate(scene);
    return scene;
}

Camera tilesCamera() {
    Camera camera;
    camera.eye = {0.0f, 1.0f, 12.0f};
    camera.target = {0.0f, 1.0f, 0.0f};
    camera.up = {0, 1, 0};
    camera.fovY = glm::radians(45.0f);
    camera.nearPlane = 1.0f;
    camera.farPlane = 100.0f;
    return camera;
}

const std::vector<std::string>& sceneNames() {
    static const std::vector<std::string> names = {"assembly", "tiles"};
    return names;
}

Scene makeScene(const std::string& name) {
    if (name == "assembly") return makeAssembly();
    if (name == "tiles") return makeTiles();
    throw std::invalid_argument("unknown scene '" + name + "'");
}

} // namespace scene
