// draw_list.h - what a technique draws: the draw ranges, each draw's DrawData, and the bytes
// of the technique's ID buffer. Plain C++, built when the scene, technique or search batch
// changes; the renderer only uploads it.
#pragma once

#include <optional>
#include <vector>

#include "render/settings.h"
#include "scene/meshlets.h"
#include "scene/part_data.h"
#include "scene/part_vertices.h"
#include "shared.h"

namespace render {

// One draw call: a range of parts of one object's geometry (scene/part_data.h).
using DrawItem = scene::DrawRange;

// ceil(fraction * objects), clamped to [0, objects]. A product within 1/1000 of a whole
// number counts as that number, so float fractions such as 0.1f of 10 objects give 1, not 2.
size_t visibleObjectCount(float fraction, size_t objects);

struct DrawList {
    // Full detail's draws, then, where the list has levels of detail, those of each coarser
    // level in turn (DrawItem::level): the cull pass draws one level of each object, and
    // whatever draws without its lists (push mode) the first fullDetailDraws.
    std::vector<DrawItem> ranges;
    size_t fullDetailDraws = 0;
    std::vector<gpu::DrawData> data; // data[i].drawIndex == i
    std::vector<uint8_t> idBytes;    // the technique's ID buffer; empty for IdBuffer::None
    // Primitives::Meshlets: mesh workgroups of each draw (its geometry's meshlet count).
    std::vector<uint32_t> meshletCounts;
    // The visibility buffer (shared_visibility.h): what its mesh shader and shading pass read
    // of each draw, and the draw of each meshlet slot of payloads.
    std::vector<gpu::VisibilityDraw> visibilityDraws;
    std::vector<uint32_t> visibilityBlocks;
};

// The geometry some techniques draw instead of the scene's indices: its per-geometry
// layout and part indices are all the draw list reads (the GPU copies are the renderer's).
struct DerivedPrimitives {
    const scene::PartVertices* partVertices = nullptr; // Primitives::PartVertices
    const scene::Meshlets* meshlets = nullptr;         // Primitives::Meshlets
    uint64_t bytes = 0;        // of the derived geometry on the GPU, for the stats
    uint64_t meshletCount = 0; // likewise (the meshlets themselves are the GPU's)
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
    // Primitives::PartVertices: vertices duplicated so every triangle can lead with its
    // part, and their bytes; the rotated copy of the geometry as a whole is geometryBytes.
    uint64_t addedVertices = 0;
    uint64_t addedVertexBytes = 0;
    uint64_t meshlets = 0;      // Primitives::Meshlets
    uint64_t geometryBytes = 0; // derived geometry drawn instead of the scene's indices
};
// Bytes of derived geometry on the GPU: part vertices drawn by vertex-fs (vertices and
// rotated indices), meshlets (gpu::Meshlet each, a uint per meshlet vertex and triangle)
// and, for meshlets over part vertices, those vertices.
uint64_t derivedBytes(const scene::PartVertices* partVertices, const scene::Meshlets* meshlets);

// The derived geometry `technique` draws, built on the CPU (for --stats without a device).
struct DerivedGeometry {
    std::optional<scene::PartVertices> partVertices;
    std::optional<scene::Meshlets> meshlets;
    DerivedPrimitives view() const;
};
DerivedGeometry buildDerivedGeometry(const scene::Scene& scene, const Technique& technique);

RenderStats statsFor(const DrawList& list, const DrawMode& mode,
                     const DerivedPrimitives& derived = {});

// The draws of `key`'s technique (and search batch) under `draws`, with every level of detail
// the scene has where `levels`. `derived` must hold what the technique's Primitives need
// (std::invalid_argument otherwise).
DrawList buildDrawList(const scene::Scene& scene, const PipelineKey& key, const DrawSettings& draws,
                       const DerivedPrimitives& derived = {}, bool levels = false);

} // namespace render
