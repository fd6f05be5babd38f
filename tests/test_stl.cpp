// test_stl.cpp - STL files (scene/stl/stl_loader.h) against independent counts (facet lines
// in the ASCII text, the binary header's count) and Open CASCADE's own reading (RWStl), and
// the format table's check of a file's content (scene/formats.h).
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include <Bnd_Box.hxx>
#include <Poly_Triangulation.hxx>
#include <RWStl.hxx>

#include "scene/cad/cad_loader.h"
#include "scene/formats.h"
#include "scene/stl/stl_loader.h"
#include "test_data.h"

namespace fs = std::filesystem;

namespace {

const char* kSpiderAscii = "/usr/share/assimp/models/STL/Spider_ascii.stl";
const char* kSpiderBinary = "/usr/share/assimp/models/STL/Spider_binary.stl";
const char* kTwoSolids = "/usr/share/assimp/models/STL/triangle_with_two_solids.stl";
const char* kEmptySolid = "/usr/share/assimp/models/STL/triangle_with_empty_solid.stl";
const char* kUpperCase = "/usr/share/assimp/models/STL/3DSMaxExport.STL";
const char* kBearing = "/usr/share/opencascade/data/stl/bearing.stl";

std::string fileText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The corners of every triangle of the scene's only geometry, in order.
std::vector<glm::vec3> corners(const scene::Scene& s) {
    const scene::Geometry& g = s.geometries[0];
    std::vector<glm::vec3> out;
    for (uint32_t i = 0; i < g.triangleCount * 3; ++i)
        out.push_back(s.vertices[g.firstVertex + s.indices[g.firstIndex + i]].position);
    return out;
}

// A file of `content` in a folder of its own, removed with it.
struct TempFile {
    fs::path folder = fs::temp_directory_path() / ("idview-stl-" + std::to_string(getpid()));
    fs::path path;
    TempFile(const std::string& name, const std::string& content) : path(folder / name) {
        fs::create_directories(folder);
        std::ofstream(path, std::ios::binary) << content;
    }
    ~TempFile() { fs::remove_all(folder); }
};

// The refusal checkModelFile or loadStl gives, "" when none.
std::string refusal(const std::string& path) {
    try {
        scene::checkModelFile(path);
        scene::loadStl(path);
    } catch (const scene::ModelError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(Stl, AsciiAndBinarySpiderGiveTheSameTrianglesAsTheFilesCount) {
    REQUIRE_DATA(kSpiderAscii);
    const scene::LoadResult ascii = scene::loadStl(kSpiderAscii);
    const scene::LoadResult binary = scene::loadStl(kSpiderBinary);
    // Independent counts: the ASCII text's facet lines, the binary header's uint32.
    const std::string text = fileText(kSpiderAscii);
    size_t facets = 0;
    for (size_t at = text.find("facet normal"); at != text.npos;
         at = text.find("facet normal", at + 1))
        ++facets;
    const std::string head = fileText(kSpiderBinary).substr(0, 84);
    uint32_t counted = 0;
    std::memcpy(&counted, head.data() + 80, 4);
    EXPECT_EQ(facets, counted);
    EXPECT_EQ(ascii.scene.drawnTriangleCount(), facets);
    EXPECT_EQ(binary.scene.drawnTriangleCount(), counted);
    const std::vector<glm::vec3> a = corners(ascii.scene), b = corners(binary.scene);
    ASSERT_EQ(a.size(), b.size());
    size_t apart = 0;
    for (size_t i = 0; i < a.size(); ++i)
        apart += glm::length(a[i] - b[i]) > 1e-5f * std::max(1.0f, glm::length(a[i]));
    EXPECT_EQ(apart, 0u) << "corners that differ between the two encodings";
    EXPECT_EQ(ascii.scene.objects.size(), 1u);
    EXPECT_EQ(binary.scene.uniquePartCount(), 1u);
}

TEST(Stl, EachSolidOfAnAsciiFileIsAnObjectOfOnePart) {
    REQUIRE_DATA(kTwoSolids);
    const scene::LoadResult r = scene::loadStl(kTwoSolids);
    ASSERT_EQ(r.scene.objects.size(), 2u);
    EXPECT_EQ(r.scene.uniquePartCount(), 2u);
    EXPECT_EQ(r.scene.objects[0].name, "testTriangle_1");
    EXPECT_EQ(r.scene.objects[1].name, "testTriangle_2");
    EXPECT_EQ(r.scene.drawnTriangleCount(), 2u);
    // Each solid's triangle is where the file puts it.
    const scene::Bounds boxes[] = {{{-1, -1, 0}, {1, 1, 0}}, {{0, 2, 0}, {3, 3, 0}}};
    for (size_t o = 0; o < 2; ++o) {
        const scene::Geometry& g = r.scene.geometries[r.scene.objects[o].geometry];
        EXPECT_EQ(g.vertexCount, 3u);
        for (uint32_t v = 0; v < g.vertexCount; ++v) {
            const glm::dvec3 p = r.scene.vertices[g.firstVertex + v].position;
            EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, boxes[o].min)) &&
                        glm::all(glm::lessThanEqual(p, boxes[o].max)))
                << "solid " << o << " vertex " << v;
        }
    }
    EXPECT_TRUE(r.warnings.empty());
}

TEST(Stl, AnEmptySolidIsSkippedWithAWarning) {
    REQUIRE_DATA(kEmptySolid);
    const scene::LoadResult r = scene::loadStl(kEmptySolid);
    ASSERT_EQ(r.scene.objects.size(), 1u);
    EXPECT_EQ(r.scene.objects[0].name, "testTriangle");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0], "solid 'emptySolid' holds no triangles: skipped");
}

