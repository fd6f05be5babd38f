// step_copies.cpp - idview-step-copies: a STEP file's whole assembly copied N times onto a grid
// and written as one STEP file, to make large test assemblies out of the small ones we have.
//
//   idview-step-copies [--instanced] [--axes xy] -n N -o OUT.step IN.step
//
// OUT's root assembly, named after OUT's stem, holds instances "copy 1" to "copy N" of a
// product named after IN's stem, which holds IN's free shapes as its components, named as IN
// names them: so every object of IN is in OUT under "OUT-stem/copy k/" with its own name (an
// instance named "copy k" of IN's root itself would rename a root that is one part). Deep
// copies (the default) give each copy products and shapes of its own (BRepBuilderAPI_Copy);
// --instanced places one product N times. The grid is idview's own (scene/copy_grid.h).
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <Bnd_Box.hxx>
#include <Message_ProgressIndicator.hxx>
#include <Message_ProgressScope.hxx>
#include <Quantity_ColorRGBA.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <TDF_LabelDataMap.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include "scene/copy_grid.h"

namespace {

namespace fs = std::filesystem;

constexpr const char* kTool = "idview-step-copies";
constexpr const char* kUsage =
    "usage: idview-step-copies [--instanced] [--axes xy] -n N -o OUT.step IN.step";

// Bad input: what() is the one line the user reads.
struct Refusal : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Options {
    bool instanced = false;
    uint32_t axes = scene::COPY_XY;
    uint32_t copies = 0;
    std::string out;
    std::string in;
};

uint32_t parseCount(const std::string& text) {
    size_t used = 0;
    unsigned long long n = 0;
    try {
        n = std::stoull(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || text[0] == '-' || n < 1 || n > 1'000'000)
        throw Refusal("-n: the number of copies must be a whole number from 1 to 1000000, not '" +
                      text + "'");
    return uint32_t(n);
}

Options parseArgs(int argc, char** argv) {
    Options o;
    bool counted = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw Refusal(arg + " needs a value; " + kUsage);
            return argv[++i];
        };
        if (arg == "--instanced") {
            o.instanced = true;
        } else if (arg == "--axes") {
            try {
                o.axes = scene::parseCopyAxes(value());
            } catch (const std::invalid_argument& e) {
                throw Refusal(std::string("--axes ") + e.what());
            }
        } else if (arg == "-n") {
            o.copies = parseCount(value());
            counted = true;
        } else if (arg == "-o") {
            o.out = value();
        } else if (!arg.empty() && arg[0] == '-') {
            throw Refusal("unknown option '" + arg + "'; " + kUsage);
        } else if (o.in.empty()) {
            o.in = arg;
        } else {
            throw Refusal("one input file only, not '" + o.in + "' and '" + arg + "'; " + kUsage);
        }
    }
    if (!counted || o.out.empty() || o.in.empty())
        throw Refusal(std::string(!counted        ? "-n N is missing"
                                  : o.out.empty() ? "-o OUT.step is missing"
                                                  : "the input file is missing") +
                      "; " + kUsage);
    return o;
}

// One line on stderr, rewritten in place, while stderr is a terminal (nothing otherwise).
namespace progress {
bool shown() {
    static const bool terminal = isatty(STDERR_FILENO);
    return terminal;
}
void show(const std::string& text) {
    if (shown()) std::fprintf(stderr, "\r\033[K%s: %s", kTool, text.c_str());
}
void clear() {
    if (shown()) std::fprintf(stderr, "\r\033[K");
}

// Open CASCADE's progress of one stage, as a percentage after the stage's words.
class Stage : public Message_ProgressIndicator {
  public:
    explicit Stage(std::string words) : words_(std::move(words)) { show(words_); }

  protected:
    void Show(const Message_ProgressScope&, const Standard_Boolean) override {
        const int percent = int(GetPosition() * 100.0);
        if (percent == percent_) return;
        percent_ = percent;
        show(words_ + " " + std::to_string(percent) + "%");
    }

  private:
    std::string words_;
    int percent_ = -1;
};
} // namespace progress

