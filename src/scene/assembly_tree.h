// assembly_tree.h - the tree of a scene's assemblies, groups and objects, from the node paths
// the loaders give every object (Object::path: STEP/IGES products and instances, glTF nodes,
// procedural groups, "copy k" for copies). Plain C++, for --tree and the panel's tree.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scene/part_set.h"
#include "scene/scene.h"

namespace scene {

struct AssemblyNode {
    std::string name;
    std::vector<AssemblyNode> children; // in the order their first object comes in the scene
    // An object's node (a leaf, or a group whose node is an object too, as a glTF node with
    // a mesh and children): the object, and its unique parts [firstPart, firstPart + count).
    std::optional<uint32_t> object;
    uint32_t firstPart = 0, partCount = 0;
};

// The root (named `rootName`) holds a node per first path name, and so on down; each object
// is the node of its whole path, named by the path's last name. Groups of one name under one
// parent are one node, and an object joins the group of its path; two objects are never one
// node (the second of one path gets a node of its own). A name that holds '/' reads as two.
AssemblyNode assemblyTree(const Scene& scene, const std::string& rootName);

// A ranges of unique parts, [first, first + count), sorted and merged.
using PartRanges = std::vector<std::pair<uint32_t, uint32_t>>;

// The tree as rows in depth-first order, for a panel that draws only the rows on screen:
// row i's subtree is the rows [i, end).
struct TreeRow {
    std::string name;
    std::string path; // names from below the root down to this node, joined by '/'
    uint32_t depth = 0;
    uint32_t end = 0;
    std::optional<uint32_t> object;
    PartRanges parts; // every unique part of the subtree
};
std::vector<TreeRow> treeRows(const AssemblyNode& root);
PartSet partSetOf(const PartRanges& ranges, uint32_t partCount);

} // namespace scene
