// cad_read.cpp - the readers behind cad_read.h: XDE documents walked down to their leaves,
// BREP files checked before Open CASCADE reads them.
#include "scene/cad/cad_read.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include <map>
#include <sstream>

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Static.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Compound.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include "scene/cad/brep_counts.h"
#include "scene/formats.h"

namespace scene::cad {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxAssemblyDepth = 64;

std::string statusReason(IFSelect_ReturnStatus status, const char* format) {
    switch (status) {
    case IFSelect_RetVoid:
        return std::string("no ") + format + " data in the file";
    case IFSelect_RetError:
        return std::string("not a readable ") + format + " file (the reader found errors)";
    case IFSelect_RetFail:
        return std::string("not a readable ") + format + " file (the reader failed on it)";
    case IFSelect_RetStop:
        return std::string("the ") + format + " reader stopped on this file";
    default:
        return std::string("the ") + format + " reader refused the file";
    }
}
// Walks an XDE document from its free shapes down to the leaves.
class TreeWalker {
  public:
    explicit TreeWalker(const Handle(TDocStd_Document) & doc)
        : shapes_(XCAFDoc_DocumentTool::ShapeTool(doc->Main())),
          colors_(XCAFDoc_DocumentTool::ColorTool(doc->Main())) {}

    std::vector<Leaf> run() {
        TDF_LabelSequence roots;
        shapes_->GetFreeShapes(roots);
        for (Standard_Integer i = 1; i <= roots.Length(); ++i)
            walk(roots.Value(i), gp_Trsf(), std::string(), nullptr, 0);
        return std::move(leaves_);
    }

  private:
    static std::string nameOf(const TDF_Label& label) {
        Handle(TDataStd_Name) name;
        if (label.IsNull() || !label.FindAttribute(TDataStd_Name::GetID(), name)) return {};
        return TCollection_AsciiString(name->Get()).ToCString(); // UTF-8
    }

    std::optional<Rgba> colorOf(const TDF_Label& label) const {
        Rgba color;
        if (colors_->GetColor(label, XCAFDoc_ColorSurf, color) ||
            colors_->GetColor(label, XCAFDoc_ColorGen, color))
            return color;
        return std::nullopt;
    }

    // The sub-shapes of the shape (faces, or solids and shells holding them) with colours.
    std::vector<std::pair<TopoDS_Shape, Rgba>> subColors(const TDF_Label& shapeLabel) const {
        std::vector<std::pair<TopoDS_Shape, Rgba>> colored;
        TDF_LabelSequence subs;
        XCAFDoc_ShapeTool::GetSubShapes(shapeLabel, subs);
        for (Standard_Integer i = 1; i <= subs.Length(); ++i)
            if (const auto color = colorOf(subs.Value(i)))
                colored.emplace_back(XCAFDoc_ShapeTool::GetShape(subs.Value(i)), *color);
        return colored;
    }

    void walk(const TDF_Label& label, const gp_Trsf& parent, const std::string& group,
              const TDF_Label* instance, int depth) {
        if (depth > kMaxAssemblyDepth) throw Bad("assembly nested too deep");
        trail_.push_back(label);
        visit(label, parent, group, instance, depth);
        trail_.pop_back();
    }

    void visit(const TDF_Label& label, const gp_Trsf& parent, const std::string& group,
               const TDF_Label* instance, int depth) {
        if (XCAFDoc_ShapeTool::IsReference(label)) {
            TDF_Label referred;
            if (!XCAFDoc_ShapeTool::GetReferredShape(label, referred)) return;
            const gp_Trsf here =
                parent.Multiplied(XCAFDoc_ShapeTool::GetLocation(label).Transformation());
            walk(referred, here, group, &label, depth + 1);
            return;
        }
        std::string name = instance ? nameOf(*instance) : std::string();
        const std::string product = nameOf(label);
        if (name.empty()) name = product;
        if (XCAFDoc_ShapeTool::IsAssembly(label)) {
            // A free assembly's own placement (components carry theirs as references).
            const gp_Trsf here =
                instance
                    ? parent
                    : parent.Multiplied(XCAFDoc_ShapeTool::GetLocation(label).Transformation());
            const std::string path = joinPath(group, name.empty() ? "assembly" : name);
            TDF_LabelSequence components;
            XCAFDoc_ShapeTool::GetComponents(label, components, false);
            for (Standard_Integer i = 1; i <= components.Length(); ++i)
                walk(components.Value(i), here, path, nullptr, depth + 1);
            return;
        }
        TopoDS_Shape shape = XCAFDoc_ShapeTool::GetShape(label);
        if (shape.IsNull()) return;
        Leaf leaf;
        leaf.world = parent.Multiplied(shape.Location().Transformation());
        shape.Location(TopLoc_Location());
        leaf.shape = shape;
        leaf.name = name;
        leaf.product = product;
        leaf.group = group;
        leaf.color = instance ? colorOf(*instance) : std::nullopt;
        if (!leaf.color) leaf.color = colorOf(label);
        leaf.subColors = subColors(label);
        leaf.trail = trail_;
        leaves_.push_back(std::move(leaf));
    }