// An XDE document, closed however the run ends so that its memory goes.
struct Document {
    Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
    Handle(TDocStd_Document) doc;
    Document() { app->NewDocument("MDTV-XCAF", doc); }
    ~Document() {
        if (!doc.IsNull() && doc->IsOpened()) app->Close(doc);
    }
    Document(const Document&) = delete;
    Document& operator=(const Document&) = delete;
    Handle(XCAFDoc_ShapeTool) shapes() const {
        return XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    }
    Handle(XCAFDoc_ColorTool) colors() const {
        return XCAFDoc_DocumentTool::ColorTool(doc->Main());
    }
};

// Reads `path` into `into` with names and colours; the reader, and the STEP model it holds,
// are gone when this returns.
void readStep(const std::string& path, Document& into) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Refusal(path + ": file not found");
    if (!fs::is_regular_file(path, ec)) throw Refusal(path + ": not a regular file");
    if (fs::file_size(path, ec) == 0) throw Refusal(path + ": the file is empty");
    STEPCAFControl_Reader reader;
    reader.SetColorMode(true);
    reader.SetNameMode(true);
    const std::string file = fs::path(path).filename().string(); // the line stays short
    progress::show("reading " + file);
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
        throw Refusal(path + ": not a readable STEP file");
    if (reader.NbRootsForTransfer() == 0) throw Refusal(path + ": the STEP file holds no shapes");
    Handle(progress::Stage) translating = new progress::Stage("translating " + file);
    if (!reader.Transfer(into.doc, translating->Start()))
        throw Refusal(path + ": no shapes could be read from the STEP file");
    TDF_LabelSequence roots;
    into.shapes()->GetFreeShapes(roots);
    if (roots.IsEmpty()) throw Refusal(path + ": the STEP file holds no shapes");
}

// The sides of the box around every free shape as placed, exact on the surfaces (as idview's
// copies measure the tessellated model, whose points lie on them).
glm::dvec3 extentOf(const Document& input) {
    TDF_LabelSequence roots;
    input.shapes()->GetFreeShapes(roots);
    Bnd_Box box;
    for (const TDF_Label& root : roots)
        BRepBndLib::AddOptimal(XCAFDoc_ShapeTool::GetShape(root), box, false, false);
    if (box.IsVoid()) return glm::dvec3(0.0);
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    return glm::dvec3(x1 - x0, y1 - y0, z1 - z0);
}

TCollection_ExtendedString utf8(const std::string& text) {
    return TCollection_ExtendedString(text.c_str(), Standard_True);
}

// Copies the input document's assembly into the output document: products, assemblies and
// their components with names and colours (of products, instances and sub-shapes).
class Copier {
  public:
    // `source`: the input file, for errors.
    Copier(const Document& from, const Document& to, std::string source)
        : from_(from.shapes()), fromColors_(from.colors()), to_(to.shapes()),
          toColors_(to.colors()), source_(std::move(source)) {}

    // A new product named `name` whose components are the input's free shapes, each placed
    // and named as the input has it; with `deep`, every shape under it is a copy of its own.
    TDF_Label wholeInput(const std::string& name, bool deep) {
        deep_ = deep;
        copied_.Clear(); // a product the input places twice is one product within one copy
        const TDF_Label whole = to_->NewShape();
        TDataStd_Name::Set(whole, utf8(name));
        TDF_LabelSequence roots;
        from_->GetFreeShapes(roots);
        for (const TDF_Label& root : roots) {
            TDF_Label product = root;
            if (XCAFDoc_ShapeTool::IsReference(root))
                XCAFDoc_ShapeTool::GetReferredShape(root, product);
            const TDF_Label placed =
                to_->AddComponent(whole, copy(product), XCAFDoc_ShapeTool::GetLocation(root));
            // The name and colour idview's loader gives the root: the reference's, else the
            // product's (whose colour the product carries already).
            copyName(root, placed);
            if (product != root) copyColors(root, placed);
        }
        return whole;
    }

  private:
    TDF_Label copy(const TDF_Label& from) {
        if (const TDF_Label* done = copied_.Seek(from)) return *done;
        const TDF_Label to =
            XCAFDoc_ShapeTool::IsAssembly(from) ? copyAssembly(from) : copyPart(from);
        copyName(from, to);
        copyColors(from, to);
        copied_.Bind(from, to);
        return to;
    }

