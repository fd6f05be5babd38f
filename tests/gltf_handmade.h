// gltf_handmade.h - what the glTF loader tests share: small glTF documents built in memory
// (buffers, views, accessors, a quad), the ModelError checks and the GltfHandmade fixture that
// writes a document to a file and loads it. For tests only: its helpers are file-local to
// each test file that includes it.
#pragma once

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>

#include <gtest/gtest.h>

#include "scene/gltf/gltf_loader.h"

namespace {

namespace fs = std::filesystem;
using scene::LoadResult;
using scene::ModelError;
using scene::PartMode;

const fs::path kCorpus = "/usr/share/assimp/models/glTF2";

// ---- helpers ---------------------------------------------------------------------------

// Asserts the ModelError contract: one line "<path>: <reason>", reason containing `needle`.
void expectModelError(const std::function<void()>& load, const std::string& path,
                      const std::string& needle) {
    try {
        load();
        ADD_FAILURE() << path << " loaded, expected a ModelError mentioning '" << needle << "'";
    } catch (const ModelError& e) {
        std::string what = e.what();
        EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        EXPECT_NE(what.find(needle), std::string::npos) << what;
    }
}

struct Stats {
    size_t objects, geometries, parts;
    uint32_t uniqueParts;
    uint64_t drawnTriangles;
};

Stats statsOf(const scene::Scene& s) {
    return {s.objects.size(), s.geometries.size(), s.parts.size(), s.uniquePartCount(),
            s.drawnTriangleCount()};
}

// Not every file that includes this uses every helper: [[maybe_unused]].
[[maybe_unused]] void expectStats(const std::string& file, PartMode mode, Stats want) {
    LoadResult r = scene::loadGltf((kCorpus / file).string(), {mode});
    EXPECT_NO_THROW(scene::validate(r.scene));
    Stats got = statsOf(r.scene);
    EXPECT_EQ(got.objects, want.objects) << file;
    EXPECT_EQ(got.geometries, want.geometries) << file;
    EXPECT_EQ(got.parts, want.parts) << file;
    EXPECT_EQ(got.uniqueParts, want.uniqueParts) << file;
    EXPECT_EQ(got.drawnTriangles, want.drawnTriangles) << file;
}

// Binary data for handmade files; each append is 4-byte aligned as accessors require.
struct Blob {
    std::vector<unsigned char> bytes;
    size_t add(const void* data, size_t size) {
        while (bytes.size() % 4) bytes.push_back(0);
        size_t offset = bytes.size();
        auto p = static_cast<const unsigned char*>(data);
        bytes.insert(bytes.end(), p, p + size);
        return offset;
    }
    template <class T>
    size_t add(const std::vector<T>& v) {
        return add(v.data(), v.size() * sizeof(T));
    }
};

std::string base64(const std::vector<unsigned char>& in) {
    static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < in.size(); i += 3) {
        uint32_t n = uint32_t(in[i]) << 16;
        if (i + 1 < in.size()) n |= uint32_t(in[i + 1]) << 8;
        if (i + 2 < in.size()) n |= in[i + 2];
        out += abc[n >> 18 & 63];
        out += abc[n >> 12 & 63];
        out += i + 1 < in.size() ? abc[n >> 6 & 63] : '=';
        out += i + 2 < in.size() ? abc[n & 63] : '=';
    }
    return out;
}

// A glTF document: `rest` holds every top-level member but asset and buffers.
std::string gltfJson(const Blob& blob, const std::string& rest) {
    return R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":)" +
           std::to_string(blob.bytes.size()) + R"(,"uri":"data:application/octet-stream;base64,)" +
           base64(blob.bytes) + "\"}]," + rest + "}";
}

