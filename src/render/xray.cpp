// xray.cpp - which parts X-ray hides and draws translucent, and the draws of its pass.
#include "render/xray.h"

namespace render {

XrayParts xrayParts(bool on, const scene::PartSet& selected, const scene::PartSet& hidden) {
    XrayParts parts{hidden, scene::PartSet(hidden.partCount())};
    if (!on || selected.empty()) return parts;
    parts.translucent = selected;
    parts.translucent.invert();
    parts.hidden.insertAll(parts.translucent);
    parts.translucent.eraseAll(hidden);
    return parts;
}

std::vector<TranslucentDraw> translucentDraws(const scene::Scene& scene,
                                              const scene::PartSet& parts) {
    std::vector<TranslucentDraw> draws;
    for (uint32_t o = 0; o < scene.objects.size(); ++o) {
        const scene::Object& object = scene.objects[o];
        const scene::Geometry& geometry = scene.geometries[object.geometry];
        if (!parts.anyIn(object.uniquePartOffset, geometry.partCount)) continue;
        bool open = false; // the last draw is this object's and ends at the part before
        for (uint32_t p = 0; p < geometry.partCount; ++p) {
            const scene::Part& part = scene.parts[geometry.firstPart + p];
            // An empty part draws nothing and breaks no run: its neighbours' triangles touch.
            if (part.empty()) continue;
            if (!parts.contains(object.uniquePartOffset + p)) {
                open = false;
                continue;
            }
            const uint32_t first = geometry.firstIndex + 3 * part.firstTriangle;
            // Parts lie in their geometry in order; a gap between two starts another draw.
            if (!open || draws.back().firstIndex + draws.back().indexCount != first)
                draws.push_back({o, first, 0, int32_t(geometry.firstVertex)});
            draws.back().indexCount += 3 * part.triangleCount;
            open = true;
        }
    }
    return draws;
}

PipelineKey translucentKey(const PipelineKey& drawn) {
    PipelineKey key;
    key.technique = &floorTechnique();
    key.mode = findDrawMode("push");
    key.msaa = drawn.msaa;
    key.clear = drawn.clear; // the pass it draws in
    key.section = drawn.section;
    key.translucent = true;
    key.overVisibility = drawn.technique->isVisibilityBuffer();
    return key.effective(false);
}

} // namespace render
