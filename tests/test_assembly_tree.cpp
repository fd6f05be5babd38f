// test_assembly_tree.cpp - the tree --tree prints (scene/assembly_tree.h, app::treeJson): on
// the car-like scene every object is exactly one node, where its path says, with its own
// unique parts; an object whose path runs through another's node hangs under it; two objects
// of one path stay two nodes; and a small scene prints exactly the JSON expected.
#include <gtest/gtest.h>

#include <functional>
#include <set>

#include "app/scene_source.h"
#include "scene/assembly_tree.h"
#include "scene/procedural.h"

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
