// draw_list.h - what a technique draws: the draw ranges, each draw's DrawData, and the bytes
// of the technique's ID buffer. Plain C++, built when the scene, technique or search batch
// changes; the renderer only uploads it.
#pragma once

#include <vector>

#include "render/technique.h"
#include "shared.h"

namespace render {

struct DrawOptions {
    uint32_t searchBatch = 16;
    // Order draws by geometry, then material, so consecutive draws share state.
    bool sortByGeometryAndMaterial = true;
};

struct DrawList {
    std::vector<DrawItem> ranges;
    std::vector<gpu::DrawData> data; // data[i].drawIndex == i
    std::vector<uint8_t> idBytes;    // the technique's ID buffer; empty for IdBuffer::None
};

// What a configuration costs, for --stats and the panel (no GPU needed).
struct RenderStats {
    size_t draws = 0;
    uint32_t pipelines = 0;
    uint64_t idBufferBytes = 0; // the technique's ID data
    uint64_t perDrawBytes = 0;  // DrawData buffer (mdi modes)
    uint64_t indirectBytes = 0; // indirect commands and draw-index attribute (mdi modes)
    bool gsPassthrough = false; // the gs technique runs the passthrough form
};
RenderStats statsFor(const DrawList& list, const DrawMode& mode);

DrawList buildDrawList(const scene::Scene& scene, const Technique& technique,
                       const DrawOptions& options);

} // namespace render
