// scene_codec.h - a Scene as bytes and back, for the CAD cache (scene/cad_cache.h): every
// array and name, the parts' faces, surfaces and materials, the levels of detail, the
// objects' placements and paths. Little-endian as the host lays it out; the cache's format
// version changes with the layout. Plain C++.
#pragma once

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "scene/scene.h"

namespace scene {

// Appends values to a byte string.
class ByteWriter {
  public:
    template <typename T>
    void put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T));
    }
    template <typename T>
    void putArray(const std::vector<T>& values) {
        static_assert(std::is_trivially_copyable_v<T>);
        put(uint64_t(values.size()));
        bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    }
    void putString(const std::string& text) {
        put(uint64_t(text.size()));
        bytes_ += text;
    }
    std::string& bytes() { return bytes_; }

  private:
    std::string bytes_;
};

// Reads them back, every read checked against the bytes left: a damaged count throws
// std::runtime_error instead of reading past the end or allocating what is not there.
class ByteReader {
  public:
    explicit ByteReader(std::string_view bytes) : bytes_(bytes) {}
    template <typename T>
    T get() {
        static_assert(std::is_trivially_copyable_v<T>);
        need(sizeof(T));
        T value;
        std::memcpy(&value, bytes_.data() + at_, sizeof(T));
        at_ += sizeof(T);
        return value;
    }
    template <typename T>
    std::vector<T> getArray() {
        const uint64_t count = get<uint64_t>();
        if (count > (bytes_.size() - at_) / sizeof(T)) throw std::runtime_error("array too long");
        std::vector<T> values(count);
        std::memcpy(values.data(), bytes_.data() + at_, count * sizeof(T));
        at_ += count * sizeof(T);
        return values;
    }
    std::string getString() { return std::string(getBytes()); }
    // A length-prefixed run of bytes, viewed where it lies (no copy).
    std::string_view getBytes() {
        const uint64_t size = get<uint64_t>();
        need(size);
        const std::string_view bytes = bytes_.substr(at_, size);
        at_ += size;
        return bytes;
    }
    bool done() const { return at_ == bytes_.size(); }

  private:
    void need(uint64_t size) const {
        if (size > bytes_.size() - at_) throw std::runtime_error("ends early");
    }
    std::string_view bytes_;
    size_t at_ = 0;
};

void encodeScene(const Scene& scene, ByteWriter& out);
// Throws std::runtime_error where the bytes do not make a scene that scene::validate accepts
// (and whose per-part lists are as long as their geometry's parts).
Scene decodeScene(ByteReader& in);

} // namespace scene
