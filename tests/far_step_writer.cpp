// far_step_writer.cpp - `idview_far_step_writer OUT.step X Y Z`: writes a small machine
// assembly in millimetres whose one top-level component is placed at (X, Y, Z) mm, as a plant
// or ship places a part kilometres from its origin (issue 35). tests/far_test.sh writes it at
// (0, 0, 0) and at (2e6, -3.5e6, 8e5) and compares what idview draws and measures.
// `--gap OUT.step [MM]` writes two faces 0.1 mm (or MM) apart instead, hundreds of metres wide.
//
// The solids never share a visible face: what touches the base plate touches it with a face
// or a point that the plate hides, so at the origin every visible pixel has one nearest
// surface (ties only where two faces meet at an edge).
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <gp_Ax1.hxx>
#include <gp_Ax2.hxx>

#include "scene/cad/cad_loader.h"

namespace {

// A placement: a turn of `degrees` about z, then a move by `offset`.
TopLoc_Location placed(gp_Vec offset, double degrees = 0.0) {
    gp_Trsf turn;
    turn.SetRotation(gp_Ax1(gp_Pnt(), gp_Dir(0.0, 0.0, 1.0)), degrees * M_PI / 180.0);
    gp_Trsf move;
    move.SetTranslation(offset);
    return TopLoc_Location(move * turn);
}

// Writes `doc` as STEP with its names, and closes it.
bool writeDocument(const Handle(XCAFApp_Application) & app, Handle(TDocStd_Document) & doc,
                   const char* path) {
    STEPCAFControl_Writer writer;
    writer.SetNameMode(true);
    const bool ok =
        writer.Transfer(doc, STEPControl_AsIs) && writer.Write(path) == IFSelect_RetDone;
    app->Close(doc);
    return ok;
}

bool write(const char* path, gp_Vec offset) {
    Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
    Handle(TDocStd_Document) doc;
    app->NewDocument("MDTV-XCAF", doc);
    Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    auto shape = [&](const TopoDS_Shape& s, const char* name) {
        const TDF_Label label = shapes->AddShape(s, false);
        TDataStd_Name::Set(label, name);
        return label;
    };
    auto component = [&](const TDF_Label& parent, const TDF_Label& child,
                         const TopLoc_Location& where, const char* name) {
        TDataStd_Name::Set(shapes->AddComponent(parent, child, where), name);
    };

    // The machine, about 800 x 500 x 330 mm: a base plate and, on it, a housing placed twice
    // (once turned), a column and a ball resting on its lowest point.
    const TDF_Label plate = shape(BRepPrimAPI_MakeBox(800.0, 500.0, 20.0).Shape(), "plate");
    const TDF_Label housing = shape(BRepPrimAPI_MakeBox(180.0, 120.0, 150.0).Shape(), "housing");
    const TDF_Label column = shape(
        BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(), gp_Dir(0.0, 0.0, 1.0)), 45.0, 310.0).Shape(),
        "column");
    const TDF_Label ball =
        shape(BRepPrimAPI_MakeSphere(gp_Pnt(0.0, 0.0, 70.0), 70.0).Shape(), "ball");
    const TDF_Label machine = shapes->NewShape();
    TDataStd_Name::Set(machine, "machine");
    component(machine, plate, placed(gp_Vec()), "base plate");
    component(machine, housing, placed(gp_Vec(60.0, 60.0, 20.0)), "housing left");
    component(machine, housing, placed(gp_Vec(420.0, 230.0, 20.0), 30.0), "housing turned");
    component(machine, column, placed(gp_Vec(330.0, 120.0, 20.0)), "column");
    component(machine, ball, placed(gp_Vec(660.0, 120.0, 20.0)), "ball");

    // The site holds the machine at its placement: the only number that changes between the
    // two files.
    const TDF_Label site = shapes->NewShape();
    TDataStd_Name::Set(site, "site");
    component(site, machine, placed(offset), "machine at site");
    shapes->UpdateAssemblies();

    return writeDocument(app, doc, path);
}

// Two faces `gap` mm apart seen from about a kilometre: a 500 m square slab (top at z = 0) and
// a 300 m square sheet sunk into it whose top lies `gap` above the slab's.
bool writeGap(const char* path, double gap) {
    Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
    Handle(TDocStd_Document) doc;
    app->NewDocument("MDTV-XCAF", doc);
    Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    const TDF_Label slab = shapes->AddShape(
        BRepPrimAPI_MakeBox(gp_Pnt(-2.5e5, -2.5e5, -1000.0), gp_Pnt(2.5e5, 2.5e5, 0.0)).Shape(),
        false);
    TDataStd_Name::Set(slab, "slab");
    const TDF_Label sheet = shapes->AddShape(
        BRepPrimAPI_MakeBox(gp_Pnt(-1.5e5, -1.5e5, gap - 10.0), gp_Pnt(1.5e5, 1.5e5, gap)).Shape(),
        false);
    TDataStd_Name::Set(sheet, "sheet");
    return writeDocument(app, doc, path);
}

} // namespace

int main(int argc, char** argv) {
    const bool gap = (argc == 3 || argc == 4) && std::string(argv[1]) == "--gap";
    if (argc != 5 && !gap) {
        std::fprintf(stderr, "usage: idview_far_step_writer OUT.step X Y Z (millimetres)\n"
                             "       idview_far_step_writer --gap OUT.step [MM] (default 0.1)\n");
        return 2;
    }
    // A generator that exits at once: Open CASCADE's one-time registrations (XDE application,
    // STEP writer) are never freed, which LeakSanitizer would report in the sanitizer pass.
    const scene::OcctLeaksIgnored ignored;
    const char* path = gap ? argv[2] : argv[1];
    if (gap ? !writeGap(path, argc == 4 ? std::atof(argv[3]) : 0.1)
            : !write(path, gp_Vec(std::atof(argv[2]), std::atof(argv[3]), std::atof(argv[4])))) {
        std::fprintf(stderr, "idview_far_step_writer: cannot write %s\n", path);
        return 1;
    }
    return 0;
}
