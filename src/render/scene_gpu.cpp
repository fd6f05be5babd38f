// scene_gpu.cpp - uploads a scene once, when it is loaded or its copies change.
#include "render/scene_gpu.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "scene/bounds.h"
#include "scene/explode.h"
#include "scene/section.h"
#include "shared.h"
#include "vk/check.h"

namespace render {

SceneGpu::SceneGpu(const scene::Scene& scene, vk::UploadBatch& upload)
    : objectCount_(static_cast<uint32_t>(scene.objects.size())) {
    // Objects without triangles yet (a load shown as it goes) draw nothing, and their empty
    // arrays get buffers of a few bytes.
    if (scene.objects.empty()) throw vk::Error("the scene is empty: nothing to draw");

    std::vector<gpu::ObjectData> objects;
    std::vector<glm::dmat4> rest;
    objects.reserve(scene.objects.size());
    rest.reserve(scene.objects.size());
    for (const auto& o : scene.objects) {
        gpu::ObjectData data{};
        data.world = relativeWorld(o.world, originWritten); // animate.comp's, at rest
        data.normalMatrix = glm::mat4(glm::transpose(glm::inverse(o.world)));
        data.materialIndex = o.material;
        data.uniquePartOffset = o.uniquePartOffset;
        data.geometryIndex = o.geometry;
        data.firstPart = scene.geometries[o.geometry].firstPart;
        objects.push_back(data);
        rest.push_back(o.world);
    }
    std::vector<gpu::Material> materials;
    for (const auto& m : scene.materials) materials.push_back({m.color});

    const VkBufferUsageFlags shaderRead =
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
    vertices_ =
        upload.add(scene.vertices.get(), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "scene vertices");
    indices_ = upload.add(scene.indices.get(), VK_BUFFER_USAGE_INDEX_BUFFER_BIT, "scene indices");
    objects_ = upload.add(objects, shaderRead, "scene objects");
    materials_ = upload.add(materials, shaderRead, "scene materials");
    rest_ = upload.add(rest, shaderRead, "animation rest matrices");
    explodeOffsets_ = scene::explodeOffsets(scene);
    offsets_ = upload.add(explodeOffsets_, shaderRead, "animation offsets");
    restWorld_ = std::move(rest);
    partBounds_ = scene::partBounds(scene);
    measureReach(scene);
    scene::Clusters clusters = scene::partClusters(scene, gpu::CLUSTER_MAX_TRIANGLES);
    std::vector<gpu::CullBox> boxes;
    boxes.reserve(clusters.boxes.size());
    static_assert(gpu::CLUSTER_MAX_TRIANGLES == 64, "CullBox::triangles packs the count in 6 bits");
    for (size_t c = 0; c < clusters.boxes.size(); ++c) {
        // Cluster runs (cull.comp) need the first triangle in 26 bits.
        if (clusters.firstTriangle[c] >= (1u << 26))
            throw std::runtime_error("a geometry of more than 67 million triangles cannot be "
                                     "culled cluster by cluster; split it into objects");
        const uint32_t triangles = clusters.firstTriangle[c] << 6 | (clusters.triangleCount[c] - 1);
        boxes.push_back(
            {clusters.boxes[c].min, clusters.localPart[c], clusters.boxes[c].max, triangles});
    }
    if (boxes.empty()) boxes.resize(1); // an address even without triangles
    clusterBoxes_ = upload.add(boxes, shaderRead, "cluster boxes");
    clusterStart_ = std::move(clusters.first);
    // Part materials only where some part has one: other scenes read none.
    std::vector<uint32_t> partMaterials;
    for (const scene::Geometry& g : scene.geometries)
        if (!g.partMaterials.empty()) {
            partMaterials.assign(scene.parts.size(), gpu::OBJECT_MATERIAL);
            break;
        }
    if (!partMaterials.empty()) {
        for (const scene::Geometry& g : scene.geometries)
            for (uint32_t p = 0; p < g.partMaterials.size(); ++p)
                partMaterials[g.firstPart + p] = g.partMaterials[p];
        partMaterials_ = upload.add(partMaterials, shaderRead, "part materials");
    }
}

void SceneGpu::measureReach(const scene::Scene& scene) {
    std::vector<double> radius(scene.geometries.size(), 0.0);
    for (size_t g = 0; g < scene.geometries.size(); ++g) {
        const scene::Geometry& geo = scene.geometries[g];
        const scene::Bounds box =
            scene::partRangeBounds(scene, partBounds_, uint32_t(g), 0, geo.partCount);
        if (!scene::isEmpty(box))
            radius[g] = glm::length(glm::max(glm::abs(box.min), glm::abs(box.max)));
    }
    reachBox_ = scene::emptyBounds();
    double offset = 0.0;
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const glm::dmat4& world = scene.objects[o].world;
        const double scale =
            std::max({glm::length(glm::dvec3(world[0])), glm::length(glm::dvec3(world[1])),
                      glm::length(glm::dvec3(world[2]))});
        const double r = scale * radius[scene.objects[o].geometry];
        localReach_ = std::max(localReach_, r);
        const glm::dvec3 at(world[3]);
        reachBox_ = scene::unite(reachBox_, {at - r, at + r});
        offset = std::max(offset, double(glm::length(glm::vec3(explodeOffsets_[o]))));
    }
    reachBox_ = {reachBox_.min - offset, reachBox_.max + offset};
}

double SceneGpu::sectionTolerance(const glm::dvec3& origin) const {
    // A vertex placed relative to origin: its local coordinates through the matrix, plus the
    // translation (at most localReach_ from a point of the box), then compared with a plane
    // whose offset is at most the box's farthest corner.
    const glm::dvec3 far =
        glm::max(glm::abs(reachBox_.min - origin), glm::abs(reachBox_.max - origin));
    return scene::inPlaneTolerance(2.0 * localReach_ + 2.0 * glm::length(far));
}

glm::mat4 relativeWorld(const glm::dmat4& world, const glm::dvec3& origin) {
    glm::mat4 relative(world);
    relative[3] = glm::vec4(glm::vec3(glm::dvec3(world[3]) - origin), 1.0f);
    return relative;
}

glm::mat4 SceneGpu::worldAt(uint32_t object, float explode, const glm::dvec3& origin) const {
    glm::dmat4 world = restWorld_[object];
    explode = explode > 0.0f ? std::min(explode, 1.0f) : 0.0f; // as Animator::record clamps
    // The float step, then the double add, as animate.comp and scene::explodedScene do.
    const glm::vec3 step = glm::vec3(explodeOffsets_[object]) * explode;
    world[3] += glm::dvec4(glm::dvec3(step), 0.0);
    return relativeWorld(world, origin);
}

} // namespace render
