// gltf_accessor.cpp - reads glTF accessors (strided, sparse) after checking that every byte
// they name lies inside its bufferView and buffer; a hostile file cannot make us read past
// the data tinygltf loaded.
#include <cstring>

#include "scene/gltf/gltf_detail.h"

namespace scene::gltf {
namespace {

// Far above any real CAD export, low enough that count * 16 bytes never overflows and that
// an accessor without data (all zeros) cannot ask for gigabytes.
constexpr size_t kMaxCount = size_t(1) << 28;
constexpr size_t kMaxZeroFilledCount = size_t(1) << 24;

size_t componentSize(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return 4;
    default:
        return 0;
    }
}

std::string accessorName(int index) {
    return "accessor " + std::to_string(index);
}

// Where `count` elements of `elementSize` bytes lie: data == nullptr means all zeros.
struct Strided {
    const unsigned char* data = nullptr;
    size_t stride = 0;
};

// True when offset + stride * (count - 1) + elementSize <= length, without overflow.
bool rangeFits(size_t offset, size_t stride, size_t count, size_t elementSize, size_t length) {
    if (count == 0) return offset <= length;
    size_t span = 0, end = 0;
    if (__builtin_mul_overflow(stride, count - 1, &span)) return false;
    if (__builtin_add_overflow(span, elementSize, &end)) return false;
    if (__builtin_add_overflow(end, offset, &end)) return false;
    return end <= length;
}

const tinygltf::BufferView& checkedBufferView(const tinygltf::Model& model, int index,
                                              const std::string& who) {
    if (index < 0 || size_t(index) >= model.bufferViews.size())
        throw Bad(who + " refers to missing bufferView " + std::to_string(index));
    const tinygltf::BufferView& view = model.bufferViews[size_t(index)];
    const std::string name = "bufferView " + std::to_string(index);
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
        throw Bad(name + " refers to missing buffer " + std::to_string(view.buffer));
    size_t bufferSize = model.buffers[size_t(view.buffer)].data.size();
    if (!rangeFits(view.byteOffset, 0, 1, view.byteLength, bufferSize))
        throw Bad(name + " is out of bounds of buffer " + std::to_string(view.buffer) + " (" +
                  std::to_string(bufferSize) + " bytes)");
    return view;
}

// Locates `count` elements in a bufferView; strided views may interleave attributes.
Strided locate(const tinygltf::Model& model, int viewIndex, size_t byteOffset, size_t count,
               size_t elementSize, bool allowStride, const std::string& who) {
    const tinygltf::BufferView& view = checkedBufferView(model, viewIndex, who);
    size_t stride = elementSize;
    if (view.byteStride != 0) {
        if (!allowStride || view.byteStride < elementSize)
            throw Bad(who + " has an invalid byteStride " + std::to_string(view.byteStride));
        stride = view.byteStride;
    }
    if (!rangeFits(byteOffset, stride, count, elementSize, view.byteLength))
        throw Bad(who + " is out of bounds of bufferView " + std::to_string(viewIndex) + " (" +
                  std::to_string(view.byteLength) + " bytes)");
    const auto& buffer = model.buffers[size_t(view.buffer)].data;
    return {buffer.data() + view.byteOffset + byteOffset, stride};
}

const tinygltf::Accessor& checkedAccessor(const tinygltf::Model& model, int index, int expectedType,
                                          const std::string& what) {
    if (index < 0 || size_t(index) >= model.accessors.size())
        throw Bad(what + " refers to missing accessor " + std::to_string(index));
    const tinygltf::Accessor& a = model.accessors[size_t(index)];
    if (a.type != expectedType)
        throw Bad(accessorName(index) + " (" + what + ") has the wrong element type");
    if (a.count > kMaxCount)
        throw Bad(accessorName(index) + " has an absurd count " + std::to_string(a.count));
    if (a.bufferView < 0 && a.count > kMaxZeroFilledCount)
        throw Bad(accessorName(index) + " has no data but an absurd count");
    return a;
}

uint32_t readIndexAt(const unsigned char* p, size_t size) {
    if (size == 1) return *p;
    if (size == 2) {
        uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
    }
    uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
}

// Copies elements of `elementSize` bytes into `out` (tightly packed), zeros where no data.
void gather(const Strided& src, size_t count, size_t elementSize, unsigned char* out) {
    if (count == 0) return; // `out` may be null then, and memset/memcpy forbid null
    if (!src.data) {
        std::memset(out, 0, count * elementSize);
        return;
    }
    for (size_t i = 0; i < count; ++i)
        std::memcpy(out + i * elementSize, src.data + i * src.stride, elementSize);
}

// Sparse accessors replace some elements of the base data (glTF 2.0 section 3.6.2.3).
void applySparse(const tinygltf::Model& model, int index, const tinygltf::Accessor& a,
                 size_t elementSize, unsigned char* out) {
    const auto& sparse = a.sparse;
    const std::string who = accessorName(index) + " sparse";
    if (sparse.count <= 0 || size_t(sparse.count) > a.count)
        throw Bad(who + " count " + std::to_string(sparse.count) + " is invalid");
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
        throw Bad(who + " has a negative byteOffset");
    size_t count = size_t(sparse.count);
    size_t indexSize = componentSize(sparse.indices.componentType);
    if (indexSize == 0 || sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
        sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_SHORT ||
        sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT)
        throw Bad(who + " indices have an invalid component type");
    Strided indices = locate(model, sparse.indices.bufferView, size_t(sparse.indices.byteOffset),
                             count, indexSize, false, who + " indices");
    Strided values = locate(model, sparse.values.bufferView, size_t(sparse.values.byteOffset),
                            count, elementSize, false, who + " values");
    for (size_t i = 0; i < count; ++i) {
        uint32_t target = readIndexAt(indices.data + i * indexSize, indexSize);
        if (target >= a.count)
            throw Bad(who + " index " + std::to_string(target) + " is out of range");
        std::memcpy(out + size_t(target) * elementSize, values.data + i * elementSize, elementSize);
    }
}

// Reads a whole accessor as tightly packed elements of `elementSize` bytes.
std::vector<unsigned char> readRaw(const tinygltf::Model& model, int index,
                                   const tinygltf::Accessor& a, size_t elementSize) {
    std::vector<unsigned char> out(a.count * elementSize);
    Strided base;
    if (a.bufferView >= 0)
        base = locate(model, a.bufferView, a.byteOffset, a.count, elementSize, true,
                      accessorName(index));
    gather(base, a.count, elementSize, out.data());
    if (a.sparse.isSparse) applySparse(model, index, a, elementSize, out.data());
    return out;
}

} // namespace

std::vector<glm::vec3> readVec3(const tinygltf::Model& model, int index, const std::string& what) {
    const tinygltf::Accessor& a = checkedAccessor(model, index, TINYGLTF_TYPE_VEC3, what);
    // Core glTF 2.0 allows only float positions and normals (quantization is an extension).
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
        throw Bad(accessorName(index) + " (" + what + ") must have float components");
    std::vector<unsigned char> raw = readRaw(model, index, a, sizeof(glm::vec3));
    std::vector<glm::vec3> out(a.count);
    if (!raw.empty()) std::memcpy(out.data(), raw.data(), raw.size());
    return out;
}

std::vector<uint32_t> readIndices(const tinygltf::Model& model, int index) {
    const tinygltf::Accessor& a = checkedAccessor(model, index, TINYGLTF_TYPE_SCALAR, "indices");
    size_t size = componentSize(a.componentType);
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        throw Bad(accessorName(index) + " (indices) must be unsigned 8, 16 or 32 bit");
    std::vector<unsigned char> raw = readRaw(model, index, a, size);
    std::vector<uint32_t> out(a.count);
    for (size_t i = 0; i < a.count; ++i) out[i] = readIndexAt(raw.data() + i * size, size);
    return out;
}

} // namespace scene::gltf
