// xray.h - X-ray: the parts outside the selection drawn translucent, so that inner selected
// parts show and can be picked and measured in place. One concept over the hidden parts: for
// the scene pass the parts outside the selection are hidden (so the ID image, picks, culling,
// box selection and edges see only the selection, drawn by the technique as ever), and one
// more pass in the scene pass's last render pass draws them over the picture, translucent,
// with the floor's shaders in push mode (the scene's vertex path): depth tested against the
// selection, no depth, no ID, no pick written. With nothing selected X-ray changes nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "render/settings.h"
#include "scene/part_set.h"
#include "scene/scene.h"

namespace render {

// The parts the scene pass leaves out (Renderer::setHidden) and those X-ray's pass draws
// translucent (Renderer::setTranslucent): with X-ray on and something selected, the hidden
// parts and everything outside the selection, and of those the ones not hidden; else just the
// hidden parts and nothing translucent.
struct XrayParts {
    scene::PartSet hidden, translucent;
};
XrayParts xrayParts(bool on, const scene::PartSet& selected, const scene::PartSet& hidden);

// One draw of X-ray's pass: a run of consecutive translucent parts of one object, as the
// scene's index buffer holds them.
struct TranslucentDraw {
    uint32_t object = 0;
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    int32_t vertexOffset = 0;
};
// The fewest draws that cover `parts` in `scene`: parts next to each other in an object's
// geometry, or with only empty parts between them, are one draw; empty parts get none.
std::vector<TranslucentDraw> translucentDraws(const scene::Scene& scene,
                                              const scene::PartSet& parts);

// The pipeline of X-ray's pass beside the scene pipeline `drawn`: the vertex floor (no-id)
// in push mode, translucent, at the same MSAA and with the same section cut.
PipelineKey translucentKey(const PipelineKey& drawn);

} // namespace render
