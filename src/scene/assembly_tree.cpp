// assembly_tree.cpp - the tree of node paths (assembly_tree.h).
#include "scene/assembly_tree.h"

#include <map>

namespace scene {

AssemblyNode assemblyTree(const Scene& scene, const std::string& rootName) {
    AssemblyNode root;
    root.name = rootName;
    // Each group's children by name, to find a group again: node addresses move as vectors
    // grow, so groups are found by their index path from the root.
    std::map<std::pair<std::vector<size_t>, std::string>, size_t> groups;
    for (uint32_t o = 0; o < scene.objects.size(); ++o) {
        const Object& object = scene.objects[o];
        std::vector<std::string> names;
        for (size_t start = 0;;) {
            const size_t slash = object.path.find('/', start);
            names.push_back(object.path.substr(start, slash - start));
            if (slash == std::string::npos) break;
            start = slash + 1;
        }
        AssemblyNode* node = &root;
        std::vector<size_t> at;
        for (size_t i = 0; i + 1 < names.size(); ++i) {
            auto [it, added] = groups.try_emplace({at, names[i]}, node->children.size());
            if (added) node->children.push_back({names[i], {}, std::nullopt, 0, 0});
            at.push_back(it->second);
            node = &node->children[it->second];
        }
        // The object's own node: a group of its path's name that holds no object yet (a
        // glTF node with a mesh and children, a procedural bracket with its bolts), else a
        // node of its own, which later objects under its path join.
        const std::string& last = object.path.empty() ? object.name : names.back();
        auto [it, added] = groups.try_emplace({at, last}, node->children.size());
        if (added || node->children[it->second].object) {
            if (!added && node->children[it->second].object) it = groups.end();
            node->children.push_back({last, {}, std::nullopt, 0, 0});
        }
        AssemblyNode& own = it == groups.end() ? node->children.back() : node->children[it->second];
        own.object = o;
        own.firstPart = object.uniquePartOffset;
        own.partCount = scene.geometries[object.geometry].partCount;
    }
    return root;
}

} // namespace scene
