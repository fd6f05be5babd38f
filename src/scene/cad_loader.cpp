// cad_loader.cpp - loadCad: STEP and IGES into an XDE document, BREP into one shape; the
// assembly tree walked down to its leaf instances; every distinct shape tessellated once (in
// parallel) and turned into a geometry with one part per triangulated face.
#include "scene/cad_loader.h"

#include "scene/brep_counts.h"
#include "scene/cad_mesh.h"
#include "scene/cad_reader_losses.h"
#include "scene/cad_sew.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <mutex>
#include <new>
#include <optional>
#include <sstream>

#include <BRepBndLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <IGESData_IGESModel.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Message_ProgressIndicator.hxx>
#include <Message_ProgressScope.hxx>
#include <Quantity_ColorRGBA.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif

namespace scene {

#if defined(__SANITIZE_ADDRESS__)
OcctLeaksIgnored::OcctLeaksIgnored() {
    __lsan_disable();
}
OcctLeaksIgnored::~OcctLeaksIgnored() {
    __lsan_enable();
}
#else
OcctLeaksIgnored::OcctLeaksIgnored() = default;
OcctLeaksIgnored::~OcctLeaksIgnored() = default;
#endif

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// A reason without the file name; loadCad puts "<path>: " in front.
struct Bad : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Far beyond any sample; a bound on what the readers are asked to hold in memory.
constexpr uintmax_t kMaxFileBytes = uintmax_t(1) << 31;
constexpr int kMaxAssemblyDepth = 64;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

enum class Format { Step, Iges, Brep, None };

Format formatOf(const std::string& path) {
    const std::string ext = lowercase(fs::path(path).extension().string());
    if (ext == ".step" || ext == ".stp") return Format::Step;
    if (ext == ".iges" || ext == ".igs") return Format::Iges;
    if (ext == ".brep") return Format::Brep;
    return Format::None;
}

// The readers trace to OCCT's default messenger, which prints on stdout, where idview writes
// its JSON lines: take its console printers away, once per process.
void quietOcct() {
    static std::once_flag once;
    std::call_once(once, [] {
        Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    });
}

// Some OCCT readers write their complaints straight to std::cout; while one runs they go here
// instead, so that stdout carries only idview's own output.
class CoutCapture {
  public:
    CoutCapture() : saved_(std::cout.rdbuf(captured_.rdbuf())) {}
    ~CoutCapture() { std::cout.rdbuf(saved_); }
    CoutCapture(const CoutCapture&) = delete;
    CoutCapture& operator=(const CoutCapture&) = delete;
    // The first line written, for an error message.
    std::string firstLine() const {
        const std::string text = captured_.str();
        return text.substr(0, text.find('\n'));
    }

  private:
    std::ostringstream captured_;
    std::streambuf* saved_;
};

// Hands OCCT's progress of one stage on to a CadProgress (OCCT serialises Show calls).
class ProgressRelay : public Message_ProgressIndicator {
  public:
    ProgressRelay(const CadProgress& to, const char* stage) : to_(to), stage_(stage) {
        if (to_) to_(stage_, 0.0);
    }

  protected:
    void Show(const Message_ProgressScope&, const Standard_Boolean) override {
        if (to_) to_(stage_, GetPosition());
    }

