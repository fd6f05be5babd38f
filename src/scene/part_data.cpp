// part_data.cpp - derived per-part data and draw lists.
#include "scene/part_data.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace scene {
namespace {

DrawRange rangeOf(const Scene& scene, uint32_t object, uint32_t geometry, uint32_t firstPart,
                  uint32_t partCount) {
    const Geometry& g = scene.geometries[geometry];
    const Part& first = scene.parts[g.firstPart + firstPart];
    const Part& last = scene.parts[g.firstPart + firstPart + partCount - 1];
    const uint32_t triangles = last.firstTriangle + last.triangleCount - first.firstTriangle;
    return {object,        geometry,
            g.level,       firstPart,
            partCount,     g.firstIndex + 3 * first.firstTriangle,
            3 * triangles, static_cast<int32_t>(g.firstVertex)};
}

// Parts [first, first + count) of geometry `g` less the empty ones at either end: (first, 0)
// where all are empty.
std::pair<uint32_t, uint32_t> withoutEmptyEnds(const Scene& scene, uint32_t g, uint32_t first,
                                               uint32_t count) {
    const Part* parts = &scene.parts[scene.geometries[g].firstPart];
    uint32_t end = first + count;
    while (first < end && parts[first].empty()) ++first;
    while (end > first && parts[end - 1].empty()) --end;
    return {first, end - first};
}

// Calls perGeometry(object, geometry) for every object that has `level`.
template <typename PerGeometry>
std::vector<DrawRange> drawsOf(const Scene& scene, uint32_t level, PerGeometry&& perGeometry) {
    std::vector<DrawRange> draws;
    for (uint32_t o = 0; o < scene.objects.size(); ++o) {
        const uint32_t full = scene.objects[o].geometry;
        if (level == 0) {
            perGeometry(o, full, draws);
        } else if (scene.geometries[full].levels.size() >= level) {
            perGeometry(o, scene.geometries[full].levels[level - 1], draws);
        }
    }
    return draws;
}

} // namespace

std::vector<DrawRange> drawsPerPart(const Scene& scene, uint32_t level) {
    return drawsPerBatch(scene, 1, level);
}

std::vector<DrawRange> drawsPerObject(const Scene& scene, uint32_t level) {
    return drawsOf(scene, level, [&](uint32_t o, uint32_t g, std::vector<DrawRange>& draws) {
        if (scene.geometries[g].triangleCount > 0)
            draws.push_back(rangeOf(scene, o, g, 0, scene.geometries[g].partCount));
    });
}

std::vector<DrawRange> drawsPerBatch(const Scene& scene, uint32_t searchCount, uint32_t level) {
    if (searchCount == 0) throw std::invalid_argument("search batch must be at least 1");
    return drawsOf(scene, level, [&](uint32_t o, uint32_t g, std::vector<DrawRange>& draws) {
        const uint32_t parts = scene.geometries[g].partCount;
        for (uint32_t first = 0; first < parts; first += searchCount) {
            const auto [from, count] =
                withoutEmptyEnds(scene, g, first, std::min(searchCount, parts - first));
            if (count > 0) draws.push_back(rangeOf(scene, o, g, from, count));
        }
    });
}

uint32_t partIndexBytes(uint32_t partCount) {
    if (partCount <= 0x100u) return 1;
    if (partCount <= 0x10000u) return 2;
    return 4;
}

void PackedPartIndices::append(const uint32_t* parts, size_t count, uint32_t partCount) {
    const uint32_t width = partIndexBytes(partCount);
    const size_t offset = (bytes.size() + 3) & ~size_t(3);
    geometries.push_back({static_cast<uint32_t>(offset), width});
    bytes.resize(offset + count * width, 0);
    uint8_t* out = bytes.data() + offset;
    for (size_t i = 0; i < count; ++i)
        for (uint32_t b = 0; b < width; ++b) out[i * width + b] = uint8_t(parts[i] >> (8 * b));
    bytes.resize((bytes.size() + 3) & ~size_t(3), 0); // whole uint32 words for shaders
}

uint32_t PackedPartIndices::partOf(uint32_t geometry, uint32_t element) const {
    const Range& r = geometries[geometry];
    uint32_t value = 0;
    for (uint32_t b = 0; b < r.elementBytes; ++b)
        value |= uint32_t(bytes[r.byteOffset + element * r.elementBytes + b]) << (8 * b);
    return value;
}

std::vector<uint32_t> trianglePartsOf(const Scene& scene, uint32_t g) {
    const Geometry& geometry = scene.geometries[g];
    std::vector<uint32_t> parts(geometry.triangleCount, 0);
    for (uint32_t p = 0; p < geometry.partCount; ++p) {
        const Part& part = scene.parts[geometry.firstPart + p];
        std::fill_n(parts.begin() + part.firstTriangle, part.triangleCount, p);
    }
    return parts;
}

TrianglePartIds buildTrianglePartIds(const Scene& scene) {
    TrianglePartIds ids;
    for (uint32_t g = 0; g < scene.geometries.size(); ++g) {
        const std::vector<uint32_t> parts = trianglePartsOf(scene, g);
        ids.append(parts.data(), parts.size(), scene.geometries[g].partCount);
    }
    return ids;
}

PartTriangleCounts buildPartTriangleCounts(const Scene& scene, uint32_t searchCount) {
    if (searchCount == 0) throw std::invalid_argument("search batch must be at least 1");
    PartTriangleCounts result;
    result.counts.reserve(scene.parts.size() + searchCount - 1);
    for (const Geometry& g : scene.geometries) {
        result.geometryOffsets.push_back(static_cast<uint32_t>(result.counts.size()));
        for (uint32_t p = 0; p < g.partCount; ++p)
            result.counts.push_back(scene.parts[g.firstPart + p].triangleCount);
    }
    result.counts.resize(result.counts.size() + searchCount - 1, 0);
    return result;
}

PartTriangleOffsets buildPartTriangleOffsets(const Scene& scene) {
    PartTriangleOffsets result;
    for (const Geometry& g : scene.geometries) {
        result.geometryOffsets.push_back(static_cast<uint32_t>(result.offsets.size()));
        for (uint32_t p = 0; p < g.partCount; ++p)
            result.offsets.push_back(scene.parts[g.firstPart + p].firstTriangle);
        result.offsets.push_back(g.triangleCount);
    }
    return result;
}

IdDataBytes idDataBytes(const Scene& scene, uint32_t searchCount) {
    IdDataBytes bytes;
    uint64_t triangleIdBytes = 0, offsets = 0;
    for (const Geometry& g : scene.geometries) {
        triangleIdBytes = ((triangleIdBytes + 3) & ~uint64_t(3)) +
                          uint64_t(g.triangleCount) * partIndexBytes(g.partCount);
        offsets += g.partCount + 1;
    }
    bytes.trianglePartIds = (triangleIdBytes + 3) & ~uint64_t(3);
    bytes.partTriangleCounts = 4ull * (scene.parts.size() + searchCount - 1);
    bytes.partTriangleOffsets = 4ull * offsets;
    return bytes;
}

} // namespace scene
