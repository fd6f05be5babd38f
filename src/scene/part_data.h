// part_data.h - what the part-ID techniques derive from a scene: per-triangle part indices,
// per-part triangle counts in search batches, per-part running triangle offsets, and the
// draw lists (per part, per object, per batch). Plain C++, computed once per scene.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace scene {

// One draw call: a contiguous range of parts of one object's geometry at one level of detail
// (scene/lod.h): `geometry` is the object's own at level 0, else that level's.
struct DrawRange {
    uint32_t object = 0;
    uint32_t geometry = 0;
    uint32_t level = 0;
    uint32_t firstPart = 0; // local part index within the geometry
    uint32_t partCount = 0;
    uint32_t firstIndex = 0; // into Scene::indices
    uint32_t indexCount = 0;
    int32_t vertexOffset = 0;
};

// The draws of every object at `level`: its own geometry at 0, else that level of it, and
// none for objects whose geometry has fewer levels. No draw holds empty parts (Part::empty)
// alone, so a geometry without triangles has none.
std::vector<DrawRange> drawsPerPart(const Scene& scene, uint32_t level = 0);
// All of the geometry's parts, empty ones at its ends included: the offset searches
// (bsearch-*, nsearch-*) index parts from the geometry's first.
std::vector<DrawRange> drawsPerObject(const Scene& scene, uint32_t level = 0);
// Up to searchCount consecutive parts of a geometry per draw, less the empty ones at the
// batch's ends.
std::vector<DrawRange> drawsPerBatch(const Scene& scene, uint32_t searchCount, uint32_t level = 0);

// Bytes per local part index for a geometry with this many parts: 1, 2 or 4.
uint32_t partIndexBytes(uint32_t partCount);

// Local part indices of some element of each geometry (its triangles, its vertices, its
// meshlet triangles), geometry after geometry. Each geometry's array uses its own element
// width and starts at a 4-byte aligned offset, so a shader can read it as uint8/16/32 from
// `base + offset` (shaders/techniques/packed_ids.glsl).
struct PackedPartIndices {
    struct Range {
        uint32_t byteOffset = 0;
        uint32_t elementBytes = 0;
    };
    std::vector<uint8_t> bytes;
    std::vector<Range> geometries; // indexed like Scene::geometries

    // Appends the next geometry's array: `count` values from `parts`, each below partCount.
    void append(const uint32_t* parts, size_t count, uint32_t partCount);
    uint32_t partOf(uint32_t geometry, uint32_t element) const;
};

// Local part index of every triangle (tri-fs, tri-gs).
using TrianglePartIds = PackedPartIndices;
TrianglePartIds buildTrianglePartIds(const Scene& scene);

// The local part of each triangle of geometry `g`, in triangle order.
std::vector<uint32_t> trianglePartsOf(const Scene& scene, uint32_t g);

// Triangle count of every part, geometry after geometry (geometryOffsets[g] is the first
// entry of geometry g), followed by searchCount - 1 zeros so a fixed-length loop of
// searchCount reads starting at any part stays inside the buffer.
struct PartTriangleCounts {
    std::vector<uint32_t> counts;
    std::vector<uint32_t> geometryOffsets;
};
PartTriangleCounts buildPartTriangleCounts(const Scene& scene, uint32_t searchCount);

// Running triangle offsets: for geometry g, partCount + 1 entries from geometryOffsets[g],
// 0, c0, c0 + c1, ..., triangleCount; part p holds triangles [o[p], o[p + 1]).
struct PartTriangleOffsets {
    std::vector<uint32_t> offsets;
    std::vector<uint32_t> geometryOffsets;
};
PartTriangleOffsets buildPartTriangleOffsets(const Scene& scene);

// Bytes of each ID buffer, for the stats and the panel.
struct IdDataBytes {
    uint64_t trianglePartIds = 0;
    uint64_t partTriangleCounts = 0;
    uint64_t partTriangleOffsets = 0;
};
IdDataBytes idDataBytes(const Scene& scene, uint32_t searchCount);

} // namespace scene
