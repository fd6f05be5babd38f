// closed_cad_files.h - the occt-misc sample files that are closed models, chosen by Open
// CASCADE rather than by hand: read by its own plain readers (not idview's), every face of the
// file sewn within the tessellation's automatic deflection leaves no free edge. A gap narrower
// than that is below what the tessellation draws; a wider one is an opening of the model.
#pragma once

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Shape.hxx>

#include "scene/cad/cad_loader.h"

namespace testing_support {

// Debian's occt-misc samples.
inline const std::filesystem::path kOcctData = "/usr/share/opencascade/data";

// Files larger than this are left out to keep the tests' time small: Bottom.brep (3.8 MB) and
// Top.brep (3.5 MB) take seconds per level, terrain.brep (3.4 MB) half a minute.
constexpr uintmax_t kClosedTestMaxBytes = 3'000'000;

// The tests' own reading, not idview's: what Open CASCADE's readers and sewing keep past the
// read (their one-time set-up, and what a failed read leaves) is not idview's to free, so the
// leak check looks away here, as for the other tests' first reader (scene::OcctLeaksIgnored).
inline TopoDS_Shape readPlain(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    TopoDS_Shape shape;
    if (ext == ".step" || ext == ".stp") {
        STEPControl_Reader reader;
        if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) return {};
        reader.TransferRoots();
        shape = reader.OneShape();
    } else if (ext == ".iges" || ext == ".igs") {
        IGESControl_Reader reader;
        if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) return {};
        reader.TransferRoots();
        shape = reader.OneShape();
    } else if (ext == ".brep") {
        BRep_Builder builder;
        if (!BRepTools::Read(shape, path.c_str(), builder)) return {};
    }
    return shape;
}

// Open CASCADE's sewing of the file's faces, within kRelativeDeflection of its bounding box
// diagonal, finds no free edge (and the file has faces).
inline bool closedBySewing(const std::filesystem::path& path) {
    const scene::OcctLeaksIgnored ignored;
    const TopoDS_Shape shape = readPlain(path);
    if (shape.IsNull()) return false;
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    if (faces.Extent() == 0) return false;
    Bnd_Box box;
    BRepBndLib::Add(shape, box, false);
    if (box.IsVoid()) return false;
    BRepBuilderAPI_Sewing sewing(std::sqrt(box.SquareExtent()) * scene::kRelativeDeflection);
    sewing.Add(shape);
    sewing.Perform();
    return sewing.NbFreeEdges() == 0;
}

// The closed models among the STEP, IGES and BREP samples up to kClosedTestMaxBytes, sorted.
inline std::vector<std::string> closedCadFiles() {
    std::vector<std::string> closed;
    std::error_code ec;
    for (const char* folder : {"step", "iges", "occ"})
        for (const auto& entry : std::filesystem::directory_iterator(kOcctData / folder, ec))
            if (entry.is_regular_file() && scene::isCadPath(entry.path().string()) &&
                entry.file_size() <= kClosedTestMaxBytes && closedBySewing(entry.path()))
                closed.push_back(entry.path().string());
    std::sort(closed.begin(), closed.end());
    return closed;
}

} // namespace testing_support
