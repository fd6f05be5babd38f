// draw_list.cpp - draw ranges, per-draw data and ID buffer bytes for a technique.
#include "render/draw_list.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <tuple>

#include "vk/check.h"

namespace render {
namespace {

std::vector<DrawItem> splitDraws(const scene::Scene& scene, DrawSplit split, uint32_t batch) {
    switch (split) {
    case DrawSplit::PerPart:
        return scene::drawsPerPart(scene);
    case DrawSplit::PerObject:
        return scene::drawsPerObject(scene);
    case DrawSplit::PerBatch:
        return scene::drawsPerBatch(scene, batch);
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

RenderStats statsFor(const DrawList& list, const DrawMode& mode) {
    RenderStats stats;
    stats.draws = list.ranges.size();
    for (const DrawItem& d : list.ranges) stats.triangles += d.indexCount / 3;
    stats.pipelines = 1;
    stats.idBufferBytes = list.idBytes.size();
    if (mode.indirect) {
        stats.perDrawBytes = stats.draws * sizeof(gpu::DrawData);
        stats.indirectBytes = stats.draws * (sizeof(uint32_t) * 5 + // VkDrawIndexedIndirectCommand
                                             (mode.drawIndexAttribute ? sizeof(uint32_t) : 0));
    }
    return stats;
}

DrawList buildDrawList(const scene::Scene& scene, const PipelineKey& key,
                       const DrawSettings& draws) {
    const Technique& technique = *key.technique;
    DrawList list;
    list.ranges = splitDraws(scene, technique.split, key.searchBatch);
    // Before sorting, so "first" means scene order; draws come in object order.
    const size_t visible = visibleObjectCount(draws.visible, scene.objects.size());
    std::erase_if(list.ranges, [&](const DrawItem& d) { return d.object >= visible; });
    if (draws.sortDraws) {
        auto key = [&](const DrawItem& d) {
            const scene::Object& o = scene.objects[d.object];
            return std::tuple(o.geometry, o.material, d.object, d.firstPart);
        };
        std::stable_sort(list.ranges.begin(), list.ranges.end(),
                         [&](const DrawItem& a, const DrawItem& b) { return key(a) < key(b); });
    }

    // Where each geometry's data starts in the ID buffer, and how wide its elements are.
    std::vector<uint32_t> geometryStart(scene.geometries.size(), 0);
    std::vector<uint32_t> geometryWidth(scene.geometries.size(), 0);
    switch (technique.ids) {
    case IdBuffer::None:
        break;
    case IdBuffer::TrianglePartIds: {
        scene::TrianglePartIds ids = scene::buildTrianglePartIds(scene);
        for (size_t g = 0; g < ids.geometries.size(); ++g) {
            geometryStart[g] = ids.geometries[g].byteOffset;
            geometryWidth[g] = ids.geometries[g].elementBytes;
        }
        list.idBytes = std::move(ids.bytes);
        break;
    }
    case IdBuffer::PartTriangleCounts: {
        scene::PartTriangleCounts counts = scene::buildPartTriangleCounts(scene, key.searchBatch);
        geometryStart = counts.geometryOffsets;
        list.idBytes = bytesOf(counts.counts);
        break;
    }
    case IdBuffer::PartTriangleOffsets: {
        scene::PartTriangleOffsets offsets = scene::buildPartTriangleOffsets(scene);
        geometryStart = offsets.geometryOffsets;
        list.idBytes = bytesOf(offsets.offsets);
        break;
    }
    }

    vk::faultPoint("draw list"); // the CPU side of a switch can fail too (out of memory)
    list.data.reserve(list.ranges.size());
    for (uint32_t i = 0; i < list.ranges.size(); ++i) {
        const DrawItem& d = list.ranges[i];
        const uint32_t g = scene.objects[d.object].geometry;
        gpu::DrawData data{};
        data.objectIndex = d.object;
        data.firstPart = d.firstPart;
        data.partCount = d.partCount;
        // Counts are indexed per part, so a batch starts at its first part's entry.
        data.idsOffset =
            geometryStart[g] + (technique.ids == IdBuffer::PartTriangleCounts ? d.firstPart : 0u);
        data.idsWidth = geometryWidth[g];
        data.drawIndex = i;
        list.data.push_back(data);
    }
    return list;
}

} // namespace render