TEST(Stl, BearingAgreesWithOpenCascadesOwnTriangulation) {
    REQUIRE_DATA(kBearing);
    const scene::LoadResult r = scene::loadStl(kBearing);
    // At idview's crease angle: merged across every angle, a few zero-area triangles (two
    // corners closer than Precision::Confusion) collapse, which split nodes keep.
    const Handle(Poly_Triangulation) occt =
        RWStl::ReadFile(kBearing, scene::kStlCreaseDegrees * M_PI / 180.0, {});
    ASSERT_FALSE(occt.IsNull());
    EXPECT_EQ(r.scene.uniquePartCount(), 1u);
    EXPECT_EQ(r.scene.drawnTriangleCount(), uint64_t(occt->NbTriangles()));
    Bnd_Box box;
    for (Standard_Integer i = 1; i <= occt->NbNodes(); ++i) box.Add(occt->Node(i));
    const gp_Pnt min = box.CornerMin(), max = box.CornerMax();
    const scene::Bounds b = r.scene.bounds();
    const double tolerance = 1e-6 * box.SquareExtent();
    EXPECT_NEAR(b.min.x, min.X(), tolerance);
    EXPECT_NEAR(b.min.y, min.Y(), tolerance);
    EXPECT_NEAR(b.min.z, min.Z(), tolerance);
    EXPECT_NEAR(b.max.x, max.X(), tolerance);
    EXPECT_NEAR(b.max.y, max.Y(), tolerance);
    EXPECT_NEAR(b.max.z, max.Z(), tolerance);
}

TEST(Stl, NormalsAreUnitLengthAndFaceOutOfFlatFacets) {
    REQUIRE_DATA(kTwoSolids);
    const scene::LoadResult r = scene::loadStl(kTwoSolids);
    for (const scene::Vertex& v : r.scene.vertices)
        EXPECT_NEAR(glm::length(v.normal - glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
}

TEST(Stl, SolidsSplitAtTheirKeywordsAndNothingElse) {
    const std::string text = "solid a\nfacet\nendsolid a\n\nSOLID b c\nfacet\nsolid d\nfacet\n";
    const std::vector<scene::StlBlock> blocks = scene::splitStlSolids(text);
    ASSERT_EQ(blocks.size(), 3u);
    EXPECT_EQ(blocks[0].name, "a");
    EXPECT_EQ(text.substr(blocks[0].begin, blocks[0].end - blocks[0].begin),
              "solid a\nfacet\nendsolid a\n");
    EXPECT_EQ(blocks[1].name, "b c");
    EXPECT_EQ(blocks[1].line, 5u);
    EXPECT_EQ(text.substr(blocks[1].begin, blocks[1].end - blocks[1].begin), "SOLID b c\nfacet\n");
    EXPECT_EQ(blocks[2].end, text.size());
    EXPECT_THROW(scene::splitStlSolids("solid a\nendsolid\njunk\n"), std::runtime_error);
}

TEST(Stl, TheFormatTableKnowsStlInAnyCase) {
    REQUIRE_DATA(kUpperCase);
    ASSERT_NE(scene::formatOfName(kUpperCase), nullptr);
    EXPECT_EQ(scene::formatOfName(kUpperCase)->reader, scene::Reader::Stl);
    EXPECT_EQ(scene::checkModelFile(kUpperCase).name, "STL");
    EXPECT_FALSE(scene::isCadPath(kSpiderAscii));
    EXPECT_EQ(scene::formatOfName("x.txt"), nullptr);
    EXPECT_NE(scene::formatList().find("STL (.stl)"), std::string::npos);
}

TEST(Stl, FilesThatAreNoStlAreRefusedInOneLineNamingThem) {
    REQUIRE_DATA(kSpiderBinary);
    const TempFile text("notreally.stl", "hello, no model here\n");
    const TempFile empty("empty.stl", "");
    const TempFile brokenFacet("broken.stl", "solid x\nfacet normal 0 0 1\nouter loop\n"
                                             "vertex a b c\nvertex 1 0 0\nvertex 0 1 0\n"
                                             "endloop\nendfacet\nendsolid\n");
    const TempFile noTriangles("none.stl", "solid x\nendsolid x\n");
    std::string shortBinary = fileText(kSpiderBinary);
    shortBinary.resize(shortBinary.size() - 50);
    const TempFile truncated("truncated.stl", shortBinary);
    const TempFile png("x.glb", "\x89PNG\r\n\x1a\nnot a model");
    const std::pair<fs::path, std::string> cases[] = {
        {text.path, "not an STL file (no ASCII 'solid' text, and too short"},
        {empty.path, "the file is empty"},
        {brokenFacet.path, "not a readable ASCII STL file: the solid from line 1 has a "
                           "malformed facet"},
        {noTriangles.path, "the file holds no triangles"},
        {truncated.path, "not an STL file (no ASCII 'solid' text, and not a binary STL"},
        {png.path, "not a glTF file (neither a GLB's 'glTF' magic nor JSON text)"},
        {text.folder / "missing.stl", "file not found"},
        {text.folder, "a folder, not a file"},
    };
    for (const auto& [path, reason] : cases) {
        const std::string said = refusal(path.string());
        EXPECT_EQ(said.rfind(path.string() + ": " + reason, 0), 0u) << said;
        EXPECT_EQ(said.find('\n'), std::string::npos) << said;
    }
}
