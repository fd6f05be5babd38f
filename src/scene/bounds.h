// bounds.h - boxes around pieces of a scene in their geometry's coordinates, for culling: each
// part's triangles, a run of parts, each meshlet. Plain C++; the GPU transforms them by the
// object's matrix every frame (shaders/cull.glsl).
#pragma once

#include <vector>

#include "scene/meshlets.h"
#include "scene/part_set.h"
#include "scene/scene.h"

namespace scene {

// An empty box: min above max, so that unite() with anything gives that thing.
Bounds emptyBounds();
Bounds unite(const Bounds& a, const Bounds& b);
bool isEmpty(const Bounds& b);

// Per entry of Scene::parts: the box of the vertices its triangles use; empty (isEmpty) for
// an empty part.
std::vector<Bounds> partBounds(const Scene& scene);

// The box of parts [firstPart, firstPart + count) of geometry `g`, from partBounds(); empty
// where they all are.
Bounds partRangeBounds(const Scene& scene, const std::vector<Bounds>& parts, uint32_t g,
                       uint32_t firstPart, uint32_t count);

// The world box of the triangles of the unique parts in `parts`, placed where their objects
// are (what F fits the view to); empty (isEmpty) when the set holds no part with triangles.
Bounds partsWorldBounds(const Scene& scene, const PartSet& parts);

// Each part's triangles in runs of at most `maxTriangles` in index order (clusters), each
// run's box and part: what culling tests a draw by, cluster by cluster, where its own box
// is not enough (shaders/cull.comp). An empty part has none, so no cluster's box is empty.
struct Clusters {
    std::vector<Bounds> boxes;       // per cluster
    std::vector<uint32_t> localPart; // per cluster: its part's index in its geometry
    // Per cluster its first triangle in its geometry and its triangle count: a draw's
    // clusters are consecutive triangles, so any run of them is one indexed draw.
    std::vector<uint32_t> firstTriangle, triangleCount;
    // Per entry of Scene::parts its first cluster, and one more entry: the cluster count.
    std::vector<uint32_t> first;
};
Clusters partClusters(const Scene& scene, uint32_t maxTriangles);

// Per meshlet: the box of its vertices, `vertices` being the array the meshlets index
// (Scene::vertices, or PartVertices::vertices).
std::vector<Bounds> meshletBounds(const Meshlets& meshlets, const std::vector<Vertex>& vertices);

} // namespace scene
