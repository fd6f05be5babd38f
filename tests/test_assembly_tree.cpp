// test_assembly_tree.cpp - the tree --tree prints (scene/assembly_tree.h, app::treeJson): on
// the car-like scene every object is exactly one node, where its path says, with its own
// unique parts; an object whose path runs through another's node hangs under it; two objects
// of one path stay two nodes; and a small scene prints exactly the JSON expected.
#include <gtest/gtest.h>

#include <functional>
#include <set>

#include "app/scene_source.h"
#include "scene/assembly_tree.h"
#include "scene/procedural/procedural.h"

using namespace scene;

namespace {

// Every object's node and the path of names from below the root down to it.
void collect(const AssemblyNode& node, const std::string& path,
             std::vector<std::pair<uint32_t, std::string>>& found,
             std::vector<const AssemblyNode*>& nodes) {
    for (const AssemblyNode& child : node.children) {
        const std::string here = path.empty() ? child.name : path + "/" + child.name;
        if (child.object) {
            found.emplace_back(*child.object, here);
            nodes.push_back(&child);
        }
        collect(child, here, found, nodes);
    }
}

// A scene of one one-part geometry placed by objects of the given paths.
Scene withPaths(const std::vector<std::string>& paths) {
    Scene s;
    s.vertices = {{{0, 0, 0}, {0, 0, 1}}, {{1, 0, 0}, {0, 0, 1}}, {{0, 1, 0}, {0, 0, 1}}};
    s.indices = {0, 1, 2};
    s.parts = {{0, 1}};
    Geometry g;
    g.vertexCount = 3;
    g.triangleCount = 1;
    g.partCount = 1;
    s.geometries.push_back(g);
    addMaterial(s, "grey", glm::vec4(0.5f));
    for (const std::string& path : paths)
        addObject(s, 0, 0, glm::mat4(1.0f), path.substr(path.rfind('/') + 1), path);
    return s;
}

} // namespace

TEST(AssemblyTree, EveryObjectIsOneNodeWhereItsPathSays) {
    const Scene s = makeProcedural({"car-like", 1});
    const AssemblyNode root = assemblyTree(s, "car");
    EXPECT_EQ(root.name, "car");
    std::vector<std::pair<uint32_t, std::string>> found;
    std::vector<const AssemblyNode*> nodes;
    collect(root, "", found, nodes);
    ASSERT_EQ(found.size(), s.objects.size());
    std::vector<bool> seen(s.objects.size(), false);
    for (size_t i = 0; i < found.size(); ++i) {
        const auto& [o, path] = found[i];
        ASSERT_LT(o, s.objects.size());
        EXPECT_FALSE(seen[o]) << "object " << o << " twice";
        seen[o] = true;
        EXPECT_EQ(path, s.objects[o].path);
        EXPECT_EQ(nodes[i]->firstPart, s.objects[o].uniquePartOffset);
        EXPECT_EQ(nodes[i]->partCount, s.geometries[s.objects[o].geometry].partCount);
    }
    // Groups are not repeated under one parent.
    std::function<void(const AssemblyNode&)> unique = [&](const AssemblyNode& node) {
        std::set<std::string> groups;
        for (const AssemblyNode& child : node.children) {
            if (!child.object) {
                EXPECT_TRUE(groups.insert(child.name).second) << child.name;
            }
            unique(child);
        }
    };
    unique(root);
}

TEST(AssemblyTree, ObjectsJoinGroupsAndNeverEachOther) {
    const Scene s = withPaths({"frame/bracket", "frame/bracket/bolt", "frame/bracket", "nut"});
    const AssemblyNode root = assemblyTree(s, "r");
    ASSERT_EQ(root.children.size(), 2u); // frame, nut
    const AssemblyNode& frame = root.children[0];
    EXPECT_FALSE(frame.object.has_value());
    ASSERT_EQ(frame.children.size(), 2u); // the bracket with its bolt, and the second bracket
    EXPECT_EQ(frame.children[0].object, 0u);
    ASSERT_EQ(frame.children[0].children.size(), 1u);
    EXPECT_EQ(frame.children[0].children[0].object, 1u);
    EXPECT_EQ(frame.children[1].object, 2u);
    EXPECT_EQ(root.children[1].object, 3u);
}

TEST(AssemblyTree, PrintsTheJsonExpected) {
    app::LoadedScene loaded;
    loaded.source = "/models/small.step";
    loaded.scene = withPaths({"a/b", "a/b/c", "d"});
    EXPECT_EQ(app::treeJson(loaded),
              "{\"name\":\"small.step\",\"children\":[{\"name\":\"a\",\"children\":[{\"name\":"
              "\"b\",\"object\":0,\"parts\":[0,1],\"children\":[{\"name\":\"c\",\"object\":1,"
              "\"parts\":[1,1]}]}]},{\"name\":\"d\",\"object\":2,\"parts\":[2,1]}]}");
}

