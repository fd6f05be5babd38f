// test_step_split_occt.cpp - the STEP splitter (scene/step/step_split.h) checked by Open
// CASCADE's own XDE reader: on the occt-misc STEP files and an assembly written here by its
// XDE writer (products placed twice, a nested sub-assembly, names, colours on a product, a
// face and a solid, compounds of solids and of a solid beside a face, lengths in metres), the
// skeleton gives the whole file's leaves (paths, names, placements) with each leaf's shape
// the two corners of one piece's box, and each piece gives one shape laid out as its
// RepLayout says, coloured as the whole file colours that product.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Interface_Static.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <gp_Pln.hxx>

#include "scene/cad/cad_read.h"
#include "scene/step/step_split.h"
#include "step_split_files.h"
#include "test_data.h"
#include "util/cache_file.h"

namespace {

namespace fs = std::filesystem;
using scene::cad::Leaf;
using scene::step::Piece;
using scene::step::StepSplit;

const fs::path kStepData = "/usr/share/opencascade/data/step";

// The leaves Open CASCADE's XDE reader gives of a file, or of STEP text in memory.
std::vector<Leaf> readLeaves(const std::string& path, const std::string* text = nullptr) {
    scene::ReaderLosses losses;
    double sewTolerance = 0.0;
    return scene::cad::readXde({path, text}, scene::cad::Format::Step, {}, losses, sewTolerance,
                               nullptr);
}

bool near(double a, double b) {
    return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(a));
}
bool near(const gp_Pnt& a, const gp_Pnt& b) {
    return near(a.X(), b.X()) && near(a.Y(), b.Y()) && near(a.Z(), b.Z());
}

std::vector<gp_Pnt> verticesOf(const TopoDS_Shape& shape) {
    TopTools_IndexedMapOfShape map;
    TopExp::MapShapes(shape, TopAbs_VERTEX, map);
    std::vector<gp_Pnt> points;
    for (int i = 1; i <= map.Extent(); ++i)
        points.push_back(BRep_Tool::Pnt(TopoDS::Vertex(map(i))));
    return points;
}

// The corners of a piece's box in millimetres, as Open CASCADE reads the file's numbers.
std::pair<gp_Pnt, gp_Pnt> cornersOf(const Piece& piece, double mmPerUnit) {
    const auto& lo = piece.boxMin;
    const auto& hi = piece.boxMax;
    return {gp_Pnt(lo[0] * mmPerUnit, lo[1] * mmPerUnit, lo[2] * mmPerUnit),
            gp_Pnt(hi[0] * mmPerUnit, hi[1] * mmPerUnit, hi[2] * mmPerUnit)};
}

std::pair<gp_Pnt, gp_Pnt> boxOf(const std::vector<gp_Pnt>& points) {
    gp_Pnt lo(1e300, 1e300, 1e300), hi(-1e300, -1e300, -1e300);
    for (const gp_Pnt& p : points)
        for (int axis = 1; axis <= 3; ++axis) {
            lo.SetCoord(axis, std::min(lo.Coord(axis), p.Coord(axis)));
            hi.SetCoord(axis, std::max(hi.Coord(axis), p.Coord(axis)));
        }
    return {lo, hi};
}

// Each face's colour, in MapShapes order: a sub-shape colour over it, else the leaf's own.
std::vector<std::string> faceColours(const Leaf& leaf) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(leaf.shape, TopAbs_FACE, faces);
    std::vector<std::string> colours;
    for (int i = 1; i <= faces.Extent(); ++i) {
        std::optional<scene::cad::Rgba> colour = leaf.color;
        for (const auto& [shape, rgba] : leaf.subColors)
            for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next())
                if (e.Current().TShape() == faces(i).TShape()) colour = rgba;
        char text[64] = "none";
        if (colour)
            std::snprintf(text, sizeof text, "%.4f %.4f %.4f", colour->GetRGB().Red(),
                          colour->GetRGB().Green(), colour->GetRGB().Blue());
        colours.push_back(text);
    }
    return colours;
}

