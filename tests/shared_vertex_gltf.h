// shared_vertex_gltf.h - writes the test model whose parts share vertices: one bumpy 9 x 9
// grid mesh whose 128 triangles are dealt to 32 primitives, all indexing one POSITION and one
// NORMAL accessor, placed by two nodes. A primitive's 4 triangles lie two rows of quads
// apart, so they share no vertex: every triangle needs a lead vertex of its own, 128 leads
// on 81 vertices, which forces vertex-fs to duplicate at least 47.
#pragma once

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace testing_support {

inline std::string base64(const std::vector<unsigned char>& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t n = uint32_t(bytes[i]) << 16 |
                           (i + 1 < bytes.size() ? uint32_t(bytes[i + 1]) << 8 : 0) |
                           (i + 2 < bytes.size() ? uint32_t(bytes[i + 2]) : 0);
        out += table[n >> 18 & 63];
        out += table[n >> 12 & 63];
        out += i + 1 < bytes.size() ? table[n >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? table[n & 63] : '=';
    }
    return out;
}

constexpr int sharedGridSide = 9;        // vertices per side
constexpr int sharedGridPrimitives = 32; // parts per mesh (primitives mode)
constexpr int sharedGridTriangles = 2 * 8 * 8;

// Which primitive triangle `t` of the grid goes to (16 triangles per row of quads).
inline int sharedGridPrimitiveOf(int t) {
    return t % sharedGridPrimitives;
}

// Writes the model into `base` with this process's ID appended (ctest runs test processes in
// parallel, and one must not read the file while another rewrites it); returns its path.
inline std::filesystem::path writeSharedVertexGltf(const std::filesystem::path& base) {
    const std::filesystem::path dir = base.string() + "-" + std::to_string(getpid());
    const int n = sharedGridSide;
    std::vector<float> positions, normals;
    auto height = [](float x, float y) { return 0.25f * std::sin(2.1f * x) * std::cos(1.7f * y); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float x = float(i) / float(n - 1) * 4.0f, y = float(j) / float(n - 1) * 4.0f;
            // glTF is y-up: the grid lies in x-z with bumps along y.
            positions.insert(positions.end(), {x, height(x, y), y});
            const float e = 1e-3f;
            const float dx = (height(x + e, y) - height(x - e, y)) / (2 * e);
            const float dy = (height(x, y + e) - height(x, y - e)) / (2 * e);
            const float len = std::sqrt(dx * dx + 1.0f + dy * dy);
            normals.insert(normals.end(), {-dx / len, 1.0f / len, -dy / len});
        }
    std::vector<std::vector<uint16_t>> indices(sharedGridPrimitives);
    int t = 0;
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const uint16_t a = uint16_t(j * n + i), b = uint16_t(a + 1), c = uint16_t(a + n),
                           d = uint16_t(c + 1);
            for (const auto& tri : {std::vector<uint16_t>{a, c, b}, {b, c, d}}) {
                auto& list = indices[size_t(sharedGridPrimitiveOf(t++))];
                list.insert(list.end(), tri.begin(), tri.end());
            }
        }

    std::vector<unsigned char> bin;
    auto append = [&](const void* data, size_t size) {
        const size_t offset = bin.size();
        bin.resize(offset + size);
        std::memcpy(bin.data() + offset, data, size);
        bin.resize((bin.size() + 3) & ~size_t(3));
        return offset;
    };
    const size_t posOffset = append(positions.data(), positions.size() * 4);
    const size_t nrmOffset = append(normals.data(), normals.size() * 4);
    std::string views = "{\"buffer\":0,\"byteOffset\":" + std::to_string(posOffset) +
                        ",\"byteLength\":" + std::to_string(positions.size() * 4) + "}," +
                        "{\"buffer\":0,\"byteOffset\":" + std::to_string(nrmOffset) +
                        ",\"byteLength\":" + std::to_string(normals.size() * 4) + "}";
    const int vertices = n * n;
    std::string accessors =
        "{\"bufferView\":0,\"componentType\":5126,\"count\":" + std::to_string(vertices) +
        ",\"type\":\"VEC3\",\"min\":[0,-0.3,0],\"max\":[4,0.3,4]},"
        "{\"bufferView\":1,\"componentType\":5126,\"count\":" +
        std::to_string(vertices) + ",\"type\":\"VEC3\"}";
    std::string primitives;
    for (int p = 0; p < sharedGridPrimitives; ++p) {
        const auto& list = indices[size_t(p)];
        const size_t offset = append(list.data(), list.size() * 2);
        views += ",{\"buffer\":0,\"byteOffset\":" + std::to_string(offset) +
                 ",\"byteLength\":" + std::to_string(list.size() * 2) + "}";
        accessors += ",{\"bufferView\":" + std::to_string(2 + p) +
                     ",\"componentType\":5123,\"count\":" + std::to_string(list.size()) +
                     ",\"type\":\"SCALAR\"}";
        primitives +=
            std::string(p ? "," : "") +
            "{\"attributes\":{\"POSITION\":0,\"NORMAL\":1},\"indices\":" + std::to_string(2 + p) +
            "}";
    }
    const std::string json =
        "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0,1]}],"
        "\"nodes\":[{\"mesh\":0},{\"mesh\":0,\"translation\":[4.5,0.5,0.5]}],"
        "\"meshes\":[{\"primitives\":[" +
        primitives + "]}],\"accessors\":[" + accessors + "],\"bufferViews\":[" + views +
        "],\"buffers\":[{\"byteLength\":" + std::to_string(bin.size()) +
        ",\"uri\":\"data:application/octet-stream;base64," + base64(bin) + "\"}]}";
    std::filesystem::create_directories(dir);
    const auto path = dir / "shared-vertices.gltf";
    std::ofstream(path) << json;
    return path;
}

} // namespace testing_support
