// explode.cpp - exploded-view offsets by assembly level and the CPU reference of the GPU
// animation.
#include "scene/explode.h"

#include "scene/assembly_tree.h"
#include "scene/bounds.h"

#include <cmath>
#include <limits>

namespace scene {

namespace {

// A box and whether anything drawn made it: an object with no vertices stands in by its
// origin, but only where nothing drawn is there to give a centre.
struct Box {
    Bounds bounds = emptyBounds();
    bool drawn = false;
};

void add(Box& into, const Box& box) {
    if (into.drawn && !box.drawn) return;
    if (box.drawn && !into.drawn) into = Box{}; // a drawn box outranks stand-ins
    into.bounds.min = glm::min(into.bounds.min, box.bounds.min);
    into.bounds.max = glm::max(into.bounds.max, box.bounds.max);
    into.drawn = box.drawn;
}

std::vector<Box> objectBoxes(const Scene& scene) {
    std::vector<Box> boxes(scene.objects.size());
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& object = scene.objects[i];
        const Geometry& g = scene.geometries[object.geometry];
        Box& b = boxes[i];
        for (uint32_t v = 0; v < g.vertexCount; ++v) {
            const glm::dvec3 p = placed(object.world, scene.vertices[g.firstVertex + v].position);
            b.bounds.min = glm::min(b.bounds.min, p);
            b.bounds.max = glm::max(b.bounds.max, p);
        }
        b.drawn = g.vertexCount > 0;
        if (!b.drawn) b.bounds.min = b.bounds.max = glm::dvec3(object.world[3]);
    }
    return boxes;
}

// The node's subtree's box, each node's kept in `boxes` in depth-first order.
Box nodeBox(const AssemblyNode& node, const std::vector<Box>& objects, std::vector<Box>& boxes) {
    const size_t at = boxes.size();
    boxes.emplace_back();
    Box box;
    if (node.object) add(box, objects[*node.object]);
    for (const AssemblyNode& child : node.children) add(box, nodeBox(child, objects, boxes));
    boxes[at] = box;
    return box;
}

struct Walk {
    const std::vector<Box>& objects;
    const std::vector<Box>& nodes; // depth-first, as nodeBox stored them
    std::vector<glm::dvec3>& offsets;
    size_t next = 0; // the next node's index in `nodes`

    // `moved`: what the node's ancestors moved it by; `weight`: its members' share.
    void node(const AssemblyNode& n, glm::dvec3 moved, double weight) {
        const glm::dvec3 centre = nodes[next++].bounds.center();
        const size_t members = n.children.size() + (n.object ? 1 : 0);
        if (n.object)
            offsets[*n.object] = moved + weight * (objects[*n.object].bounds.center() - centre);
        const double below = members > 1 ? weight * 0.5 : weight;
        for (const AssemblyNode& child : n.children) {
            const glm::dvec3 term = weight * (nodes[next].bounds.center() - centre);
            node(child, moved + term, below);
        }
    }
};

} // namespace

std::vector<glm::vec4> explodeOffsets(const Scene& scene) {
    const std::vector<Box> objects = objectBoxes(scene);
    const AssemblyNode root = assemblyTree(scene, {});
    std::vector<Box> nodes;
    nodeBox(root, objects, nodes);
    std::vector<glm::dvec3> offsets(scene.objects.size(), glm::dvec3(0.0));
    Walk{objects, nodes, offsets}.node(root, glm::dvec3(0.0), 1.0);
    std::vector<glm::vec4> result;
    result.reserve(offsets.size());
    for (const glm::dvec3& o : offsets) result.push_back(glm::vec4(glm::vec3(o), 0.0f));
    return result;
}

void placeExploded(Scene& moved, const Scene& rest, const std::vector<glm::vec4>& offsets,
                   float explode) {
    for (size_t i = 0; i < moved.objects.size(); ++i) {
        const glm::dmat4& from = rest.objects[i].world;
        glm::dmat4& world = moved.objects[i].world;
        // A float multiply, then a double add, per component: animate.comp marks the same
        // expression `precise`, which forbids fusing them into an fma.
        for (int c = 0; c < 3; ++c) {
            const float step = offsets[i][c] * explode;
            world[3][c] = from[3][c] + double(step);
        }
    }
}

Scene explodedScene(const Scene& scene, float explode) {
    Scene moved = scene;
    placeExploded(moved, scene, explodeOffsets(scene), explode);
    return moved;
}

float explodeLoop(float seconds, float periodSeconds) {
    const float pi = 3.14159265358979f;
    return 0.5f - 0.5f * std::cos(2.0f * pi * seconds / periodSeconds);
}

} // namespace scene
