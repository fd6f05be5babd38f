// assembly_tree.cpp - the tree of node paths (assembly_tree.h).
#include "scene/assembly_tree.h"

#include <algorithm>
#include <cctype>
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

std::vector<PartRange> partsAround(const Scene& scene, uint32_t id, uint32_t level) {
    const std::optional<PartRef> ref = scene.locate(id);
    if (!ref) return {};
    const Object& object = scene.objects[ref->object];
    if (level == 0) return {{id, 1}};
    const uint32_t partCount = scene.geometries[object.geometry].partCount;
    const std::string& path = object.path.empty() ? object.name : object.path;
    // The node `level - 1` names above the object's, keeping the first name at least.
    size_t end = path.size();
    for (uint32_t up = 1; up < level; ++up) {
        const size_t slash = path.rfind('/', end - 1);
        if (slash == std::string::npos || slash == 0) break;
        end = slash;
    }
    if (end == path.size()) return {{object.uniquePartOffset, partCount}};
    const std::string node = path.substr(0, end);
    std::vector<PartRange> ranges;
    for (const Object& o : scene.objects) {
        const std::string& p = o.path.empty() ? o.name : o.path;
        if (p == node || (p.size() > node.size() && p.starts_with(node) && p[node.size()] == '/'))
            ranges.push_back({o.uniquePartOffset, scene.geometries[o.geometry].partCount});
    }
    std::sort(ranges.begin(), ranges.end(),
              [](const PartRange& a, const PartRange& b) { return a.first < b.first; });
    std::vector<PartRange> merged;
    for (const PartRange& r : ranges) {
        if (!merged.empty() && merged.back().first + merged.back().count == r.first)
            merged.back().count += r.count;
        else
            merged.push_back(r);
    }
    return merged;
}

namespace {

void addRows(const AssemblyNode& node, const std::string& path, uint32_t depth,
             std::vector<TreeRow>& rows, std::string label) {
    const size_t index = rows.size();
    rows.push_back({node.name, path, depth, 0, node.object, {}, std::move(label)});
    PartRanges parts;
    if (node.object && node.partCount) parts.push_back({node.firstPart, node.partCount});
    for (size_t c = 0; c < node.children.size(); ++c) {
        const AssemblyNode& child = node.children[c];
        // Siblings of one name (objects of one path) are told apart by their number.
        size_t same = 0, before = 0;
        for (size_t o = 0; o < node.children.size(); ++o)
            if (node.children[o].name == child.name) {
                ++same;
                before += o < c;
            }
        addRows(child, path.empty() ? child.name : path + "/" + child.name, depth + 1, rows,
                same > 1 ? child.name + " #" + std::to_string(before + 1) : child.name);
    }
    // The children's rows are done: gather their ranges (each child's row is the first of
    // its subtree), sort and merge touching ones.
    for (size_t r = index + 1; r < rows.size(); r = rows[r].end)
        parts.insert(parts.end(), rows[r].parts.begin(), rows[r].parts.end());
    std::sort(parts.begin(), parts.end(),
              [](const PartRange& x, const PartRange& y) { return x.first < y.first; });
    PartRanges merged;
    for (const auto& [first, count] : parts) {
        if (!merged.empty() && merged.back().first + merged.back().count >= first) {
            const uint32_t end = std::max(merged.back().first + merged.back().count, first + count);
            merged.back().count = end - merged.back().first;
        } else {
            merged.push_back({first, count});
        }
    }
    rows[index].parts = std::move(merged);
    rows[index].end = uint32_t(rows.size());
}

} // namespace

PartSet partSetOf(const PartRanges& ranges, uint32_t partCount) {
    PartSet set(partCount);
    for (const auto& [first, count] : ranges)
        for (uint32_t id = first; id < first + count; ++id) set.insert(id);
    return set;
}

std::vector<TreeRow> treeRows(const AssemblyNode& root) {
    std::vector<TreeRow> rows;
    addRows(root, "", 0, rows, root.name);
    return rows;
}

bool naturalLess(const std::string& a, const std::string& b) {
    auto digit = [](char c) { return c >= '0' && c <= '9'; };
    size_t i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        if (digit(a[i]) && digit(b[j])) {
            // Compare the runs as numbers: skip leading zeros, then the longer run is larger,
            // then the first differing digit decides.
            size_t ei = i, ej = j;
            while (ei < a.size() && digit(a[ei])) ++ei;
            while (ej < b.size() && digit(b[ej])) ++ej;
            size_t si = i, sj = j;
            while (si + 1 < ei && a[si] == '0') ++si;
            while (sj + 1 < ej && b[sj] == '0') ++sj;
            if (ei - si != ej - sj) return ei - si < ej - sj;
            const int order = a.compare(si, ei - si, b, sj, ej - sj);
            if (order != 0) return order < 0;
            i = ei;
            j = ej;
            continue;
        }
        const int x = std::tolower(static_cast<unsigned char>(a[i]));
        const int y = std::tolower(static_cast<unsigned char>(b[j]));
        if (x != y) return x < y;
        ++i;
        ++j;
    }
    if (a.size() - i != b.size() - j) return a.size() - i < b.size() - j;
    return a < b;
}

void sortNatural(AssemblyNode& node) {
    std::stable_sort(
        node.children.begin(), node.children.end(),
        [](const AssemblyNode& x, const AssemblyNode& y) { return naturalLess(x.name, y.name); });
    for (AssemblyNode& child : node.children) sortNatural(child);
}

std::optional<size_t> rowOfParts(const std::vector<TreeRow>& rows, const PartSet& selected) {
    const uint32_t wanted = selected.size();
    std::optional<size_t> found;
    for (size_t i = 0; i < rows.size(); ++i) {
        uint32_t total = 0, in = 0;
        for (const auto& [first, count] : rows[i].parts) {
            total += count;
            in += selected.countIn(first, count);
        }
        // Deeper rows come later in their subtree: the last match is the deepest.
        if (wanted > 0 && total == wanted && in == wanted) found = i;
    }
    return found;
}

} // namespace scene