// The objects idview makes of the leaf (splitSolids), as face counts.
std::vector<uint32_t> objectFaces(const Leaf& leaf) {
    std::vector<uint32_t> faces;
    for (const Leaf& object : scene::cad::splitSolids({leaf}, "test")) {
        TopTools_IndexedMapOfShape map;
        TopExp::MapShapes(object.shape, TopAbs_FACE, map);
        faces.push_back(uint32_t(map.Extent()));
    }
    return faces;
}

// The piece whose box corners are the skeleton leaf's two vertices.
size_t pieceOf(const Leaf& dummy, const std::vector<Piece>& pieces, double mmPerUnit) {
    const std::vector<gp_Pnt> points = verticesOf(dummy.shape);
    EXPECT_EQ(points.size(), 2u) << dummy.name;
    std::vector<size_t> found;
    for (size_t k = 0; k < pieces.size() && points.size() == 2; ++k) {
        const auto [lo, hi] = cornersOf(pieces[k], mmPerUnit);
        if ((near(points[0], lo) && near(points[1], hi)) ||
            (near(points[0], hi) && near(points[1], lo)))
            found.push_back(k);
    }
    EXPECT_EQ(found.size(), 1u) << dummy.name << ": the box of no piece, or of several";
    return found.empty() ? pieces.size() : found[0];
}

void expectSamePlacement(const gp_Trsf& a, const gp_Trsf& b, const std::string& name) {
    for (int row = 1; row <= 3; ++row)
        for (int column = 1; column <= 4; ++column)
            EXPECT_NEAR(a.Value(row, column), b.Value(row, column), 1e-9) << name;
}

// Each piece read alone: one free shape, laid out as its RepLayout says.
std::vector<std::optional<Leaf>> readPieces(const StepSplit& split) {
    std::vector<std::optional<Leaf>> leaves(split.pieces().size());
    for (size_t k = 0; k < leaves.size(); ++k) {
        const Piece& piece = split.pieces()[k];
        const std::string text = split.pieceText(k);
        EXPECT_EQ(text.size(), piece.bytes);
        const std::vector<Leaf> read = readLeaves("piece.step", &text);
        EXPECT_EQ(read.size(), 1u) << "piece " << k << ": one free shape";
        if (read.size() != 1) continue;
        EXPECT_EQ(objectFaces(read[0]), piece.layout.objectFaces) << "piece " << k;
        TopTools_IndexedMapOfShape solids;
        TopExp::MapShapes(read[0].shape, TopAbs_SOLID, solids);
        EXPECT_EQ(uint32_t(solids.Extent()), piece.layout.solids) << "piece " << k;
        leaves[k] = read[0];
    }
    return leaves;
}

// The whole file, its skeleton and every piece read by Open CASCADE agree (see the top). A
// leaf's colours split: the piece's face colours, else the skeleton's (its instance's), else
// the piece's (its product's), as the loader will take them. Returns the pieces.
std::vector<Piece> expectSplitAsOpenCascadeReads(const std::string& path, double mmPerUnit) {
    const StepSplit split(path);
    EXPECT_FALSE(split.notSplit()) << split.notSplit()->reason;
    if (split.notSplit()) return {};
    const std::vector<Piece>& pieces = split.pieces();
    const std::vector<Leaf> whole = readLeaves(path);
    const std::string skeletonText = split.skeleton();
    const std::vector<Leaf> skeleton = readLeaves("skeleton.step", &skeletonText);
    const std::vector<std::optional<Leaf>> pieceLeaves = readPieces(split);
    EXPECT_EQ(skeleton.size(), whole.size());
    std::vector<bool> used(pieces.size(), false);
    for (size_t i = 0; i < std::min(whole.size(), skeleton.size()); ++i) {
        EXPECT_EQ(skeleton[i].group, whole[i].group);
        EXPECT_EQ(skeleton[i].name, whole[i].name);
        EXPECT_EQ(skeleton[i].product, whole[i].product);
        expectSamePlacement(skeleton[i].world, whole[i].world, whole[i].name);
        const size_t k = pieceOf(skeleton[i], pieces, mmPerUnit);
        if (k == pieces.size()) continue;
        used[k] = true;
        EXPECT_EQ(objectFaces(whole[i]), pieces[k].layout.objectFaces) << whole[i].name;
        const auto [lo, hi] = boxOf(verticesOf(whole[i].shape));
        const auto [pieceLo, pieceHi] = cornersOf(pieces[k], mmPerUnit);
        EXPECT_TRUE(pieces[k].hasBox && near(lo, pieceLo) && near(hi, pieceHi)) << whole[i].name;
        if (!pieceLeaves[k]) continue;
        Leaf coloured = *pieceLeaves[k];
        if (skeleton[i].color) coloured.color = skeleton[i].color;
        EXPECT_EQ(faceColours(coloured), faceColours(whole[i])) << whole[i].name;
    }
    for (size_t k = 0; k < pieces.size(); ++k) EXPECT_TRUE(used[k]) << "piece " << k << " unused";
    return pieces;
}

