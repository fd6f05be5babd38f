// meshlets.cpp - meshoptimizer's meshlets, and which scene triangle each meshlet triangle is.
#include "scene/meshlets.h"

#include <meshoptimizer.h>

#include <stdexcept>

#include "scene/part_data.h"

namespace scene {
namespace {

// Triangles by vertex (compressed rows): which triangles of a geometry use a vertex, so each
// meshlet triangle can be matched with the scene triangle it came from. meshoptimizer keeps
// a triangle's corners in order but reorders triangles and does not say where each went.
class TriangleFinder {
  public:
    TriangleFinder(const uint32_t* indices, uint32_t triangles, uint32_t vertices)
        : indices_(indices), start_(vertices + 1, 0), used_(triangles, false) {
        for (uint32_t i = 0; i < 3 * triangles; ++i) ++start_[indices[i] + 1];
        for (uint32_t v = 0; v < vertices; ++v) start_[v + 1] += start_[v];
        rows_.resize(3 * triangles);
        std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
        for (uint32_t i = 0; i < 3 * triangles; ++i) rows_[fill[indices[i]]++] = i / 3;
    }

    // The unused triangle with corners (a, b, c) in this cyclic order; marks it used.
    uint32_t take(uint32_t a, uint32_t b, uint32_t c) {
        for (uint32_t k = start_[a]; k < start_[a + 1]; ++k) {
            const uint32_t t = rows_[k];
            if (used_[t]) continue;
            const uint32_t* tri = indices_ + 3 * t;
            for (int r = 0; r < 3; ++r)
                if (tri[r] == a && tri[(r + 1) % 3] == b && tri[(r + 2) % 3] == c) {
                    used_[t] = true;
                    return t;
                }
        }
        throw std::logic_error("meshlet triangle matches no triangle of its geometry");
    }

  private:
    const uint32_t* indices_;
    std::vector<uint32_t> start_, rows_;
    std::vector<bool> used_;
};

// What one geometry's meshlets are cut from.
struct Source {
    const Vertex* vertices; // the geometry's first vertex
    uint32_t firstVertex, vertexCount;
    const uint32_t* indices;              // the geometry's first index, geometry-local
    const uint32_t* vertexPart = nullptr; // per vertex of the geometry (part vertices only)
};

void addGeometry(const Scene& scene, uint32_t g, const Source& from, Meshlets& out) {
    const Geometry& geometry = scene.geometries[g];
    const uint32_t* indices = from.indices;
    const size_t indexCount = size_t(geometry.triangleCount) * 3;
    const size_t bound =
        meshopt_buildMeshletsBound(indexCount, meshletMaxVertices, meshletMaxTriangles);
    std::vector<meshopt_Meshlet> built(bound);
    std::vector<unsigned int> vertices(bound * meshletMaxVertices);
    std::vector<unsigned char> corners(bound * meshletMaxTriangles * 3);
    // Triangles are rasterized in the order the meshlets hold them, and where two parts meet
    // at exactly one depth the first drawn keeps the pixel (depth test LESS). To give the ID
    // image of every other technique, parts keep their order: each part's triangles are
    // reordered for vertex reuse within the part only, then cut into meshlets in that order.
    // (meshopt_buildMeshlets clusters across parts: 3 pixels of 3.7 M differed on the H100.)
    std::vector<uint32_t> ordered(indexCount);
    for (uint32_t p = 0; p < geometry.partCount; ++p) {
        const Part& part = scene.parts[geometry.firstPart + p];
        const size_t first = size_t(part.firstTriangle) * 3, count = size_t(part.triangleCount) * 3;
        meshopt_optimizeVertexCache(ordered.data() + first, indices + first, count,
                                    from.vertexCount);
    }
    built.resize(meshopt_buildMeshletsScan(built.data(), vertices.data(), corners.data(),
                                           ordered.data(), indexCount, from.vertexCount,
                                           meshletMaxVertices, meshletMaxTriangles));

    const std::vector<uint32_t> parts = trianglePartsOf(scene, g);
    TriangleFinder finder(indices, geometry.triangleCount, from.vertexCount);
    out.firstMeshlet.push_back(static_cast<uint32_t>(out.meshlets.size()));
    out.meshletCount.push_back(static_cast<uint32_t>(built.size()));
    out.geometryFirstTriangle.push_back(static_cast<uint32_t>(out.sourceTriangle.size()));
    out.geometryFirstVertex.push_back(static_cast<uint32_t>(out.vertices.size()));
    uint32_t localTriangle = 0, localVertex = 0;
    for (const meshopt_Meshlet& m : built) {
        Meshlet meshlet;
        meshlet.firstVertex = static_cast<uint32_t>(out.vertices.size());
        meshlet.firstTriangle = static_cast<uint32_t>(out.sourceTriangle.size());
        meshlet.vertexCount = m.vertex_count;
        meshlet.triangleCount = m.triangle_count;
        meshlet.firstLocalTriangle = localTriangle;
        meshlet.firstLocalVertex = localVertex;
        const unsigned int* mv = vertices.data() + m.vertex_offset;
        for (uint32_t i = 0; i < m.vertex_count; ++i) {
            out.vertices.push_back(from.firstVertex + mv[i]);
            if (from.vertexPart) out.vertexPart.push_back(from.vertexPart[mv[i]]);
        }
        const unsigned char* mc = corners.data() + m.triangle_offset;
        for (uint32_t i = 0; i < m.triangle_count; ++i) {
            const uint8_t* c = mc + 3 * i;
            const uint32_t t = finder.take(mv[c[0]], mv[c[1]], mv[c[2]]);
            // Corners in the scene triangle's own order, whichever rotation meshoptimizer
            // kept: the rasterizer then sets up exactly the triangle the other techniques
            // draw, down to the rounding of its depth plane.
            for (int k = 0; k < 3; ++k) {
                const uint32_t v = indices[3 * t + k];
                uint8_t local = 0;
                while (mv[c[local]] != v) ++local; // one of the three, by the match above
                out.corners.push_back(c[local]);
            }
            out.sourceTriangle.push_back(t);
            out.localPart.push_back(parts[t]);
        }
        localTriangle += m.triangle_count;
        localVertex += m.vertex_count;
        out.meshlets.push_back(meshlet);
    }
    if (localTriangle != geometry.triangleCount)
        throw std::logic_error("meshlets of geometry '" + geometry.name + "' lost triangles");
}

} // namespace

Meshlets buildMeshlets(const Scene& scene, const PartVertices* partVertices) {
    Meshlets out;
    for (uint32_t g = 0; g < scene.geometries.size(); ++g) {
        const Geometry& geometry = scene.geometries[g];
        Source from{scene.vertices.data() + geometry.firstVertex, geometry.firstVertex,
                    geometry.vertexCount, scene.indices.data() + geometry.firstIndex};
        if (partVertices) {
            const uint32_t first = partVertices->firstVertex[g];
            from = {partVertices->vertices.data() + first, first, partVertices->vertexCount[g],
                    partVertices->indices.data() + geometry.firstIndex,
                    partVertices->localPart.data() + first};
        }
        addGeometry(scene, g, from, out);
    }
    return out;
}

} // namespace scene
