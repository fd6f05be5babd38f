// scene_codec.h - a Scene as bytes and back, for the CAD cache (scene/cad/cad_cache.h): every
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

    // One field, however it is stored: the record layouts below are written once, as
    // functions of `io(field)` that serve the writer and the reader alike.
    template <typename T>
    void operator()(const T& value) {
        put(value);
    }
    void operator()(const std::string& text) { putString(text); }
    template <typename T>
    void operator()(const std::vector<T>& values) {
        putArray(values);
    }
    template <typename T>
    void operator()(const SharedArray<T>& values) {
        putArray(values.get());
    }
    // A list of records, each written by fields(*this, record).
    template <typename T, typename Fields>
    void records(const std::vector<T>& values, Fields fields) {
        put(uint64_t(values.size()));
        for (const T& value : values) fields(*this, value);
    }
    template <typename T, typename Fields>
    void records(const SharedArray<T>& values, Fields fields) {
        records(values.get(), fields);
    }

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
        // An empty vector's data() may be null, which memcpy must not get even for 0 bytes.
        if (count) std::memcpy(values.data(), bytes_.data() + at_, count * sizeof(T));
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
    size_t left() const { return bytes_.size() - at_; }

    template <typename T>
    void operator()(T& value) {
        value = get<T>();
    }
    void operator()(std::string& text) { text = getString(); }
    template <typename T>
    void operator()(std::vector<T>& values) {
        values = getArray<T>();
    }
    template <typename T>
    void operator()(SharedArray<T>& values) {
        values = getArray<T>();
    }
    // A list of records, each read by fields(*this, record). Records take a byte at least, so
    // a damaged count stops at the end of the bytes, not at an allocation.
    template <typename T, typename Fields>
    void records(std::vector<T>& values, Fields fields) {
        const uint64_t count = get<uint64_t>();
        if (count > bytes_.size() - at_) throw std::runtime_error("count too large");
        values.clear();
        for (uint64_t i = 0; i < count; ++i) fields(*this, values.emplace_back());
    }
    template <typename T, typename Fields>
    void records(SharedArray<T>& values, Fields fields) {
        std::vector<T> read;
        records(read, fields);
        values = std::move(read);
    }

  private:
    void need(uint64_t size) const {
        if (size > bytes_.size() - at_) throw std::runtime_error("ends early");
    }
    std::string_view bytes_;
    size_t at_ = 0;
};

// A record's fields in the order they are stored, for a ByteWriter or a ByteReader alike:
// fields(io, r.a, r.b, r.c).
template <typename IO, typename... Fields>
void fields(IO& io, Fields&... each) {
    (io(each), ...);
}

void encodeScene(const Scene& scene, ByteWriter& out);
// Throws std::runtime_error where the bytes do not make a scene that scene::validate accepts
// (and whose per-part lists are as long as their geometry's parts).
Scene decodeScene(ByteReader& in);

} // namespace scene