    Handle(XCAFDoc_ShapeTool) shapes_;
    Handle(XCAFDoc_ColorTool) colors_;
    std::vector<Leaf> leaves_;
    std::vector<TDF_Label> trail_; // from the free shape down to the label being walked
};

Handle(XCAFApp_Application) application() {
    const OcctLeaksIgnored ignored; // its driver table, made once
    return XCAFApp_Application::GetApplication();
}

IFSelect_ReturnStatus readInto(STEPCAFControl_Reader& reader, const XdeSource& source) {
    if (!source.text) return reader.ReadFile(source.path.c_str());
    std::istringstream stream(*source.text);
    return reader.ChangeReader().ReadStream(source.path.c_str(), stream);
}
IFSelect_ReturnStatus readInto(IGESCAFControl_Reader& reader, const XdeSource& source) {
    return reader.ReadFile(source.path.c_str());
}

Handle(XSControl_WorkSession) sessionOf(STEPCAFControl_Reader& reader) {
    return reader.ChangeReader().WS();
}
Handle(XSControl_WorkSession) sessionOf(IGESCAFControl_Reader& reader) {
    return reader.WS();
}

// Reads the file (or `text`, STEP only, where it is given) into `doc` with names and colours;
// throws Bad with the reader's verdict. Returns what the reading dropped.
template <typename Reader>
ReaderLosses transfer(Reader& reader, const XdeSource& source, const std::string& format,
                      Handle(TDocStd_Document) & doc, const CadProgress& progress,
                      const std::atomic<bool>* cancel) {
    reader.SetColorMode(true);
    reader.SetNameMode(true);
    reader.SetLayerMode(false);
    if (progress) progress("reading", 0.0);
    IFSelect_ReturnStatus status;
    {
        const OcctLeaksIgnored ignored; // the IGES parser's buffers on a failed read
        status = readInto(reader, source);
    }
    if (status != IFSelect_RetDone) throw Bad(statusReason(status, format.c_str()));
    if (reader.NbRootsForTransfer() == 0) throw Bad("the " + format + " file holds no shapes");
    Handle(ProgressRelay) relay;
    if (!reader.Transfer(doc, startStage(relay, progress, "translating", cancelled(cancel))))
        throw Bad("no shapes could be read from the " + format + " file");
    return readerLosses(sessionOf(reader));
}
// The sub-shape colours of `leaf` that touch a face of `part`, by the faces' TShapes (a
// sub-shape's location is the product's, which the parts no longer carry).
std::vector<std::pair<TopoDS_Shape, Rgba>>
colorsTouching(const TopoDS_Shape& part, const std::multimap<const void*, size_t>& byFace,
               const Leaf& leaf) {
    std::vector<bool> taken(leaf.subColors.size(), false);
    std::vector<std::pair<TopoDS_Shape, Rgba>> touching;
    for (TopExp_Explorer e(part, TopAbs_FACE); e.More(); e.Next()) {
        const auto [first, last] = byFace.equal_range(e.Current().TShape().get());
        for (auto it = first; it != last; ++it)
            if (!taken[it->second]) {
                taken[it->second] = true;
                touching.push_back(leaf.subColors[it->second]);
            }
    }
    return touching;
}

// `leaf` split into its solids and the faces of no solid.
void appendSplit(const Leaf& leaf, const std::string& group, std::vector<Leaf>& out) {
    std::multimap<const void*, size_t> byFace; // face TShape -> sub-colour index
    for (size_t i = 0; i < leaf.subColors.size(); ++i) {
        TopTools_IndexedMapOfShape faces;
        TopExp::MapShapes(leaf.subColors[i].first, TopAbs_FACE, faces);
        for (int f = 1; f <= faces.Extent(); ++f) byFace.emplace(faces(f).TShape().get(), i);
    }
    auto add = [&](TopoDS_Shape part, const std::string& name, int32_t solid) {
        Leaf& piece = out.emplace_back();
        piece.trail = leaf.trail;
        piece.solid = solid;
        piece.world = leaf.world.Multiplied(part.Location().Transformation());
        piece.subColors = colorsTouching(part, byFace, leaf);
        part.Location(TopLoc_Location());
        piece.shape = part;
        piece.name = name;
        piece.product = leaf.product.empty() ? std::string() : leaf.product + " " + name;
        piece.group = group;
        piece.color = leaf.color;
    };
    int32_t n = 0;
    for (TopExp_Explorer e(leaf.shape, TopAbs_SOLID); e.More(); e.Next(), ++n)
        add(e.Current(), "solid " + std::to_string(n + 1), n);
    TopoDS_Compound free;
    BRep_Builder builder;
    builder.MakeCompound(free);
    bool any = false;
    for (TopExp_Explorer e(leaf.shape, TopAbs_FACE, TopAbs_SOLID); e.More(); e.Next(), any = true)
        builder.Add(free, e.Current());
    if (any) add(free, "free faces", kFreeFaces);
}

} // namespace

