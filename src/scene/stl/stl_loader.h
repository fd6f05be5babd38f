// stl_loader.h - STL models, ASCII and binary, read through Open CASCADE's RWStl_Reader. Each
// `solid ... endsolid` block of an ASCII file (a binary file is one) becomes an object placing
// a geometry of one part, named after the solid; normals are computed (STL's facet normals
// are often wrong), smooth across an edge only where its facets meet at a small angle.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "scene/gltf/gltf_loader.h" // LoadResult
#include "scene/units.h"

namespace scene {

// Two facets whose normals differ by more than this meet at a crease: their shared corner
// gets a vertex (and a normal) for each side. CAD exports' curved surfaces come in facets a
// few degrees apart, their edges at 45 degrees and more.
constexpr double kStlCreaseDegrees = 30.0;

// True when `head` (at least the file's first 84 bytes) and the file's `size` make a binary
// STL: an 80-byte header, the triangle count (uint32, little-endian), 50 bytes a triangle
// and nothing after. ASCII files never match (the count would be read from text).
bool isBinaryStl(std::string_view head, uint64_t size);

// One `solid NAME ... endsolid` block of an ASCII STL text: its bytes [begin, end) and the
// line (from 1) it starts on.
struct StlBlock {
    std::string name;
    size_t begin = 0, end = 0;
    uint32_t line = 1;
};
// The blocks of an ASCII STL text, in order; a last block without its `endsolid` runs to the
// end. Throws std::runtime_error naming the line of any text outside a block.
std::vector<StlBlock> splitStlSolids(std::string_view text);

// STL stores no unit.
LengthUnit stlUnit();

// The whole file; every block with triangles is an object, an empty solid is skipped with a
// warning. Throws ModelError "<path>: <reason>".
LoadResult loadStl(const std::string& path);

} // namespace scene
