// draw_list.cpp - draw ranges, per-draw data and ID buffer bytes for a technique.
#include "render/draw_list.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <tuple>

#include "scene/lod.h"
#include "vk/check.h"

namespace render {
namespace {

std::vector<DrawItem> splitDraws(const scene::Scene& scene, DrawSplit split, uint32_t batch,
                                 uint32_t level) {
    switch (split) {
    case DrawSplit::PerPart:
        return scene::drawsPerPart(scene, level);
    case DrawSplit::PerObject:
        return scene::drawsPerObject(scene, level);
    case DrawSplit::PerBatch:
        return scene::drawsPerBatch(scene, batch, level);
    }
    return {};
}

template <typename T>
std::vector<uint8_t> bytesOf(const std::vector<T>& values) {
    std::vector<uint8_t> bytes(values.size() * sizeof(T));
    if (!bytes.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
    return bytes;
}

} // namespace

size_t visibleObjectCount(float fraction, size_t objects) {
    const double wanted = std::ceil(double(fraction) * double(objects) - 1e-3);
    return size_t(std::clamp(wanted, 0.0, double(objects)));
}

uint64_t derivedBytes(const scene::PartVertices* partVertices, const scene::Meshlets* meshlets) {
    uint64_t bytes = 0;
    if (partVertices) {
        bytes += partVertices->vertices.size() * sizeof(gpu::Vertex);
        // vertex-fs draws its rotated indices; meshlets bring their own.
        if (!meshlets) bytes += partVertices->indices.size() * sizeof(uint32_t);
    }
    if (meshlets)
        bytes += meshlets->meshlets.size() * sizeof(gpu::Meshlet) +
                 (meshlets->vertices.size() + meshlets->sourceTriangle.size()) * sizeof(uint32_t);
    return bytes;
}

DerivedPrimitives DerivedGeometry::view() const {
    DerivedPrimitives d;
    d.partVertices = partVertices ? &*partVertices : nullptr;
    d.meshlets = meshlets ? &*meshlets : nullptr;
    d.bytes = derivedBytes(d.partVertices, d.meshlets);
    d.meshletCount = meshlets ? meshlets->meshlets.size() : 0;
    return d;
}

DerivedGeometry buildDerivedGeometry(const scene::Scene& scene, const Technique& technique) {
    DerivedGeometry g;
    if (technique.usesPartVertices()) g.partVertices = scene::buildPartVertices(scene);
    if (technique.usesMeshShader())
        g.meshlets = scene::buildMeshlets(scene, g.partVertices ? &*g.partVertices : nullptr);
    return g;
}

RenderStats statsFor(const DrawList& list, const DrawMode& mode, const DerivedPrimitives& derived) {
    RenderStats stats;
    stats.draws = list.fullDetailDraws;
    if (derived.partVertices) {
        stats.addedVertices = derived.partVertices->addedVertices;
        stats.addedVertexBytes = stats.addedVertices * sizeof(gpu::Vertex);
    }
    stats.meshlets = derived.meshletCount;
    stats.geometryBytes = derived.bytes;
    for (size_t i = 0; i < list.fullDetailDraws; ++i)
        stats.triangles += list.ranges[i].indexCount / 3;
    stats.pipelines = 1;
    stats.idBufferBytes = list.idBytes.size();
    if (mode.indirect) {
        // VkDrawIndexedIndirectCommand, or VkDrawMeshTasksIndirectCommandEXT for meshlets.
        const uint64_t command = sizeof(uint32_t) * (list.meshletCounts.empty() ? 5 : 3);
        stats.perDrawBytes = stats.draws * sizeof(gpu::DrawData);
        stats.indirectBytes =
            stats.draws * (command + (mode.drawIndexAttribute ? sizeof(uint32_t) : 0));
    }
    return stats;
}

namespace {

// Where each geometry's data starts in a technique's ID buffer, how wide its elements are, and
// the buffer's bytes.
struct IdData {
    std::vector<uint32_t> start, width;
    std::vector<uint8_t> bytes;
};

// The packed part indices of the techniques that read one per vertex or meshlet triangle.
scene::PackedPartIndices packedPartIndices(const scene::Scene& scene, IdBuffer ids,
                                           const DerivedPrimitives& derived) {
    scene::PackedPartIndices packed;
    const scene::PartVertices* partVertices = derived.partVertices;
    const scene::Meshlets* meshlets = derived.meshlets;
    for (uint32_t g = 0; g < scene.geometries.size(); ++g) {
        const scene::Geometry& geometry = scene.geometries[g];
        if (ids == IdBuffer::VertexPartIds) {
            packed.append(partVertices->localPart.data() + partVertices->firstVertex[g],
                          partVertices->vertexCount[g], geometry.partCount);
        } else if (ids == IdBuffer::MeshletTrianglePartIds) {
            packed.append(meshlets->localPart.data() + meshlets->geometryFirstTriangle[g],
                          geometry.triangleCount, geometry.partCount);
        } else {
            const uint32_t first = meshlets->geometryFirstVertex[g];
            const uint32_t end = g + 1 < scene.geometries.size()
                                     ? meshlets->geometryFirstVertex[g + 1]
                                     : uint32_t(meshlets->vertexPart.size());
            packed.append(meshlets->vertexPart.data() + first, end - first, geometry.partCount);
        }
    }
    return packed;
}

// The ID data `key`'s technique reads, for every geometry of the scene.
IdData idData(const scene::Scene& scene, const PipelineKey& key, const DerivedPrimitives& derived) {
    IdData data;
    data.start.assign(scene.geometries.size(), 0);
    data.width.assign(scene.geometries.size(), 0);
    auto takeGeometries = [&](const auto& geometries) {
        for (size_t g = 0; g < geometries.size(); ++g) {
            data.start[g] = geometries[g].byteOffset;
            data.width[g] = geometries[g].elementBytes;
        }
    };
    switch (key.technique->ids) {
    case IdBuffer::None:
        break;
    case IdBuffer::TrianglePartIds: {
        scene::TrianglePartIds ids = scene::buildTrianglePartIds(scene);
        takeGeometries(ids.geometries);
        data.bytes = std::move(ids.bytes);
        break;
    }
    case IdBuffer::PartTriangleCounts: {
        scene::PartTriangleCounts counts = scene::buildPartTriangleCounts(scene, key.searchBatch);
        data.start = counts.geometryOffsets;
        data.bytes = bytesOf(counts.counts);
        break;
    }
    case IdBuffer::PartTriangleOffsets: {
        scene::PartTriangleOffsets offsets = scene::buildPartTriangleOffsets(scene);
        data.start = offsets.geometryOffsets;
        data.bytes = bytesOf(offsets.offsets);
        break;
    }
    case IdBuffer::VertexPartIds:
    case IdBuffer::MeshletTrianglePartIds:
    case IdBuffer::MeshletVertexPartIds: {
        scene::PackedPartIndices ids = packedPartIndices(scene, key.technique->ids, derived);
        takeGeometries(ids.geometries);
        data.bytes = std::move(ids.bytes);
        break;
    }
    }
    return data;
}

// The draws of every object shown, full detail first, then each coarser level's (where
// `levels`), in the same order within each.
std::vector<DrawItem> drawRanges(const scene::Scene& scene, const PipelineKey& key,
                                 const DrawSettings& draws, bool levels, size_t& fullDetailDraws) {
    std::vector<DrawItem> all;
    const size_t visible = visibleObjectCount(draws.visible, scene.objects.size());
    for (uint32_t level = 0; level < (levels ? scene::maxLevels : 1u); ++level) {
        std::vector<DrawItem> ranges =
            splitDraws(scene, key.technique->split, key.searchBatch, level);
        // Before sorting, so "first" means scene order; draws come in object order.
        std::erase_if(ranges, [&](const DrawItem& d) { return d.object >= visible; });
        if (draws.sortDraws) {
            auto order = [&](const DrawItem& d) {
                const scene::Object& o = scene.objects[d.object];
                return std::tuple(o.geometry, o.material, d.object, d.firstPart);
            };
            std::stable_sort(
                ranges.begin(), ranges.end(),
                [&](const DrawItem& a, const DrawItem& b) { return order(a) < order(b); });
        }
        all.insert(all.end(), ranges.begin(), ranges.end());
        if (level == 0) fullDetailDraws = all.size();
    }
    return all;
}

// The visibility buffer's payloads (shared_visibility.h): each draw's meshlets numbered from a
// base, VIS_MESHLET_PAYLOADS apiece, the draw of each meshlet slot, and what the mesh shader
// and the shading pass read of each draw. Payloads are 32 bits and BACKGROUND_ID is none.
void numberTriangles(DrawList& list) {
    const uint64_t slot = gpu::VIS_MESHLET_PAYLOADS;
    uint64_t next = 0;
    for (uint32_t i = 0; i < list.ranges.size(); ++i) {
        const gpu::DrawData& data = list.data[i];
        list.visibilityDraws.push_back({data.objectIndex, data.idsOffset, data.idsWidth,
                                        data.firstElement, uint32_t(next), i, data.lodLevel, 0});
        next += list.meshletCounts[i] * slot;
        if (next >= gpu::BACKGROUND_ID)
            throw vk::Error("visbuffer names a triangle in 32 bits, and the meshlets of this "
                            "scene (every level of detail included) hold more than 33 million: "
                            "use another technique");
        list.visibilityBlocks.resize(next / slot, i);
    }
    if (list.visibilityBlocks.empty()) list.visibilityBlocks.push_back(0); // a buffer to address
}

} // namespace

DrawList buildDrawList(const scene::Scene& scene, const PipelineKey& key, const DrawSettings& draws,
                       const DerivedPrimitives& derived, bool levels) {
    const Technique& technique = *key.technique;
    const scene::PartVertices* partVertices = derived.partVertices;
    const scene::Meshlets* meshlets = derived.meshlets;
    if ((technique.usesPartVertices() && !partVertices) ||
        (technique.usesMeshShader() && !meshlets))
        throw std::invalid_argument(std::string(technique.name) +
                                    ": its derived geometry was not given");
    DrawList list;
    list.ranges = drawRanges(scene, key, draws, levels, list.fullDetailDraws);
    IdData ids = idData(scene, key, derived);
    list.idBytes = std::move(ids.bytes);

    vk::faultPoint("draw list"); // the CPU side of a switch can fail too (out of memory)
    list.data.reserve(list.ranges.size());
    for (uint32_t i = 0; i < list.ranges.size(); ++i) {
        const DrawItem& d = list.ranges[i];
        const uint32_t g = d.geometry;
        gpu::DrawData data{};
        data.objectIndex = d.object;
        data.firstPart = d.firstPart;
        data.partCount = d.partCount;
        // Counts are indexed per part, so a batch starts at its first part's entry.
        data.idsOffset =
            ids.start[g] + (technique.ids == IdBuffer::PartTriangleCounts ? d.firstPart : 0u);
        data.idsWidth = ids.width[g];
        if (technique.ids == IdBuffer::MeshletVertexPartIds) // see DrawData::idsOffset
            data.idsOffset -= meshlets->geometryFirstVertex[g] * data.idsWidth;
        data.drawIndex = i;
        data.lodLevel = d.level;
        if (partVertices && !meshlets) {
            data.firstElement = partVertices->firstVertex[g];
            list.ranges[i].vertexOffset = static_cast<int32_t>(partVertices->firstVertex[g]);
        }
        if (meshlets) {
            data.firstElement = meshlets->firstMeshlet[g];
            list.meshletCounts.push_back(meshlets->meshletCount[g]);
        }
        list.data.push_back(data);
    }
    if (technique.isVisibilityBuffer()) numberTriangles(list);
    return list;
}

} // namespace render
