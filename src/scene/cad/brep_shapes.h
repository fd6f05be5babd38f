// brep_shapes.h - the exact B-rep behind a CAD scene, kept from the load so that edges,
// distances, volumes and centres of mass are answered from Open CASCADE's geometry rather
// than from triangles. One shape per full-detail geometry (levels of detail have none), in
// the geometry's own coordinates (an object's placement is applied when a query needs it),
// with its faces in the order Geometry::partFaces numbers them (the order of the read shape,
// kept through sewing). The tessellation cache stores them too (encodeBrep), so a file opened
// from the cache inspects exactly as one loaded anew.
// This header stays free of Open CASCADE types (brep_occt.h has them).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace scene {

class BrepShapes {
  public:
    struct Impl; // brep_occt.h
    explicit BrepShapes(std::unique_ptr<Impl> impl);
    ~BrepShapes();
    BrepShapes(const BrepShapes&) = delete;
    BrepShapes& operator=(const BrepShapes&) = delete;

    // Scene geometries covered (levels of detail and faceless shapes count, with no shape).
    uint32_t geometryCount() const;
    // Whether `geometry` has a shape, and how many faces it has.
    bool has(uint32_t geometry) const;
    uint32_t faceCount(uint32_t geometry) const;
    const Impl& impl() const { return *impl_; }

  private:
    std::unique_ptr<Impl> impl_;
};

// Open CASCADE's binary B-rep format (BinTools, without triangulations) plus each shape's face
// order: a few bytes per face and edge.
std::string encodeBrep(const BrepShapes& shapes);
// Throws std::runtime_error when the bytes do not hold what encodeBrep wrote.
std::shared_ptr<const BrepShapes> decodeBrep(std::string_view bytes);

} // namespace scene
