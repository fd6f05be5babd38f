// technique.cpp - the registry of techniques and per-draw modes.
#include "render/technique.h"

namespace render {
namespace {

template <typename Entry>
std::string namesOf(const std::vector<Entry>& entries) {
    std::string text;
    for (const auto& entry : entries) text += (text.empty() ? "" : ", ") + std::string(entry.name);
    return text;
}

template <typename Entry>
const Entry* findByName(const std::vector<Entry>& entries, const std::string& name) {
    for (const auto& entry : entries)
        if (name == entry.name) return &entry;
    return nullptr;
}

} // namespace

const std::vector<Technique>& techniques() {
    static const std::vector<Technique> list = {
        {"per-draw",
         "one draw per part; the draw carries the part index",
         "techniques/per_draw.glsl",
         {},
         scene::drawsPerPart},
    };
    return list;
}

const std::vector<DrawMode>& drawModes() {
    static const std::vector<DrawMode> list = {
        {"push", "push constants per draw; only what changed is pushed", {{"IDV_MODE_PUSH", "1"}}},
    };
    return list;
}

const Technique* findTechnique(const std::string& name) {
    return findByName(techniques(), name);
}
const DrawMode* findDrawMode(const std::string& name) {
    return findByName(drawModes(), name);
}
std::string techniqueNames() {
    return namesOf(techniques());
}
std::string drawModeNames() {
    return namesOf(drawModes());
}

} // namespace render
