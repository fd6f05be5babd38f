// rig_step.h - STEP files the CAD tests write with Open CASCADE: an XDE document to fill and
// write, and the rig (instances of one product, names, instance, product and face colours, a
// turned sub-assembly).
#pragma once

#include <cmath>
#include <filesystem>
#include <optional>

#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <Quantity_Color.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <gp_Ax1.hxx>

#include "scene/cad/cad_loader.h"

namespace cadtest {

// An XDE document to fill through `shapes` and `colors` and write as STEP with names and
// colours; closed when it goes.
class StepDocument {
  public:
    StepDocument() {
        std::optional<scene::OcctLeaksIgnored> ignored(std::in_place); // the application's setup
        app_ = XCAFApp_Application::GetApplication();
        ignored.reset();
        app_->NewDocument("MDTV-XCAF", doc_);
        shapes = XCAFDoc_DocumentTool::ShapeTool(doc_->Main());
        colors = XCAFDoc_DocumentTool::ColorTool(doc_->Main());
    }
    ~StepDocument() { app_->Close(doc_); }
    StepDocument(const StepDocument&) = delete;
    StepDocument& operator=(const StepDocument&) = delete;

    void write(const std::filesystem::path& path) {
        // The STEP writer's setup and its default axis directions are never freed by OCCT.
        std::optional<scene::OcctLeaksIgnored> ignored(std::in_place);
        STEPCAFControl_Writer writer;
        writer.SetColorMode(true);
        writer.SetNameMode(true);
        EXPECT_TRUE(writer.Transfer(doc_, STEPControl_AsIs));
        ignored.reset();
        EXPECT_EQ(writer.Write(path.c_str()), IFSelect_RetDone) << path;
    }

    Handle(XCAFDoc_ShapeTool) shapes;
    Handle(XCAFDoc_ColorTool) colors;

  private:
    Handle(XCAFApp_Application) app_;
    Handle(TDocStd_Document) doc_;
};

// Writes `path` as STEP: one box placed twice ("left box" red, "right box" blue), a cylinder
// ("pin", product colour green, its second face yellow of its own) and a sub-assembly holding
// the box once more, all under the assembly "rig".
inline void writeRigStep(const std::filesystem::path& path) {
    StepDocument document;
    const Handle(XCAFDoc_ShapeTool)& shapes = document.shapes;
    const Handle(XCAFDoc_ColorTool)& colors = document.colors;

    const TDF_Label rig = shapes->NewShape();
    TDataStd_Name::Set(rig, "rig");
    const TDF_Label box = shapes->AddShape(BRepPrimAPI_MakeBox(10.0, 20.0, 30.0).Shape(), false);
    TDataStd_Name::Set(box, "box");
    const TopoDS_Shape cylinderShape = BRepPrimAPI_MakeCylinder(5.0, 15.0).Shape();
    const TDF_Label cylinder = shapes->AddShape(cylinderShape, false);
    TDataStd_Name::Set(cylinder, "cylinder");
    colors->SetColor(cylinder, Quantity_Color(0.0, 1.0, 0.0, Quantity_TOC_RGB), XCAFDoc_ColorSurf);
    TopTools_IndexedMapOfShape cylinderFaces;
    TopExp::MapShapes(cylinderShape, TopAbs_FACE, cylinderFaces);
    const TDF_Label ownFace = shapes->AddSubShape(cylinder, cylinderFaces(2));
    colors->SetColor(ownFace, Quantity_Color(1.0, 1.0, 0.0, Quantity_TOC_RGB), XCAFDoc_ColorSurf);

    auto place = [&](const TDF_Label& shape, gp_Vec offset, const char* name) {
        gp_Trsf move;
        move.SetTranslation(offset);
        const TDF_Label component = shapes->AddComponent(rig, shape, TopLoc_Location(move));
        TDataStd_Name::Set(component, name);
        return component;
    };
    const TDF_Label left = place(box, gp_Vec(100.0, 0.0, 0.0), "left box");
    const TDF_Label right = place(box, gp_Vec(0.0, 200.0, 0.0), "right box");
    place(cylinder, gp_Vec(0.0, 0.0, 50.0), "pin");
    // A sub-assembly, turned a quarter about z and raised, holding the box moved along x:
    // the box lands at turn(5, 0, 0) + (0, 0, 100) = (0, 5, 100).
    const TDF_Label arm = shapes->NewShape();
    TDataStd_Name::Set(arm, "arm");
    gp_Trsf along;
    along.SetTranslation(gp_Vec(5.0, 0.0, 0.0));
    TDataStd_Name::Set(shapes->AddComponent(arm, box, TopLoc_Location(along)), "arm box");
    gp_Trsf turn;
    turn.SetRotation(gp_Ax1(gp_Pnt(), gp_Dir(0.0, 0.0, 1.0)), M_PI / 2.0);
    turn.SetTranslationPart(gp_Vec(0.0, 0.0, 100.0));
    TDataStd_Name::Set(shapes->AddComponent(rig, arm, TopLoc_Location(turn)), "raised arm");
    colors->SetColor(left, Quantity_Color(1.0, 0.0, 0.0, Quantity_TOC_RGB), XCAFDoc_ColorSurf);
    colors->SetColor(right, Quantity_Color(0.0, 0.0, 1.0, Quantity_TOC_RGB), XCAFDoc_ColorSurf);
    shapes->UpdateAssemblies();

    document.write(path);
}

} // namespace cadtest