// The rows the panel draws: depth-first, each row's subtree the rows up to its end, its
// parts exactly the parts of the objects in it (counted here from the objects' paths).
TEST(AssemblyTree, RowsHoldEachSubtreeAndItsParts) {
    const Scene s = makeProcedural({"car-like", 1});
    const std::vector<TreeRow> rows = treeRows(assemblyTree(s, "car"));
    ASSERT_FALSE(rows.empty());
    EXPECT_EQ(rows[0].end, rows.size());
    EXPECT_EQ(rows[0].depth, 0u);
    size_t objects = 0;
    for (size_t i = 0; i < rows.size(); ++i) {
        const TreeRow& row = rows[i];
        ASSERT_GT(row.end, i);
        ASSERT_LE(row.end, rows.size());
        for (size_t r = i + 1; r < row.end; ++r) EXPECT_GT(rows[r].depth, row.depth);
        if (row.end < rows.size()) {
            EXPECT_LE(rows[row.end].depth, row.depth);
        }
        if (row.object) {
            ++objects;
            EXPECT_EQ(row.path, s.objects[*row.object].path);
        }
        // Independently: the parts of every object whose path is this row's or below it.
        PartSet expected(s.uniquePartCount()), got(s.uniquePartCount());
        for (const Object& o : s.objects)
            if (i == 0 || o.path == row.path || o.path.starts_with(row.path + "/"))
                for (uint32_t p = 0; p < s.geometries[o.geometry].partCount; ++p)
                    expected.insert(o.uniquePartOffset + p);
        for (size_t k = 0; k < row.parts.size(); ++k) {
            const auto [first, count] = row.parts[k];
            EXPECT_GT(count, 0u);
            if (k > 0) {
                EXPECT_GT(first, row.parts[k - 1].first + row.parts[k - 1].count);
            }
            for (uint32_t p = first; p < first + count; ++p) got.insert(p);
        }
        EXPECT_EQ(got, expected) << row.path;
    }
    EXPECT_EQ(objects, s.objects.size());
}

TEST(PartSet, CountsMembersInARange) {
    PartSet set(100);
    for (uint32_t id : {0u, 31u, 32u, 33u, 64u, 99u}) set.insert(id);
    for (uint32_t first = 0; first < 100; first += 7)
        for (uint32_t count = 0; first + count <= 100; count += 5) {
            uint32_t expected = 0;
            for (uint32_t id = first; id < first + count; ++id) expected += set.contains(id);
            EXPECT_EQ(set.countIn(first, count), expected) << first << "+" << count;
            EXPECT_EQ(set.anyIn(first, count), expected > 0);
            EXPECT_EQ(set.allIn(first, count), expected == count);
        }
    EXPECT_EQ(set.countIn(90, 50), 1u); // clamped to the set's parts
}

// Around a part at each level, on hand-made paths: the bolt's parent node is the first
// bracket (object 0), whose path the third object shares; "framework" is no part of "frame".
TEST(AssemblyTree, PartsAroundAPartGrowWithTheLevel) {
    const Scene s = withPaths({"frame/bracket", "frame/bracket/bolt", "frame/plate", "nut",
                               "frame/bracket", "framework"});
    using R = std::vector<PartRange>;
    EXPECT_EQ(partsAround(s, 1, 0), (R{{1, 1}}));
    EXPECT_EQ(partsAround(s, 1, 1), (R{{1, 1}}));
    EXPECT_EQ(partsAround(s, 1, 2), (R{{0, 2}, {4, 1}}));
    EXPECT_EQ(partsAround(s, 1, 3), (R{{0, 3}, {4, 1}}));
    EXPECT_EQ(partsAround(s, 1, 9), (R{{0, 3}, {4, 1}})); // never past "frame"
    EXPECT_EQ(partsAround(s, 0, 2), (R{{0, 3}, {4, 1}}));
    EXPECT_EQ(partsAround(s, 3, 5), (R{{3, 1}})); // at the root: alone
    EXPECT_EQ(partsAround(s, 5, 2), (R{{5, 1}}));
    EXPECT_TRUE(partsAround(s, 6, 1).empty()); // no such part
}

TEST(AssemblyTree, NaturalOrderComparesNumbersAsNumbers) {
    EXPECT_TRUE(naturalLess("solid 2", "solid 10"));
    EXPECT_FALSE(naturalLess("solid 10", "solid 2"));
    EXPECT_TRUE(naturalLess("Bolt", "nut")); // letters without case
    EXPECT_TRUE(naturalLess("part 007", "part 8"));
    EXPECT_TRUE(naturalLess("part", "part 1")); // a prefix first
    EXPECT_FALSE(naturalLess("same", "same"));
    EXPECT_NE(naturalLess("a", "A"), naturalLess("A", "a")); // a total order still
}

TEST(AssemblyTree, SortedRowsTellSameNamesApartAndNameASelection) {
    // Two objects of one path are two nodes of one name; siblings come out sorted.
    const Scene s = withPaths({"box/solid 10", "box/solid 2", "box/solid 2", "box/Bolt"});
    AssemblyNode root = assemblyTree(s, "model");
    sortNatural(root);
    const std::vector<TreeRow> rows = treeRows(root);
    std::vector<std::string> labels;
    for (const TreeRow& row : rows) labels.push_back(row.label);
    EXPECT_EQ(labels, (std::vector<std::string>{"model", "box", "Bolt", "solid 2 #1", "solid 2 #2",
                                                "solid 10"}));
    // The selection of exactly one row's parts is named by it, the deepest such row.
    for (size_t i = 0; i < rows.size(); ++i) {
        const auto found = rowOfParts(rows, partSetOf(rows[i].parts, s.uniquePartCount()));
        ASSERT_TRUE(found) << i;
        // The root and "box" hold the same parts: the deeper "box" names them.
        EXPECT_EQ(*found, i == 0 ? 1u : i) << labels[i];
    }
    PartSet two(s.uniquePartCount());
    two.insert(rows[2].parts[0].first);
    two.insert(rows[5].parts[0].first); // parts of two rows, no one row's: unnamed
    EXPECT_FALSE(rowOfParts(rows, two));
    EXPECT_FALSE(rowOfParts(rows, PartSet(s.uniquePartCount())));
}
