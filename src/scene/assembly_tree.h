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

// A run of unique part IDs, [first, first + count).
struct PartRange {
    uint32_t first = 0, count = 0;
    bool operator==(const PartRange&) const = default;
};

// What a selection at a coarser level than the face takes in around part `id`, by the node
// paths: level 0 the part alone; 1 its object (a CAD solid, a glTF node's mesh); 2 every
// object under the node above the object (path equal to that node's, or below it), 3 the
// node above that, and so on, stopping at the topmost node below the root (never the whole
// scene, unless the scene is one node). An object at the root is alone at every level above
// 0. Runs in increasing order, touching ones merged; empty when `id` names no part.
std::vector<PartRange> partsAround(const Scene& scene, uint32_t id, uint32_t level);

// Runs of unique parts, sorted and merged.
using PartRanges = std::vector<PartRange>;

// The tree as rows in depth-first order, for a panel that draws only the rows on screen:
// row i's subtree is the rows [i, end).
struct TreeRow {
    std::string name;
    std::string path; // names from below the root down to this node, joined by '/'
    uint32_t depth = 0;
    uint32_t end = 0;
    std::optional<uint32_t> object;
    PartRanges parts; // every unique part of the subtree
    // What the panel shows: the name, and " #k" when siblings share it (the k-th of them).
    std::string label;
};
std::vector<TreeRow> treeRows(const AssemblyNode& root);
PartSet partSetOf(const PartRanges& ranges, uint32_t partCount);

// Names in natural order: runs of digits compare as numbers ("solid 2" before "solid 10"),
// letters without case; ties fall back to plain comparison, so the order is total.
bool naturalLess(const std::string& a, const std::string& b);
// Sorts every node's children by name in natural order (stable: equal names keep theirs).
void sortNatural(AssemblyNode& node);
// The deepest row whose parts are exactly `selected`: what names a selection in the panel.
std::optional<size_t> rowOfParts(const std::vector<TreeRow>& rows, const PartSet& selected);

} // namespace scene
