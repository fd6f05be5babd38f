// mesh_builder.cpp - faces, boxes and prisms as parts of one geometry.
#include "scene/mesh_builder.h"

#include <array>
#include <cmath>
#include <stdexcept>

namespace scene {

std::vector<glm::vec3> areaWeightedNormals(std::span<const glm::vec3> positions,
                                           std::span<const uint32_t> corners) {
    std::vector<glm::vec3> sum(positions.size(), glm::vec3(0.0f));
    for (size_t i = 0; i + 2 < corners.size(); i += 3) {
        const glm::vec3& a = positions[corners[i]];
        const glm::vec3 n =
            glm::cross(positions[corners[i + 1]] - a, positions[corners[i + 2]] - a);
        for (size_t k = 0; k < 3; ++k) sum[corners[i + k]] += n;
    }
    for (auto& n : sum) {
        const float len = glm::length(n);
        n = (std::isfinite(len) && len > 0.0f) ? n / len : glm::vec3(0, 0, 1);
    }
    return sum;
}

void MeshBuilder::beginPart() {
    uint32_t triangles = static_cast<uint32_t>(indices_.size() / 3);
    if (!parts_.empty() && parts_.back().firstTriangle == triangles)
        return; // the previous part is still empty: reuse it
    parts_.push_back({triangles, 0});
}

uint32_t MeshBuilder::addVertex(glm::vec3 position, glm::vec3 normal) {
    vertices_.push_back({position, normal});
    return static_cast<uint32_t>(vertices_.size() - 1);
}

void MeshBuilder::addTriangle(uint32_t a, uint32_t b, uint32_t c) {
    if (parts_.empty()) throw std::logic_error("MeshBuilder: addTriangle before beginPart");
    indices_.insert(indices_.end(), {a, b, c});
    parts_.back().triangleCount++;
}

void MeshBuilder::addFlatFace(std::span<const glm::vec3> corners) {
    glm::vec3 normal = glm::normalize(glm::cross(corners[1] - corners[0], corners[2] - corners[0]));
    beginPart();
    uint32_t first = addVertex(corners[0], normal);
    for (size_t i = 1; i < corners.size(); ++i) addVertex(corners[i], normal);
    for (uint32_t i = 1; i + 1 < corners.size(); ++i) addTriangle(first, first + i, first + i + 1);
}

void MeshBuilder::addBox(glm::vec3 center, glm::vec3 size) {
    glm::vec3 h = size * 0.5f;
    auto corner = [&](float x, float y, float z) { return center + glm::vec3(x, y, z) * h; };
    const std::array<std::array<glm::vec3, 4>, 6> faces = {{
        {corner(1, -1, -1), corner(1, 1, -1), corner(1, 1, 1), corner(1, -1, 1)},     // +x
        {corner(-1, 1, -1), corner(-1, -1, -1), corner(-1, -1, 1), corner(-1, 1, 1)}, // -x
        {corner(1, 1, -1), corner(-1, 1, -1), corner(-1, 1, 1), corner(1, 1, 1)},     // +y
        {corner(-1, -1, -1), corner(1, -1, -1), corner(1, -1, 1), corner(-1, -1, 1)}, // -y
        {corner(-1, -1, 1), corner(1, -1, 1), corner(1, 1, 1), corner(-1, 1, 1)},     // +z
        {corner(-1, 1, -1), corner(1, 1, -1), corner(1, -1, -1), corner(-1, -1, -1)}, // -z
    }};
    for (const auto& face : faces) addFlatFace(face);
}

void MeshBuilder::addPrism(glm::vec2 center, float radius, float z0, float z1, int sides,
                           bool smoothSides) {
    auto rim = [&](int i) {
        float a = 2.0f * float(M_PI) * float(i % sides) / float(sides);
        return glm::vec2(std::cos(a), std::sin(a));
    };
    if (smoothSides) beginPart();
    for (int i = 0; i < sides; ++i) {
        glm::vec2 d0 = rim(i), d1 = rim(i + 1);
        glm::vec3 p[4] = {{center + d0 * radius, z0},
                          {center + d1 * radius, z0},
                          {center + d1 * radius, z1},
                          {center + d0 * radius, z1}};
        if (!smoothSides) {
            addFlatFace(p);
            continue;
        }
        uint32_t a = addVertex(p[0], glm::vec3(d0, 0)), b = addVertex(p[1], glm::vec3(d1, 0));
        uint32_t c = addVertex(p[2], glm::vec3(d1, 0)), d = addVertex(p[3], glm::vec3(d0, 0));
        addTriangle(a, b, c);
        addTriangle(a, c, d);
    }
    std::vector<glm::vec3> top, bottom;
    for (int i = 0; i < sides; ++i) {
        top.push_back({center + rim(i) * radius, z1});
        bottom.push_back({center + rim(sides - i) * radius, z0});
    }
    addFlatFace(top);
    addFlatFace(bottom);
}

uint32_t MeshBuilder::finish(Scene& scene, std::string name) {
    if (parts_.empty() || indices_.empty())
        throw std::logic_error("MeshBuilder: geometry '" + name + "' has no triangles");
    if (parts_.back().triangleCount == 0) parts_.pop_back();
    Geometry g;
    g.name = std::move(name);
    g.firstVertex = static_cast<uint32_t>(scene.vertices.size());
    g.vertexCount = static_cast<uint32_t>(vertices_.size());
    g.firstIndex = static_cast<uint32_t>(scene.indices.size());
    g.triangleCount = static_cast<uint32_t>(indices_.size() / 3);
    g.firstPart = static_cast<uint32_t>(scene.parts.size());
    g.partCount = static_cast<uint32_t>(parts_.size());
    scene.vertices.insert(scene.vertices.end(), vertices_.begin(), vertices_.end());
    scene.indices.insert(scene.indices.end(), indices_.begin(), indices_.end());
    scene.parts.insert(scene.parts.end(), parts_.begin(), parts_.end());
    scene.geometries.push_back(std::move(g));
    *this = MeshBuilder();
    return static_cast<uint32_t>(scene.geometries.size() - 1);
}

} // namespace scene