    TDF_Label copyAssembly(const TDF_Label& from) {
        const TDF_Label to = to_->NewShape();
        TDF_LabelSequence components;
        XCAFDoc_ShapeTool::GetComponents(from, components, false);
        for (const TDF_Label& component : components) {
            TDF_Label referred;
            if (!XCAFDoc_ShapeTool::GetReferredShape(component, referred)) continue;
            const TDF_Label placed =
                to_->AddComponent(to, copy(referred), XCAFDoc_ShapeTool::GetLocation(component));
            copyName(component, placed);
            copyColors(component, placed);
        }
        return to;
    }

    TDF_Label copyPart(const TDF_Label& from) {
        const TopoDS_Shape shape = XCAFDoc_ShapeTool::GetShape(from);
        const TDF_Label to = to_->NewShape();
        if (!deep_) {
            to_->SetShape(to, shape);
            copySubShapeColors(from, to, shape, nullptr);
            return to;
        }
        BRepBuilderAPI_Copy copier(shape, Standard_True, Standard_False);
        to_->SetShape(to, copier.Shape());
        copySubShapeColors(from, to, shape, &copier);
        return to;
    }

    // Faces, shells and solids with colours of their own: each colour goes to the sub-shape
    // the copy made of it (by the copy's history), or to the same one when not copied.
    void copySubShapeColors(const TDF_Label& from, const TDF_Label& to, const TopoDS_Shape& shape,
                            BRepBuilderAPI_Copy* copier) {
        TDF_LabelSequence subs;
        XCAFDoc_ShapeTool::GetSubShapes(from, subs);
        TopTools_IndexedMapOfShape all; // the copy's history is keyed by these, as placed
        for (const TDF_Label& sub : subs) {
            if (!hasColor(sub)) continue;
            TopoDS_Shape piece = XCAFDoc_ShapeTool::GetShape(sub);
            if (copier) {
                if (all.IsEmpty()) TopExp::MapShapes(shape, all);
                piece = copier->ModifiedShape(historyKey(all, piece, from));
            }
            TDF_Label added;
            to_->AddSubShape(to, piece, added); // finds it instead where it is there already
            if (added.IsNull())
                throw Refusal(source_ + ": " + nameOf(from) + ": a coloured sub-shape is lost");
            copyColors(sub, added);
        }
    }

    static std::string nameOf(const TDF_Label& label) {
        Handle(TDataStd_Name) name;
        if (!label.FindAttribute(TDataStd_Name::GetID(), name)) return "a product";
        return "product '" + std::string(TCollection_AsciiString(name->Get()).ToCString()) + "'";
    }
    // `piece` as the copy's history knows it: the same sub-shape, else one of its TShape
    // (a sub-shape label may hold it at another location than the product's shape does).
    TopoDS_Shape historyKey(const TopTools_IndexedMapOfShape& all, const TopoDS_Shape& piece,
                            const TDF_Label& product) const {
        if (all.Contains(piece)) return piece;
        for (int i = 1; i <= all.Extent(); ++i)
            if (all(i).TShape() == piece.TShape()) return all(i);
        throw Refusal(source_ + ": " + nameOf(product) +
                      ": a coloured sub-shape is not part of its shape");
    }

    bool hasColor(const TDF_Label& label) const {
        for (XCAFDoc_ColorType type : {XCAFDoc_ColorGen, XCAFDoc_ColorSurf, XCAFDoc_ColorCurv})
            if (fromColors_->IsSet(label, type)) return true;
        return false;
    }
    void copyColors(const TDF_Label& from, const TDF_Label& to) {
        Quantity_ColorRGBA color;
        for (XCAFDoc_ColorType type : {XCAFDoc_ColorGen, XCAFDoc_ColorSurf, XCAFDoc_ColorCurv})
            if (fromColors_->GetColor(from, type, color)) toColors_->SetColor(to, color, type);
    }
    static void copyName(const TDF_Label& from, const TDF_Label& to) {
        Handle(TDataStd_Name) name;
        if (from.FindAttribute(TDataStd_Name::GetID(), name)) TDataStd_Name::Set(to, name->Get());
    }

