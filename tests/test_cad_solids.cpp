// test_cad_solids.cpp - a shape that holds several solids loads as an object per solid
// (scene/cad/cad_read.h, splitSolids): Motor-c.brep against Open CASCADE's own solids and faces,
// a BREP written here with a repeated solid and a face of no solid, and a STEP product whose
// shape is a compound with a solid coloured of its own; and partsAround on such a scene.
#include <filesystem>
#include <unistd.h>

#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Quantity_Color.hxx>
#include <TDataStd_Name.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Pln.hxx>

#include "rig_step.h"
#include "scene/assembly_tree.h"
#include "scene/cad/cad_loader.h"
#include "test_data.h"

namespace {

namespace fs = std::filesystem;
using scene::PartRange;

const fs::path kData = "/usr/share/opencascade/data";

fs::path scratch(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("idview_solids_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir / name;
}

uint32_t facesOf(const TopoDS_Shape& shape) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    return uint32_t(faces.Extent());
}

TEST(CadSolids, MotorIsAnObjectPerSolid) {
    const fs::path path = kData / "occ/Motor-c.brep";
    REQUIRE_DATA(path);
    TopoDS_Shape shape;
    BRep_Builder builder;
    ASSERT_TRUE(BRepTools::Read(shape, path.c_str(), builder));
    std::vector<uint32_t> solidFaces;
    for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next())
        solidFaces.push_back(facesOf(e.Current()));
    ASSERT_GT(solidFaces.size(), 1u);

    const scene::Scene s = scene::loadCad(path.string()).scene;
    scene::validate(s);
    ASSERT_EQ(s.objects.size(), solidFaces.size());
    EXPECT_EQ(s.uniquePartCount(), facesOf(shape));
    EXPECT_EQ(s.uniquePartCount(), 223u); // as before the split
    for (size_t i = 0; i < s.objects.size(); ++i) {
        const scene::Object& o = s.objects[i];
        const std::string name = "solid " + std::to_string(i + 1);
        EXPECT_EQ(o.name, name);
        EXPECT_EQ(o.path, "Motor-c/" + name);
        const scene::Geometry& g = s.geometries[o.geometry];
        EXPECT_EQ(g.partCount, solidFaces[i]) << name;
        // Faces are numbered within their solid now.
        for (uint32_t p = 0; p < g.partCount; ++p) EXPECT_EQ(g.partFaces.at(p), p) << name;
        // A click takes the solid at level 1 and the whole motor at level 2.
        const uint32_t last = o.uniquePartOffset + g.partCount - 1;
        EXPECT_EQ(scene::partsAround(s, last, 0), (std::vector<PartRange>{{last, 1}}));
        EXPECT_EQ(scene::partsAround(s, last, 1),
                  (std::vector<PartRange>{{o.uniquePartOffset, solidFaces[i]}}));
        EXPECT_EQ(scene::partsAround(s, last, 2),
                  (std::vector<PartRange>{{0, s.uniquePartCount()}}));
    }
}

// A compound of a box, the same box moved, a cylinder and a lone square face.
TEST(CadSolids, RepeatedSolidsShareAGeometryAndFreeFacesAreOneObject) {
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(10.0, 20.0, 30.0).Shape();
    gp_Trsf move;
    move.SetTranslation(gp_Vec(50.0, 0.0, 0.0));
    TopoDS_Compound all;
    BRep_Builder builder;
    builder.MakeCompound(all);
    builder.Add(all, box);
    builder.Add(all, box.Moved(TopLoc_Location(move)));
    builder.Add(all, BRepPrimAPI_MakeCylinder(5.0, 15.0).Shape());
    builder.Add(all, BRepBuilderAPI_MakeFace(gp_Pln(), 0.0, 4.0, 0.0, 4.0).Face());
    const fs::path path = scratch("parts.brep");
    ASSERT_TRUE(BRepTools::Write(all, path.c_str()));

    const scene::Scene s = scene::loadCad(path.string()).scene;
    scene::validate(s);
    ASSERT_EQ(s.objects.size(), 4u);
    const char* names[] = {"solid 1", "solid 2", "solid 3", "free faces"};
    const uint32_t faces[] = {6, 6, 3, 1};
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(s.objects[i].name, names[i]);
        EXPECT_EQ(s.objects[i].path, std::string("parts/") + names[i]);
        EXPECT_EQ(s.geometries[s.objects[i].geometry].partCount, faces[i]) << names[i];
    }
    EXPECT_EQ(s.objects[0].geometry, s.objects[1].geometry);
    EXPECT_EQ(glm::vec3(s.objects[1].world[3]) - glm::vec3(s.objects[0].world[3]),
              glm::vec3(50.0f, 0.0f, 0.0f));
    EXPECT_EQ(s.geometries.size(), 3u);
}

// A STEP product whose shape is one compound of two boxes, the second red of its own.
TEST(CadSolids, ASolidsColourStaysWithItsFaces) {
    cadtest::StepDocument document;
    TopoDS_Compound pair;
    BRep_Builder builder;
    builder.MakeCompound(pair);
    builder.Add(pair, BRepPrimAPI_MakeBox(1.0, 1.0, 1.0).Shape());
    const TopoDS_Shape red = BRepPrimAPI_MakeBox(gp_Pnt(5.0, 0.0, 0.0), 2.0, 2.0, 2.0).Shape();
    builder.Add(pair, red);
    const TDF_Label product = document.shapes->AddShape(pair, false);
    TDataStd_Name::Set(product, "pair");
    document.colors->SetColor(document.shapes->AddSubShape(product, red),
                              Quantity_Color(1.0, 0.0, 0.0, Quantity_TOC_RGB), XCAFDoc_ColorSurf);
    const fs::path path = scratch("pair.step");
    document.write(path);

    const scene::Scene s = scene::loadCad(path.string()).scene;
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(s.objects[0].path, "pair/solid 1");
    EXPECT_EQ(s.objects[1].path, "pair/solid 2");
    const scene::Geometry& plain = s.geometries[s.objects[0].geometry];
    const scene::Geometry& coloured = s.geometries[s.objects[1].geometry];
    EXPECT_TRUE(plain.partMaterials.empty());
    ASSERT_EQ(coloured.partMaterials.size(), 6u);
    for (uint32_t m : coloured.partMaterials) {
        ASSERT_LT(m, s.materials.size());
        EXPECT_EQ(glm::vec3(s.materials[m].color), glm::vec3(1.0f, 0.0f, 0.0f));
    }
}

} // namespace