  private:
    const CadProgress& to_;
    const char* stage_;
};

// A progress range for `stage` that reports to `to` while `relay` lives.
Message_ProgressRange startStage(Handle(ProgressRelay) & relay, const CadProgress& to,
                                 const char* stage) {
    relay = new ProgressRelay(to, stage);
    return relay->Start();
}

void checkFile(const std::string& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Bad("file not found");
    if (!fs::is_regular_file(path, ec)) throw Bad("not a regular file");
    const uintmax_t size = fs::file_size(path, ec);
    if (ec) throw Bad("cannot read the file size: " + ec.message());
    if (size == 0) throw Bad("the file is empty");
    if (size > kMaxFileBytes) throw Bad("file too large (" + std::to_string(size) + " bytes)");
}

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

glm::mat4 toMat4(const gp_Trsf& t) {
    glm::mat4 m(1.0f);
    for (int row = 1; row <= 3; ++row)
        for (int col = 1; col <= 4; ++col) m[col - 1][row - 1] = float(t.Value(row, col));
    return m;
}

using Rgba = Quantity_ColorRGBA;

uint32_t packed(const Rgba& c) {
    auto byte = [](double v) { return uint32_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
    // Colours as stored (XCAF keeps them linear); 8 bits each is plenty to tell them apart.
    const Quantity_Color& rgb = c.GetRGB();
    return byte(rgb.Red()) << 24 | byte(rgb.Green()) << 16 | byte(rgb.Blue()) << 8 |
           byte(c.Alpha());
}

// One leaf instance of the assembly tree.
struct Leaf {
    TopoDS_Shape shape; // at the identity location: `world` places it
    gp_Trsf world;
    std::string name;    // the instance's or the product's; empty: numbered later
    std::string product; // the shape label's name, for the geometry
    std::string group;   // the path of the assemblies above it
    std::optional<Rgba> color;
    // Faces (or solids and shells, for all their faces) with colours of their own.
    std::vector<std::pair<TopoDS_Shape, Rgba>> subColors;
};

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
        leaves_.push_back(std::move(leaf));
    }

    Handle(XCAFDoc_ShapeTool) shapes_;
    Handle(XCAFDoc_ColorTool) colors_;
    std::vector<Leaf> leaves_;
};

// Closes the XDE document however the load ends, so that its memory goes.
Handle(XCAFApp_Application) application() {
    const OcctLeaksIgnored ignored; // its driver table, made once
    return XCAFApp_Application::GetApplication();
}

struct DocumentGuard {
    Handle(XCAFApp_Application) app = application();
    Handle(TDocStd_Document) doc;
    DocumentGuard() { app->NewDocument("MDTV-XCAF", doc); }
    ~DocumentGuard() {
        try {
            if (!doc.IsNull() && doc->IsOpened()) app->Close(doc);
        } catch (...) { // nothing to do about a failing close in a destructor
        }
    }
};

Handle(XSControl_WorkSession) sessionOf(STEPCAFControl_Reader& reader) {
    return reader.ChangeReader().WS();
}
Handle(XSControl_WorkSession) sessionOf(IGESCAFControl_Reader& reader) {
    return reader.WS();
}

// Reads the file into `doc` with names and colours; throws Bad with the reader's verdict.
// Returns what the reading dropped.
template <typename Reader>
ReaderLosses transfer(Reader& reader, const std::string& path, const std::string& format,
                      Handle(TDocStd_Document) & doc, const CadProgress& progress) {
    reader.SetColorMode(true);
    reader.SetNameMode(true);
    reader.SetLayerMode(false);
    if (progress) progress("reading", 0.0);
    IFSelect_ReturnStatus status;
    {
        const OcctLeaksIgnored ignored; // the IGES parser's buffers on a failed read
        status = reader.ReadFile(path.c_str());
    }
    if (status != IFSelect_RetDone) throw Bad(statusReason(status, format.c_str()));
    if (reader.NbRootsForTransfer() == 0) throw Bad("the " + format + " file holds no shapes");
    Handle(ProgressRelay) relay;
    if (!reader.Transfer(doc, startStage(relay, progress, "translating")))
        throw Bad("no shapes could be read from the " + format + " file");
    return readerLosses(sessionOf(reader));
}