    Handle(XCAFDoc_ShapeTool) from_;
    Handle(XCAFDoc_ColorTool) fromColors_;
    Handle(XCAFDoc_ShapeTool) to_;
    Handle(XCAFDoc_ColorTool) toColors_;
    std::string source_;
    bool deep_ = true;
    TDF_LabelDataMap copied_; // input product or assembly -> its copy in this copy
};

// The root assembly, named after OUT's stem, with the N copies on the grid.
void buildCopies(const Options& o, const Document& input, const Document& output) {
    const glm::dvec3 step = scene::copyStep(extentOf(input));
    const std::string inStem = fs::path(o.in).stem().string();
    const Handle(XCAFDoc_ShapeTool) shapes = output.shapes();
    const TDF_Label root = shapes->NewShape();
    TDataStd_Name::Set(root, utf8(fs::path(o.out).stem().string()));
    Copier copier(input, output, o.in);
    TDF_Label shared;
    if (o.instanced) shared = copier.wholeInput(inStem, false);
    for (uint32_t k = 0; k < o.copies; ++k) {
        progress::show("copying " + std::to_string(k + 1) + "/" + std::to_string(o.copies));
        const glm::dvec3 shift = scene::copyShift(k, o.copies, o.axes, step);
        gp_Trsf move;
        move.SetTranslation(gp_Vec(shift.x, shift.y, shift.z));
        const TDF_Label product = o.instanced ? shared : copier.wholeInput(inStem, true);
        const TDF_Label placed = shapes->AddComponent(root, product, TopLoc_Location(move));
        TDataStd_Name::Set(placed, utf8("copy " + std::to_string(k + 1)));
    }
    shapes->UpdateAssemblies();
}

void writeStep(const Document& output, const std::string& path) {
    STEPCAFControl_Writer writer;
    writer.SetColorMode(true);
    writer.SetNameMode(true);
    Handle(progress::Stage) translating = new progress::Stage("translating the copies");
    if (!writer.Transfer(output.doc, STEPControl_AsIs, nullptr, translating->Start()))
        throw Refusal(path + ": Open CASCADE could not translate the copies to STEP");
    progress::show("writing " + fs::path(path).filename().string());
    // A write that fails or throws half-way leaves no half of a file behind.
    struct Partial {
        const std::string& path;
        bool done = false;
        ~Partial() {
            std::error_code ec;
            if (!done) fs::remove(path, ec);
        }
    } partial{path};
    if (writer.Write(path.c_str()) != IFSelect_RetDone)
        throw Refusal(path + ": cannot write the file");
    partial.done = true;
}

void run(const Options& o) {
    const fs::path folder = fs::path(o.out).parent_path();
    std::error_code ec;
    if (!folder.empty() && !fs::is_directory(folder, ec))
        throw Refusal(o.out + ": the folder " + folder.string() + " does not exist");
    XCAFDoc_ShapeTool::SetAutoNaming(false); // no made-up names on the copies' labels
    const Document output;
    {
        Document input; // closed once copied: the copies hold what they need
        readStep(o.in, input);
        buildCopies(o, input, output);
    }
    writeStep(output, o.out);
}

} // namespace

int main(int argc, char** argv) {
    if (argc == 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
        std::printf("%s\n", kUsage);
        return 0;
    }
    // Open CASCADE's readers and writers report on std::cout; this tool prints nothing there.
    std::cout.rdbuf(nullptr);
    std::string error;
    try {
        const Options o = parseArgs(argc, argv);
        try {
            run(o);
            progress::clear();
            return 0;
        } catch (const Standard_Failure& e) {
            error = o.in + ": Open CASCADE failed: " + e.DynamicType()->Name() + ": " +
                    e.GetMessageString();
        } catch (const std::bad_alloc&) {
            error = o.in + ": out of memory making " + std::to_string(o.copies) + " copies";
        }
    } catch (const Refusal& e) {
        error = e.what();
    }
    progress::clear();
    std::fprintf(stderr, "%s: error: %s\n", kTool, error.c_str());
    return 1;
}