std::vector<Leaf> splitSolids(std::vector<Leaf> leaves, const std::string& stem) {
    std::vector<Leaf> out;
    out.reserve(leaves.size());
    uint32_t unnamed = 0;
    for (Leaf& leaf : leaves) {
        int solids = 0;
        for (TopExp_Explorer e(leaf.shape, TopAbs_SOLID); e.More() && solids < 2; e.Next())
            ++solids;
        const bool freeFaces =
            solids > 0 && TopExp_Explorer(leaf.shape, TopAbs_FACE, TopAbs_SOLID).More();
        if (solids < 2 && !freeFaces) {
            out.push_back(std::move(leaf));
            continue;
        }
        const std::string name = !leaf.name.empty() ? leaf.name
                                 : !leaf.product.empty()
                                     ? leaf.product
                                     : stem + " compound " + std::to_string(++unnamed);
        appendSplit(leaf, joinPath(leaf.group, name), out);
    }
    return out;
}

Format formatOf(const std::string& path) {
    const ModelFormat* format = formatOfName(path);
    switch (format ? format->reader : Reader::Gltf) {
    case Reader::Step:
        return Format::Step;
    case Reader::Iges:
        return Format::Iges;
    case Reader::Brep:
        return Format::Brep;
    default:
        return Format::None;
    }
}

XdeDocument::XdeDocument() : app(application()) {
    app->NewDocument("MDTV-XCAF", doc);
}
XdeDocument::~XdeDocument() {
    try {
        if (!doc.IsNull() && doc->IsOpened()) app->Close(doc);
    } catch (...) { // nothing to do about a failing close in a destructor
    }
}

std::vector<Leaf> readXde(const XdeSource& source, Format format, const CadProgress& progress,
                          ReaderLosses& losses, double& sewTolerance,
                          const std::atomic<bool>* cancel, const SessionInspector& inspect) {
    XdeDocument document;
    losses = readDocument(source, format, document.doc, progress, sewTolerance, cancel, inspect);
    std::vector<Leaf> leaves = leavesOf(document.doc);
    for (Leaf& leaf : leaves) leaf.trail.clear(); // its labels close with the document
    return leaves;
}

std::vector<Leaf> leavesOf(const Handle(TDocStd_Document) & doc) {
    return TreeWalker(doc).run();
}