// `sewTolerance`: for IGES, the file's resolution, within which its faces are sewn.
std::vector<Leaf> readXde(const std::string& path, Format format, const CadProgress& progress,
                          ReaderLosses& losses, double& sewTolerance) {
    DocumentGuard guard;
    // The first reader of each kind registers the toolkit's parameters, once per process.
    std::optional<OcctLeaksIgnored> ignored(std::in_place);
    if (format == Format::Step) {
        STEPCAFControl_Reader reader;
        ignored.reset();
        reader.SetPropsMode(false);
        reader.SetGDTMode(false);
        reader.SetMatMode(false);
        reader.SetViewMode(false);
        losses = transfer(reader, path, "STEP", guard.doc, progress);
    } else {
        IGESCAFControl_Reader reader;
        ignored.reset();
        losses = transfer(reader, path, "IGES", guard.doc, progress);
        const auto model = Handle(IGESData_IGESModel)::DownCast(reader.WS()->Model());
        if (!model.IsNull()) sewTolerance = model->GlobalSection().Resolution();
    }
    return TreeWalker(guard.doc).run();
}

std::vector<Leaf> readBrep(const std::string& path, const std::string& stem,
                           const CadProgress& progress) {
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
    if (!BRepTools::Read(shape, path.c_str(), builder, startStage(relay, progress, "reading")) ||
        shape.IsNull()) {
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

std::string hex(const Rgba& color) {
    char text[16];
    std::snprintf(text, sizeof text, "#%08x", packed(color));
    return text;
}

CadLoadResult load(const std::string& path, const CadOptions& options, const CadProgress& progress,
                   uint32_t levels) {
    const Format format = formatOf(path);
    if (format == Format::None) throw Bad("not a STEP, IGES or BREP file name");
    if (!(options.deflection >= 0.0) || !std::isfinite(options.deflection))
        throw Bad("the linear deflection must be a finite number of at least 0");
    if (!(options.angularDeflection > 0.0) || !std::isfinite(options.angularDeflection))
        throw Bad("the angular deflection must be a positive number of radians");
    checkFile(path);
    quietOcct();
    const std::string stem = fs::path(path).stem().string();
    CadLoadResult result;

    auto start = Clock::now();
    std::vector<Leaf> leaves;
    ReaderLosses losses;
    double sewTolerance = 0.0;
    {
        const CoutCapture quiet;
        leaves = format == Format::Brep ? readBrep(path, stem, progress)
                                        : readXde(path, format, progress, losses, sewTolerance);
    }
    result.readMs = msSince(start);
    if (leaves.empty()) throw Bad("the file holds no shapes");

    // Distinct shapes (same TShape, same orientation), each with its faces and bounds.
    struct Distinct {
        TopoDS_Shape shape;
        std::string name;
        TopTools_IndexedMapOfShape faces;
        std::vector<std::optional<Rgba>> faceColor; // by face index - 1: its own colour
        Bnd_Box box;
        int64_t geometry = -1;
    };
    std::vector<Distinct> distinct;
    std::map<std::pair<const void*, int>, size_t> distinctOf;
    std::vector<size_t> leafDistinct(leaves.size());
    uint32_t faceless = 0;
    Bnd_Box world;
    for (size_t i = 0; i < leaves.size(); ++i) {
        const Leaf& leaf = leaves[i];
        const auto key = std::make_pair(static_cast<const void*>(leaf.shape.TShape().get()),
                                        int(leaf.shape.Orientation()));
        auto [it, added] = distinctOf.try_emplace(key, distinct.size());
        if (added) {
            Distinct& d = distinct.emplace_back();
            d.shape = leaf.shape;
            d.name = leaf.product;
            TopExp::MapShapes(d.shape, TopAbs_FACE, d.faces);
            if (d.faces.Extent() > 0) BRepBndLib::Add(d.shape, d.box, false);
            // Coloured sub-shapes name their faces by TShape: their locations are the
            // product's, which the leaf's shape no longer carries.
            d.faceColor.resize(size_t(d.faces.Extent()));
            std::map<const void*, int> faceIndex;
            for (int f = d.faces.Extent(); f >= 1; --f) // the first of equal TShapes wins
                faceIndex[d.faces(f).TShape().get()] = f;
            for (const auto& [sub, color] : leaf.subColors) {
                TopTools_IndexedMapOfShape subFaces;
                TopExp::MapShapes(sub, TopAbs_FACE, subFaces);
                for (int f = 1; f <= subFaces.Extent(); ++f) {
                    const auto found = faceIndex.find(subFaces(f).TShape().get());
                    // A face's own label wins over a solid's or shell's that holds it.
                    if (found != faceIndex.end() &&
                        (!d.faceColor[size_t(found->second - 1)] || sub.ShapeType() == TopAbs_FACE))
                        d.faceColor[size_t(found->second - 1)] = color;
                }
            }
        }
        leafDistinct[i] = it->second;
        const Distinct& d = distinct[it->second];
        if (d.faces.Extent() == 0) {
            ++faceless;
            continue;
        }
        if (!d.box.IsVoid()) world.Add(d.box.Transformed(leaf.world));
    }
    if (faceless == leaves.size()) throw Bad("the file holds no shapes with faces");
    if (faceless)
        result.warnings.push_back(std::to_string(faceless) +
                                  " shapes without faces (wires or points) skipped");

    // Tessellation: every distinct shape once, all in one call so that faces mesh in parallel.
    double deflection = options.deflection;
    if (deflection == 0.0) {
        const double diagonal =
            world.IsVoid() || world.IsOpen() ? 0.0 : std::sqrt(world.SquareExtent());
        deflection =
            std::isfinite(diagonal) && diagonal > 0.0 ? diagonal * kRelativeDeflection : 0.01;
    }
    result.deflection = deflection;
    start = Clock::now();
    // Colours were matched above by the faces as read; sewing keeps their order.
    for (Distinct& d : distinct) sewFaces(d.shape, d.faces, sewTolerance);
    TopoDS_Compound all;
    BRep_Builder builder;
    builder.MakeCompound(all);
    for (const Distinct& d : distinct)
        if (d.faces.Extent() > 0) builder.Add(all, d.shape);
    IMeshTools_Parameters parameters;
    parameters.Deflection = deflection;
    parameters.Angle = options.angularDeflection;
    parameters.Relative = false;
    parameters.InParallel = true;
    Handle(ProgressRelay) relay;
    BRepMesh_IncrementalMesh mesher(all, parameters, startStage(relay, progress, "tessellating"));
    result.tessellationMs = msSince(start);

    Scene& scene = result.scene;
    // A material per distinct colour, for objects and for faces with colours of their own.
    std::map<uint32_t, uint32_t> materialOf;
    const uint32_t grey = addMaterial(scene, "default", Material{}.color);
    auto materialFor = [&](const Rgba& color) {
        auto [it, added] = materialOf.try_emplace(packed(color), 0);
        if (added) {
            const Quantity_Color& rgb = color.GetRGB();
            // XCAF holds linear RGB, as the renderer's material colours are.
            it->second = addMaterial(
                scene, "colour " + hex(color),
                glm::vec4(float(rgb.Red()), float(rgb.Green()), float(rgb.Blue()), color.Alpha()));
        }
        return it->second;
    };
    uint32_t unnamedShapes = 0, emptyShapes = 0;
    for (size_t di = 0; di < distinct.size(); ++di) {
        Distinct& d = distinct[di];
        if (progress) progress("building", double(di) / double(distinct.size()));
        if (d.faces.Extent() == 0) continue;
        Geometry& g = scene.geometries.emplace_back();
        g.name = d.name.empty() ? stem + " shape " + std::to_string(++unnamedShapes) : d.name;
        g.firstVertex = uint32_t(scene.vertices.size());
        g.firstIndex = uint32_t(scene.indices.size());
        g.firstPart = uint32_t(scene.parts.size());
        for (Standard_Integer f = 1; f <= d.faces.Extent(); ++f) {
            ++result.faces;
            if (appendFace(scene, TopoDS::Face(d.faces(f)), g.firstVertex)) {
                Geometry& built = scene.geometries.back();
                built.partFaces.push_back(uint32_t(f - 1));
                const auto& own = d.faceColor[size_t(f - 1)];
                built.partMaterials.push_back(own ? materialFor(*own) : gpu::OBJECT_MATERIAL);
            } else {
                ++result.facesFailed;
            }
            if (scene.vertices.size() > std::numeric_limits<uint32_t>::max() / 2 ||
                scene.indices.size() > std::numeric_limits<uint32_t>::max() / 2)
                throw Bad("the tessellation is too large (try a larger --deflection)");
        }
        Geometry& built = scene.geometries.back();
        if (std::all_of(built.partMaterials.begin(), built.partMaterials.end(),
                        [](uint32_t m) { return m == gpu::OBJECT_MATERIAL; }))
            built.partMaterials.clear(); // every face takes its object's colour
        built.vertexCount = uint32_t(scene.vertices.size()) - built.firstVertex;
        built.partCount = uint32_t(scene.parts.size()) - built.firstPart;
        if (built.partCount == 0) {
            ++emptyShapes;
            scene.geometries.pop_back();
            continue;
        }
        d.geometry = int64_t(scene.geometries.size() - 1);
    }
    if (levels > 1) {
        start = Clock::now();
        std::vector<CadShapeFaces> shapes;
        for (const Distinct& d : distinct)
            if (d.geometry >= 0) shapes.push_back({&d.faces, uint32_t(d.geometry)});
        addCadLevels(scene, all, shapes, deflection, options.angularDeflection, levels,
                     LodOptions{}, [&](double fraction) {
                         if (progress) progress("levels of detail", fraction);
                     });
        result.levelsMs = msSince(start);
    }
    if (const auto dropped =
            lossWarning(losses, result.faces, format == Format::Step ? "STEP" : "IGES"))
        result.warnings.push_back(*dropped);
    if (result.facesFailed)
        result.warnings.push_back(std::to_string(result.facesFailed) + " of " +
                                  std::to_string(result.faces) +
                                  " faces could not be triangulated and are left out");
    if (emptyShapes)
        result.warnings.push_back(std::to_string(emptyShapes) +
                                  " shapes had no face that triangulated and are left out");

    // Objects, one per leaf instance: the instance's colour, else the product's.
    uint32_t unnamed = 0;
    for (size_t i = 0; i < leaves.size(); ++i) {
        const Leaf& leaf = leaves[i];
        const Distinct& d = distinct[leafDistinct[i]];
        if (d.geometry < 0) continue;
        const uint32_t material = leaf.color ? materialFor(*leaf.color) : grey;
        const std::string name =
            leaf.name.empty() ? stem + " solid " + std::to_string(++unnamed) : leaf.name;
        addObject(scene, uint32_t(d.geometry), material, toMat4(leaf.world), name,
                  joinPath(leaf.group, name));
    }
    if (scene.objects.empty()) throw Bad("no face of the model could be triangulated");
    try {
        validate(scene);
    } catch (const std::invalid_argument& e) {
        throw Bad(std::string("inconsistent tessellation: ") + e.what());
    }
    return result;
}

} // namespace

bool isCadPath(const std::string& path) {
    return formatOf(path) != Format::None;
}

CadLoadResult loadCad(const std::string& path, const CadOptions& options,
                      const CadProgress& progress, uint32_t levels) {
    try {
        return load(path, options, progress, levels);
    } catch (const Bad& e) {
        throw ModelError(path + ": " + e.what());
    } catch (const Standard_Failure& e) {
        const char* message = e.GetMessageString();
        throw ModelError(path + ": Open CASCADE failed: " + e.DynamicType()->Name() +
                         (message && *message ? std::string(": ") + message : std::string()));
    } catch (const std::bad_alloc&) {
        throw ModelError(path + ": out of memory");
    }
}

} // namespace scene
