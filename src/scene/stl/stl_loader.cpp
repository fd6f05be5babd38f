// stl_loader.cpp - loadStl: the file read by Open CASCADE's RWStl_Reader solid by solid, and
// each solid built into an object of its own.
//
// RWStl_Reader is a plain parser: unlike the STEP and IGES readers it touches none of Open
// CASCADE's global data-exchange state (Interface_Static, the XDE application), so STL files
// are read in this process, on the loading thread (never the viewer's UI thread), with no
// worker process. Its only global is the default messenger it reports errors to, which
// quietOcct empties of printers (the reason given here is idview's own).
#include "scene/stl/stl_loader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>

#include <RWStl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <Standard_ReadLineBuffer.hxx>

#include "scene/cad/cad_stages.h"
#include "scene/mesh_builder.h"

namespace scene {
namespace {

namespace fs = std::filesystem;

struct Bad : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A bound on what is read into memory whole, as for the CAD readers: far beyond any sample.
constexpr uintmax_t kMaxStlBytes = uintmax_t(1) << 31;
// RWStl_Reader's line buffer: facet lines are short, this is its chunk of the text.
constexpr size_t kLineBufferBytes = size_t(1) << 16;

struct Solid {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> corners; // 3 a triangle
    bool finite = true;
};

// Takes RWStl_Reader's nodes (merged where equal, split at creases) and triangles (the
// degenerate ones it drops) into one Solid.
class SolidReader final : public RWStl_Reader {
  public:
    explicit SolidReader(Solid& into) : into_(into) {
        SetMergeAngle(kStlCreaseDegrees * M_PI / 180.0);
    }
    Standard_Integer AddNode(const gp_XYZ& p) override {
        into_.finite &= std::isfinite(p.X()) && std::isfinite(p.Y()) && std::isfinite(p.Z());
        into_.positions.emplace_back(float(p.X()), float(p.Y()), float(p.Z()));
        return Standard_Integer(into_.positions.size() - 1);
    }
    void AddTriangle(Standard_Integer a, Standard_Integer b, Standard_Integer c) override {
        into_.corners.insert(into_.corners.end(), {uint32_t(a), uint32_t(b), uint32_t(c)});
    }

