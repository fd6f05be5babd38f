// draw_list.h - what a technique draws: the draw ranges, each draw's DrawData, and the bytes
// of the technique's ID buffer. Plain C++, built when the scene, technique or search batch
// changes; the renderer only uploads it.
#pragma once

#include <vector>

#include "render/settings.h"
#include "scene/part_data.h"
#include "shared.h"

namespace render {

// One draw call: a range of parts of one object's geometry (scene/part_data.h).
using DrawItem = scene::DrawRange;

// ceil(fraction * objects), clamped to [0, objects]. A product within 1/1000 of a whole
// number counts as that number, so float fractions such as 0.1f of 10 objects give 1, not 2.
size_t visibleObjectCount(float fraction, size_t objects);

struct DrawList {
    std::vector<DrawItem> ranges;
    std::vector<gpu::DrawData> data; // data[i].drawIndex == i
    std::vector<uint8_t> idBytes;    // the technique's ID buffer; empty for IdBuffer::None
};

// What a configuration costs, for --stats and the panel (no GPU needed).
struct RenderStats {
    size_t draws = 0;
    uint64_t triangles = 0; // drawn, over all draws
    uint32_t pipelines = 0;
    uint64_t idBufferBytes = 0; // the technique's ID data
    uint64_t perDrawBytes = 0;  // DrawData buffer (mdi modes)
    uint64_t indirectBytes = 0; // indirect commands and draw-index attribute (mdi modes)
    bool gsPassthrough = false; // the gs technique runs the passthrough form
};
RenderStats statsFor(const DrawList& list, const DrawMode& mode);

// The draws of `key`'s technique (and search batch) under `draws`.
DrawList buildDrawList(const scene::Scene& scene, const PipelineKey& key,
                       const DrawSettings& draws);

} // namespace render
