// technique.h - the part-ID techniques and per-draw modes as data. Adding a technique means
// one entry in techniques() (technique.cpp), its GLSL file in shaders/techniques/, and its
// name in the test lists; nothing else switches on technique names.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "scene/part_data.h"

namespace render {

// One draw call: a range of parts of one object's geometry (scene/part_data.h).
using DrawItem = scene::DrawRange;

struct Technique {
    const char* name;        // as the CLI spells it
    const char* description; // one line for --list-renderers and the panel
    const char* shaderFile;  // the file scene.frag includes as "technique.glsl"
    std::vector<std::pair<std::string, std::string>> defines;
    // How the technique splits the scene into draws.
    std::vector<DrawItem> (*buildDrawList)(const scene::Scene& scene);
};

// How per-draw parameters reach the shaders.
struct DrawMode {
    const char* name;
    const char* description;
    std::vector<std::pair<std::string, std::string>> defines;
};

const std::vector<Technique>& techniques();
const std::vector<DrawMode>& drawModes();

// nullptr when there is no such name.
const Technique* findTechnique(const std::string& name);
const DrawMode* findDrawMode(const std::string& name);

// "a, b, c": for usage text and error messages.
std::string techniqueNames();
std::string drawModeNames();

} // namespace render