TEST(StepSplitOcct, SplitsTheOcctMiscFilesAsOpenCascadeReadsThem) {
    for (const char* name : {"linkrods.step", "screw.step"}) {
        const fs::path path = kStepData / name;
        REQUIRE_DATA(path);
        const std::vector<Piece> pieces = expectSplitAsOpenCascadeReads(path.string(), 1.0);
        ASSERT_EQ(pieces.size(), 1u) << name;
        EXPECT_EQ(pieces[0].layout.solids, 1u);
        EXPECT_FALSE(pieces[0].layout.split);
    }
}

// Sets an Open CASCADE parameter while this lives (the session's parameters are global).
class StaticParameter {
  public:
    StaticParameter(const char* name, const char* value)
        : name_(name), saved_(Interface_Static::CVal(name)) {
        Interface_Static::SetCVal(name, value);
    }
    ~StaticParameter() { Interface_Static::SetCVal(name_, saved_.c_str()); }
    StaticParameter(const StaticParameter&) = delete;
    StaticParameter& operator=(const StaticParameter&) = delete;

  private:
    const char* name_;
    std::string saved_;
};

gp_Trsf moved(double x, double y, double z, double turn = 0.0) {
    gp_Trsf trsf;
    trsf.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), turn);
    trsf.SetTranslationPart(gp_Vec(x, y, z));
    return trsf;
}

TDF_Label addProduct(const Handle(XCAFDoc_ShapeTool) & shapes, const TopoDS_Shape& shape,
                     const char* name) {
    const TDF_Label label = shapes->AddShape(shape, false);
    TDataStd_Name::Set(label, name);
    return label;
}

void place(const Handle(XCAFDoc_ShapeTool) & shapes, const TDF_Label& assembly,
           const TDF_Label& product, const gp_Trsf& where, const char* name) {
    TDataStd_Name::Set(shapes->AddComponent(assembly, product, TopLoc_Location(where)), name);
}