std::vector<unsigned char> glb(const std::string& json, const std::vector<unsigned char>& bin) {
    std::string j = json;
    while (j.size() % 4) j += ' ';
    std::vector<unsigned char> b = bin;
    while (b.size() % 4) b.push_back(0);
    std::vector<unsigned char> out = {'g', 'l', 'T', 'F'};
    auto u32 = [&](uint32_t v) {
        for (int i = 0; i < 4; ++i) out.push_back((unsigned char)(v >> (8 * i)));
    };
    u32(2);
    u32(uint32_t(12 + 8 + j.size() + 8 + b.size()));
    u32(uint32_t(j.size()));
    u32(0x4E4F534A); // JSON
    out.insert(out.end(), j.begin(), j.end());
    u32(uint32_t(b.size()));
    u32(0x004E4942); // BIN
    out.insert(out.end(), b.begin(), b.end());
    return out;
}

class GltfHandmade : public ::testing::Test {
  protected:
    fs::path dir_;
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("idview_gltf_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& text) {
        return write(name, std::vector<unsigned char>(text.begin(), text.end()));
    }
    std::string write(const std::string& name, const std::vector<unsigned char>& bytes) {
        fs::path p = dir_ / name;
        std::ofstream(p, std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        return p.string();
    }
    LoadResult load(const std::string& json, PartMode mode = PartMode::Primitives) {
        LoadResult r = scene::loadGltf(write("model.gltf", json), {mode});
        EXPECT_NO_THROW(scene::validate(r.scene));
        return r;
    }
    void expectError(const std::string& json, const std::string& needle) {
        std::string path = write("bad.gltf", json);
        expectModelError([&] { scene::loadGltf(path); }, path, needle);
    }
};

// A unit quad in the xy-plane, counter-clockwise seen from +z.
const std::vector<glm::vec3> kQuad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const std::vector<uint32_t> kQuadIndices = {0, 1, 2, 0, 2, 3};

std::string accessor(size_t view, int componentType, size_t count, const char* type,
                     const std::string& extra = "") {
    return R"({"bufferView":)" + std::to_string(view) + R"(,"componentType":)" +
           std::to_string(componentType) + R"(,"count":)" + std::to_string(count) + R"(,"type":")" +
           type + "\"" + extra + "}";
}

std::string view(size_t offset, size_t length, const std::string& extra = "") {
    return R"({"buffer":0,"byteOffset":)" + std::to_string(offset) + R"(,"byteLength":)" +
           std::to_string(length) + extra + "}";
}

// One mesh with one primitive, one node, one scene.
std::string singleMesh(const std::string& views, const std::string& accessors,
                       const std::string& primitive, const std::string& node = R"({"mesh":0})") {
    return R"("bufferViews":[)" + views + R"(],"accessors":[)" + accessors +
           R"(],"meshes":[{"primitives":[)" + primitive + R"(]}],"nodes":[)" + node +
           R"(],"scenes":[{"nodes":[0]}],"scene":0)";
}

// Vertex `corner` of triangle `tri` of the first geometry, in geometry-local space.
const scene::Vertex& corner(const scene::Scene& s, uint32_t tri, uint32_t c) {
    const scene::Geometry& g = s.geometries[0];
    return s.vertices[g.firstVertex + s.indices[g.firstIndex + 3 * tri + c]];
}

[[maybe_unused]] void expectTriangle(const scene::Scene& s, uint32_t tri, glm::vec3 a, glm::vec3 b,
                                     glm::vec3 c) {
    EXPECT_EQ(corner(s, tri, 0).position, a) << "triangle " << tri;
    EXPECT_EQ(corner(s, tri, 1).position, b) << "triangle " << tri;
    EXPECT_EQ(corner(s, tri, 2).position, c) << "triangle " << tri;
}

// A quad with indices of `componentType`, packed as `T`.
template <class T>
std::string quadWithIndices(int componentType) {
    Blob blob;
    std::vector<T> idx(kQuadIndices.begin(), kQuadIndices.end());
    size_t p = blob.add(kQuad), i = blob.add(idx);
    return gltfJson(blob, singleMesh(view(p, 48) + "," + view(i, idx.size() * sizeof(T)),
                                     accessor(0, 5126, 4, "VEC3") + "," +
                                         accessor(1, componentType, 6, "SCALAR"),
                                     R"({"attributes":{"POSITION":0},"indices":1})"));
}

} // namespace