ReaderLosses readDocument(const XdeSource& source, Format format, Handle(TDocStd_Document) & doc,
                          const CadProgress& progress, double& sewTolerance,
                          const std::atomic<bool>* cancel, const SessionInspector& inspect) {
    ReaderLosses losses;
    // The first reader of each kind registers the toolkit's parameters, once per process.
    std::optional<OcctLeaksIgnored> ignored(std::in_place);
    if (format == Format::Step) {
        STEPCAFControl_Reader reader;
        ignored.reset();
        reader.SetPropsMode(false);
        reader.SetGDTMode(false);
        reader.SetMatMode(false);
        reader.SetViewMode(false);
        losses = transfer(reader, source, "STEP", doc, progress, cancel);
        if (inspect) inspect(sessionOf(reader));
    } else {
        if (source.text) throw Bad("IGES is read from its file only");
        IGESCAFControl_Reader reader;
        ignored.reset();
        losses = transfer(reader, source, "IGES", doc, progress, cancel);
        const auto model = Handle(IGESData_IGESModel)::DownCast(reader.WS()->Model());
        if (!model.IsNull()) sewTolerance = model->GlobalSection().Resolution();
        if (inspect) inspect(sessionOf(reader));
    }
    return losses;
}

std::vector<Leaf> readBrep(const std::string& path, const std::string& stem,
                           const CadProgress& progress, const std::atomic<bool>* cancel) {
    // BRepTools::Read reports a wrong header on stdout: check it here first.
    std::ifstream in(path, std::ios::binary);
    std::string head(256, '\0');
    in.read(head.data(), std::streamsize(head.size()));
    head.resize(size_t(in.gcount()));
    if (head.find("CASCADE Topology V") == std::string::npos)
        throw Bad("not a BREP file (no 'CASCADE Topology' header)");
    in.clear();
    in.seekg(0);
    if (const auto why = implausibleBrepCount(in, fs::file_size(path)))
        throw Bad("not a readable BREP file: " + *why);
    TopoDS_Shape shape;
    BRep_Builder builder;
    const CoutCapture capture;
    Handle(ProgressRelay) relay;
    // Open CASCADE's reader goes on reading a stream that has failed, where every read leaves
    // its value as it was, and some damaged files keep it looping on one for ever: the first
    // read that fails throws instead.
    in.clear();
    in.seekg(0);
    in.exceptions(std::ios::failbit | std::ios::badbit);
    try {
        BRepTools::Read(shape, in, builder,
                        startStage(relay, progress, "reading", cancelled(cancel)));
    } catch (const std::ios_base::failure&) {
        throw Bad("not a readable BREP file: it ends, or breaks off, where a value was expected");
    }
    if (shape.IsNull()) {
        const std::string said = capture.firstLine();
        throw Bad("not a readable BREP file" + (said.empty() ? "" : " (" + said + ")"));
    }
    Leaf leaf;
    leaf.world = shape.Location().Transformation();
    shape.Location(TopLoc_Location());
    leaf.shape = shape;
    leaf.name = leaf.product = stem;
    return {std::move(leaf)};
}

} // namespace scene::cad

namespace scene {

LengthUnit cadUnit(const std::string& path) {
    if (cad::formatOf(path) == cad::Format::Brep)
        return {"", "BREP files store no unit (Open CASCADE's modelling is in millimetres by "
                    "habit, not by the file)"};
    // The readers register the parameter when the first is made; a cache hit may come before
    // any, and then the default holds.
    const char* name = Interface_Static::IsPresent("xstep.cascade.unit")
                           ? Interface_Static::CVal("xstep.cascade.unit")
                           : nullptr;
    const std::string value = name && *name ? name : "MM";
    static const std::pair<const char*, const char*> symbols[] = {
        {"MM", "mm"},   {"M", "m"},   {"CM", "cm"}, {"KM", "km"},   {"UM", "\u00b5m"},
        {"INCH", "in"}, {"FT", "ft"}, {"MI", "mi"}, {"MIL", "mil"}, {"UIN", "\u00b5in"}};
    for (const auto& [occt, symbol] : symbols)
        if (value == occt)
            return {symbol, "Open CASCADE converts STEP and IGES files to " + std::string(symbol) +
                                " (xstep.cascade.unit " + value + ")"};
    return {value, "Open CASCADE's xstep.cascade.unit " + value};
}

} // namespace scene