  private:
    Solid& into_;
};

std::string lowercase(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string_view trimmed(std::string_view text) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
        text.remove_prefix(1);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
        text.remove_suffix(1);
    return text;
}

// The block's text without its blank lines, which RWStl_Reader takes for a broken facet.
std::string withoutBlankLines(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    while (!text.empty()) {
        const size_t eol = text.find('\n');
        const std::string_view line = text.substr(0, eol == text.npos ? text.size() : eol + 1);
        if (!trimmed(line).empty()) out.append(line);
        text.remove_prefix(line.size());
    }
    return out;
}

std::vector<Solid> readAscii(const std::string& text) {
    std::vector<Solid> solids;
    for (const StlBlock& block : splitStlSolids(text)) {
        Solid& solid = solids.emplace_back();
        solid.name = block.name;
        std::istringstream in(
            withoutBlankLines(std::string_view(text).substr(block.begin, block.end - block.begin)));
        const auto size = std::streampos(std::streamoff(in.str().size()));
        Standard_ReadLineBuffer buffer(kLineBufferBytes);
        Handle(SolidReader) reader = new SolidReader(solid);
        bool read = false;
        cad::guarded("reading the STL file",
                     [&] { read = reader->ReadAscii(in, buffer, size, Message_ProgressRange()); });
        if (!read)
            throw Bad("not a readable ASCII STL file: the solid from line " +
                      std::to_string(block.line) + " has a malformed facet");
    }
    return solids;
}

std::vector<Solid> readBinary(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<Solid> solids(1);
    Handle(SolidReader) reader = new SolidReader(solids[0]);
    bool read = false;
    cad::guarded("reading the STL file",
                 [&] { read = reader->ReadBinary(in, Message_ProgressRange()); });
    if (!read) throw Bad("not a readable binary STL file: it ends before its last triangle");
    return solids;
}

std::vector<Solid> readSolids(const std::string& path) {
    std::error_code ec;
    const uintmax_t size = fs::file_size(path, ec);
    if (ec) throw Bad("cannot read the file size: " + ec.message());
    if (size > kMaxStlBytes) throw Bad("file too large (" + std::to_string(size) + " bytes)");
    std::ifstream in(path, std::ios::binary);
    std::string text(std::min<uintmax_t>(size, 84), '\0');
    in.read(text.data(), std::streamsize(text.size()));
    if (isBinaryStl(text, size)) return readBinary(path);
    const size_t head = text.size();
    text.resize(size);
    in.read(text.data() + head, std::streamsize(size - head));
    if (!in) throw Bad("cannot read the whole file");
    return readAscii(text);
}

// The solid's name, or the file's for a file of one unnamed solid, or "solid N".
std::string objectName(const Solid& solid, size_t index, size_t count, const std::string& stem) {
    if (!solid.name.empty()) return solid.name;
    return count == 1 ? stem : "solid " + std::to_string(index + 1);
}

void addSolid(Scene& scene, const Solid& solid, const std::string& name, uint32_t material) {
    for (const uint32_t corner : solid.corners)
        if (corner >= solid.positions.size())
            throw Bad("the reader gave a triangle without a node");
    if (!solid.finite) throw Bad("solid '" + name + "' has a coordinate that is no finite number");
    const std::vector<glm::vec3> normals = areaWeightedNormals(solid.positions, solid.corners);
    MeshBuilder builder;
    builder.beginPart();
    for (size_t v = 0; v < solid.positions.size(); ++v)
        builder.addVertex(solid.positions[v], normals[v]);
    for (size_t i = 0; i + 2 < solid.corners.size(); i += 3)
        builder.addTriangle(solid.corners[i], solid.corners[i + 1], solid.corners[i + 2]);
    const uint32_t geometry = builder.finish(scene, name);
    addObject(scene, geometry, material, glm::dmat4(1.0), name, name);
}

LoadResult loadHere(const std::string& path) {
    cad::quietOcct();
    const std::vector<Solid> solids = readSolids(path);
    const std::string stem = fs::path(path).stem().string();
    LoadResult result;
    const uint32_t material = addMaterial(result.scene, "STL", Material{}.color);
    for (size_t i = 0; i < solids.size(); ++i) {
        const std::string name = objectName(solids[i], i, solids.size(), stem);
        if (solids[i].corners.empty())
            result.warnings.push_back("solid '" + name + "' holds no triangles: skipped");
        else
            addSolid(result.scene, solids[i], name, material);
    }
    if (result.scene.objects.empty()) throw Bad("the file holds no triangles");
    try {
        validate(result.scene);
    } catch (const std::invalid_argument& e) {
        throw Bad(std::string("inconsistent mesh: ") + e.what());
    }
    return result;
}

} // namespace

bool isBinaryStl(std::string_view head, uint64_t size) {
    if (head.size() < 84) return false;
    const auto* count = reinterpret_cast<const unsigned char*>(head.data() + 80);
    const uint64_t n = uint64_t(count[0]) | uint64_t(count[1]) << 8 | uint64_t(count[2]) << 16 |
                       uint64_t(count[3]) << 24;
    return size == 84 + 50 * n;
}

std::vector<StlBlock> splitStlSolids(std::string_view text) {
    std::vector<StlBlock> blocks;
    bool inside = false;
    uint32_t line = 0;
    for (size_t at = 0; at < text.size();) {
        const size_t eol = text.find('\n', at);
        const size_t next = eol == text.npos ? text.size() : eol + 1;
        const std::string_view content = trimmed(text.substr(at, next - at));
        const std::string word = lowercase(content.substr(0, content.find_first_of(" \t")));
        ++line;
        if (word == "solid") {
            if (inside) blocks.back().end = at; // the previous one lacks its endsolid
            blocks.push_back({std::string(trimmed(content.substr(5))), at, text.size(), line});
            inside = true;
        } else if (inside && word == "endsolid") {
            blocks.back().end = next;
            inside = false;
        } else if (!inside && !content.empty()) {
            throw Bad("line " + std::to_string(line) + " lies outside any 'solid ... endsolid'");
        }
        at = next;
    }
    return blocks;
}

LengthUnit stlUnit() {
    return {"", "STL files store no unit"};
}

LoadResult loadStl(const std::string& path) {
    try {
        return loadHere(path);
    } catch (const std::runtime_error& e) { // Bad, and cad::Bad from a crash caught
        throw ModelError(path + ": " + e.what());
    } catch (const Standard_Failure& e) {
        throw ModelError(path + ": Open CASCADE failed: " + e.DynamicType()->Name());
    } catch (const std::bad_alloc&) {
        throw ModelError(path + ": out of memory reading it");
    }
}

} // namespace scene