// rig: a block placed twice (a face of it blue, one instance yellow), the sub-assembly arm (a green
// pin turned a quarter, a pair of boxes, one red), and a box beside a face of no solid.
void buildRig(const Handle(TDocStd_Document) & doc) {
    const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    const Handle(XCAFDoc_ColorTool) colours = XCAFDoc_DocumentTool::ColorTool(doc->Main());
    const TopoDS_Shape block = BRepPrimAPI_MakeBox(10.0, 20.0, 30.0).Shape();
    const TDF_Label blockLabel = addProduct(shapes, block, "block");
    colours->SetColor(
        shapes->AddSubShape(blockLabel, TopExp_Explorer(block, TopAbs_FACE).Current()),
        Quantity_Color(0.0, 0.0, 1.0, Quantity_TOC_RGB), XCAFDoc_ColorSurf);
    const TDF_Label pin = addProduct(shapes, BRepPrimAPI_MakeCylinder(5.0, 20.0).Shape(), "pin");
    colours->SetColor(pin, Quantity_Color(0.0, 1.0, 0.0, Quantity_TOC_RGB), XCAFDoc_ColorSurf);
    BRep_Builder builder;
    TopoDS_Compound pair, sheet;
    builder.MakeCompound(pair);
    builder.Add(pair, BRepPrimAPI_MakeBox(1.0, 1.0, 1.0).Shape());
    const TopoDS_Shape red = BRepPrimAPI_MakeBox(gp_Pnt(5.0, 0.0, 0.0), 2.0, 2.0, 2.0).Shape();
    builder.Add(pair, red);
    const TDF_Label pairLabel = addProduct(shapes, pair, "pair");
    colours->SetColor(shapes->AddSubShape(pairLabel, red),
                      Quantity_Color(1.0, 0.0, 0.0, Quantity_TOC_RGB), XCAFDoc_ColorSurf);
    builder.MakeCompound(sheet);
    builder.Add(sheet, BRepPrimAPI_MakeBox(4.0, 4.0, 4.0).Shape());
    builder.Add(
        sheet, BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 9), gp_Dir(0, 0, 1)), 0.0, 4.0, 0.0, 4.0)
                   .Face());
    const TDF_Label sheetLabel = addProduct(shapes, sheet, "sheet");
    const TDF_Label arm = shapes->NewShape();
    TDataStd_Name::Set(arm, "arm");
    place(shapes, arm, pin, moved(0.0, 0.0, 5.0, M_PI / 2), "pin in arm");
    place(shapes, arm, pairLabel, moved(10.0, 0.0, 0.0), "pair in arm");
    const TDF_Label rig = shapes->NewShape();
    TDataStd_Name::Set(rig, "rig");
    place(shapes, rig, blockLabel, moved(0.0, 0.0, 0.0), "left block");
    const TDF_Label right = shapes->AddComponent(rig, blockLabel, TopLoc_Location(moved(50, 0, 0)));
    TDataStd_Name::Set(right, "right block");
    colours->SetColor(right, Quantity_Color(1.0, 1.0, 0.0, Quantity_TOC_RGB), XCAFDoc_ColorSurf);
    place(shapes, rig, arm, moved(0.0, 40.0, 0.0, 0.3), "arm");
    place(shapes, rig, sheetLabel, moved(-20.0, 0.0, 0.0), "sheet");
    shapes->UpdateAssemblies();
}

// The rig written in metres by Open CASCADE's XDE writer.
std::string writeRig(const steptest::TempFile& file) {
    std::optional<scene::OcctLeaksIgnored> ignored(std::in_place);
    Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
    Handle(TDocStd_Document) doc;
    app->NewDocument("MDTV-XCAF", doc);
    ignored.reset();
    buildRig(doc);
    // The STEP writer's setup and its first translation's tables are never freed by OCCT.
    ignored.emplace();
    STEPCAFControl_Writer writer;
    const StaticParameter metres("write.step.unit", "M");
    const scene::cad::CoutCapture quiet; // the writer's statistics
    writer.SetColorMode(true);
    writer.SetNameMode(true);
    EXPECT_TRUE(writer.Transfer(doc, STEPControl_AsIs));
    ignored.reset();
    EXPECT_EQ(writer.Write(file.path().c_str()), IFSelect_RetDone);
    app->Close(doc);
    return file.path();
}

TEST(StepSplitOcct, SplitsAnAssemblyWrittenByOpenCascadeAsItReadsIt) {
    const steptest::TempFile file("rig.step", "");
    const std::string path = writeRig(file);
    const std::optional<std::string> text = util::readWholeFile(path);
    ASSERT_TRUE(text);
    EXPECT_NE(text->find("SI_UNIT($,.METRE.)"), std::string::npos) << "not written in metres";
    EXPECT_NE(text->find("PRESENTATION_STYLE_BY_CONTEXT"), std::string::npos)
        << "no instance style";
    ASSERT_EQ(readLeaves(path).size(), 5u); // two blocks, the arm's pin and pair, the sheet
    const std::vector<Piece> pieces = expectSplitAsOpenCascadeReads(path, 1000.0);
    std::vector<std::vector<uint32_t>> layouts;
    for (const Piece& piece : pieces) {
        layouts.push_back(piece.layout.objectFaces);
        EXPECT_EQ(piece.layout.freeFaces, piece.layout.objectFaces.back() == 1u);
    }
    std::sort(layouts.begin(), layouts.end());
    // The pin, the block, the box beside the face, the pair.
    EXPECT_EQ(layouts, (std::vector<std::vector<uint32_t>>{{3}, {6}, {6, 1}, {6, 6}}));
}

} // namespace
