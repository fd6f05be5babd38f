// brep_shapes.h - the exact B-rep behind a CAD scene, kept from the load so that edges,
// distances, volumes and centres of mass are answered from Open CASCADE's geometry rather
// than from triangles. One shape per full-detail geometry (levels of detail have none), in
// the geometry's own coordinates (an object's placement is applied when a query needs it),
// with its faces in the order Geometry::partFaces numbers them.
//
// Shapes are held encoded (Open CASCADE's binary format, a few bytes per face and edge, see
// encodeShape) and decoded one geometry at a time, the first time a query asks for it: an
// assembly of thousands of solids keeps in memory only the solids a person inspects. The bytes
// are in memory, or in the tessellation cache's entry (cad_cache.h), read back from it when
// asked. This header stays free of Open CASCADE types (brep_occt.h has them).
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace scene {

// Where encoded shapes lie when they are not in memory: a byte range of a file, checked by a
// hash when read (the tessellation cache's entry).
class EncodedShapeFile {
  public:
    virtual ~EncodedShapeFile() = default;
    // The bytes at [offset, offset + size); throws std::runtime_error where they cannot be read
    // or their hash is not `hash`.
    virtual std::string read(uint64_t offset, uint64_t size, uint64_t hash) const = 0;
};

// The faces an encoded shape (encodeShape, brep_occt.h) holds, read without decoding it; throws
// std::runtime_error on bytes too short for it.
uint32_t encodedFaceCount(std::string_view bytes);

class BrepShapes {
  public:
    struct Shape; // brep_occt.h: the shape and its faces by B-rep face number

    // One geometry's shape as stored: encoded bytes in memory, or a range of `file`; none at
    // all where `faces` is 0 and there are no bytes (a level of detail, a model geometry).
    struct Stored {
        uint32_t faces = 0;
        std::string bytes; // encodeShape's, or empty where the file holds them
        uint64_t offset = 0, size = 0, hash = 0;
        bool present = false;
    };
    BrepShapes(std::vector<Stored> stored, std::shared_ptr<const EncodedShapeFile> file = {});
    ~BrepShapes();
    BrepShapes(const BrepShapes&) = delete;
    BrepShapes& operator=(const BrepShapes&) = delete;

    // Scene geometries covered (levels of detail and faceless shapes count, with no shape).
    uint32_t geometryCount() const { return uint32_t(stored_.size()); }
    // Whether `geometry` has a shape, and how many faces it has: known without decoding it.
    bool has(uint32_t geometry) const;
    uint32_t faceCount(uint32_t geometry) const;
    // The shape, decoded (and read from the file) the first time; safe from any thread.
    // Throws std::runtime_error where its bytes cannot be read back.
    const Shape& shape(uint32_t geometry) const;
    // Its bytes as encodeShape wrote them (from memory or the file), for the cache's writer.
    std::string encoded(uint32_t geometry) const;
    const Stored& stored(uint32_t geometry) const { return stored_[geometry]; }
    // Shapes decoded so far (for --stats and tests).
    uint32_t decodedCount() const;

  private:
    std::vector<Stored> stored_;
    std::shared_ptr<const EncodedShapeFile> file_;
    mutable std::mutex mutex_;
    mutable std::vector<std::unique_ptr<Shape>> decoded_;
};

} // namespace scene
