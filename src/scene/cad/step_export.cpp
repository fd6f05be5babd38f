// step_export.cpp - the worker's side of writeStepSubset (step_exterior.h): the source read into
// an XDE document, its leaves matched with the scene's objects, and a new document made of the
// kept leaves with the assemblies above them, written by Open CASCADE's STEP writer.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>

#include <BRep_Builder.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDF_Tool.hxx>
#include <TDataStd_Name.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS_Compound.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include "scene/cad/cad_healing.h"
#include "scene/cad/cad_stages.h"
#include "scene/cad/cad_worker.h"

namespace scene::cad {
namespace {

namespace fs = std::filesystem;

// The source as an XDE document: STEP and IGES as their readers give it, a BREP file's shape as
// one free product named after the file's stem, as the loader names it.
void readSource(const std::string& path, Format format, const std::string& stem,
                XdeDocument& into) {
    const CoutCapture quiet;
    guarded("reading the file", [&] {
        if (format != Format::Brep) {
            double sewTolerance = 0.0; // IGES: the loader sews; the file keeps its faces as read
            readDocument({path}, format, into.doc, {}, sewTolerance, nullptr);
            return;
        }
        const Leaf leaf = readBrep(path, stem, {}, nullptr).front();
        const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(into.doc->Main());
        // A location made of an identity transformation is not the identity location, and
        // would make the shape an instance.
        const TopLoc_Location placed =
            leaf.world.Form() == gp_Identity ? TopLoc_Location() : TopLoc_Location(leaf.world);
        const TDF_Label added = shapes->AddShape(leaf.shape.Located(placed), false);
        const TCollection_ExtendedString name(stem.c_str(), Standard_True);
        TDataStd_Name::Set(added, name);
        TDF_Label product;
        if (XCAFDoc_ShapeTool::GetReferredShape(added, product)) TDataStd_Name::Set(product, name);
    });
}

// Per leaf: whether it is kept. The leaves with faces are the scene's objects, in order, named
// as addObjects names them; throws Bad where they are not the job's.
std::vector<bool> keptLeaves(const std::vector<Leaf>& leaves, const StepExportJob& job,
                             const std::string& stem) {
    std::vector<bool> kept(leaves.size(), false);
    uint32_t unnamed = 0;
    size_t object = 0;
    for (size_t i = 0; i < leaves.size(); ++i) {
        if (!TopExp_Explorer(leaves[i].shape, TopAbs_FACE).More()) continue; // no object
        const std::string path = joinPath(leaves[i].group, objectName(leaves[i], stem, unnamed));
        if (object >= job.paths.size() || job.paths[object] != path)
            throw Bad("the file no longer gives the scene loaded from it (object " +
                      std::to_string(object + 1) + " is '" +
                      (object < job.paths.size() ? job.paths[object] : std::string()) +
                      "' in the scene, '" + path + "' in the file); load it again");
        kept[i] = job.keep[object++] != 0;
    }
    if (object != job.paths.size())
        throw Bad("the file no longer gives the scene loaded from it (" + std::to_string(object) +
                  " objects, the scene has " + std::to_string(job.paths.size()) +
                  "); load it again");
    return kept;
}

// Copies the kept leaves of one XDE document into another with the assemblies above them.
// A product (assembly or shape) is copied once for each distinct choice of what is kept below
// it, so instances that keep the same stay instances of one product.
class SubsetCopier {
  public:
    SubsetCopier(const Handle(TDocStd_Document) & from, const Handle(TDocStd_Document) & to,
                 const std::vector<Leaf>& leaves, const std::vector<bool>& kept)
        : fromColors_(XCAFDoc_DocumentTool::ColorTool(from->Main())),
          to_(XCAFDoc_DocumentTool::ShapeTool(to->Main())),
          toColors_(XCAFDoc_DocumentTool::ColorTool(to->Main())), leaves_(leaves), kept_(kept) {}

    void run() {
        forRuns(0, leaves_.size(), 0, [&](size_t b, size_t e) {
            if (const std::optional<Placed> placed = resolve(b, e, 0)) addRoot(*placed);
        });
        to_->UpdateAssemblies();
    }

  private:
    // A product made in the output, and the placement its shape carried in the source.
    struct Made {
        TDF_Label label;
        TopLoc_Location own;
    };
    // A product as placed by a component or a free shape: the source's instance, if any.
    struct Placed {
        TDF_Label product;
        TopLoc_Location location;
        TDF_Label instance;
    };

    // How many of the leaves [b, e) are kept.
    size_t keptOf(size_t b, size_t e) const {
        return size_t(std::count(kept_.begin() + long(b), kept_.begin() + long(e), true));
    }

    // Calls f(b, e) for each run of leaves of [begin, end) that share trail[depth].
    template <typename F>
    void forRuns(size_t begin, size_t end, size_t depth, F f) const {
        for (size_t b = begin; b < end;) {
            size_t e = b + 1;
            while (e < end && leaves_[e].trail[depth] == leaves_[b].trail[depth]) ++e;
            f(b, e);
            b = e;
        }
    }

    // Leaves [b, e) share trail[0..depth]; that label is a reference or a product.
    std::optional<Placed> resolve(size_t b, size_t e, size_t depth) {
        const TDF_Label& label = leaves_[b].trail[depth];
        const bool reference = XCAFDoc_ShapeTool::IsReference(label);
        const std::optional<Made> made = product(b, e, reference ? depth + 1 : depth);
        if (!made) return std::nullopt;
        const TopLoc_Location placement =
            reference ? XCAFDoc_ShapeTool::GetLocation(label) : TopLoc_Location();
        return Placed{made->label, placement * made->own, reference ? label : TDF_Label()};
    }

    std::optional<Made> product(size_t b, size_t e, size_t depth) {
        const TDF_Label& label = leaves_[b].trail[depth];
        TCollection_AsciiString entry;
        TDF_Tool::Entry(label, entry);
        std::string key = std::string(entry.ToCString()) + '/';
        for (size_t i = b; i < e; ++i) key += kept_[i] ? '1' : '0';
        if (keptOf(b, e) == 0) return std::nullopt;
        if (const auto done = made_.find(key); done != made_.end()) return done->second;
        const Made made =
            depth + 1 == leaves_[b].trail.size() ? part(b, e, label) : assembly(b, e, depth, label);
        made_.emplace(key, made);
        return made;
    }

    Made assembly(size_t b, size_t e, size_t depth, const TDF_Label& from) {
        std::vector<Placed> children;
        forRuns(b, e, depth + 1, [&](size_t cb, size_t ce) {
            if (const std::optional<Placed> placed = resolve(cb, ce, depth + 1))
                children.push_back(*placed);
        });
        const TDF_Label to = to_->NewShape();
        copyAttributes(from, to);
        for (const Placed& child : children) {
            const TDF_Label component = to_->AddComponent(to, child.product, child.location);
            if (!child.instance.IsNull()) copyAttributes(child.instance, component);
        }
        // A free assembly's own placement; a component's is its reference's.
        return {to, depth == 0 ? XCAFDoc_ShapeTool::GetLocation(from) : TopLoc_Location()};
    }

    // The leaves [b, e) of one shape: all of it, or (split by splitSolids) some of its pieces.
    Made part(size_t b, size_t e, const TDF_Label& from) {
        const TopoDS_Shape located = XCAFDoc_ShapeTool::GetShape(from);
        const TopoDS_Shape shape = located.Located(TopLoc_Location());
        const bool whole =
            std::all_of(kept_.begin() + long(b), kept_.begin() + long(e), [](bool k) { return k; });
        const TDF_Label to = to_->AddShape(whole ? shape : keptPieces(shape, b, e), false);
        copyAttributes(from, to);
        TDF_LabelSequence subs;
        XCAFDoc_ShapeTool::GetSubShapes(from, subs);
        const TopLoc_Location unplace = located.Location().Inverted();
        for (const TDF_Label& sub : subs) {
            const TopoDS_Shape s = XCAFDoc_ShapeTool::GetShape(sub);
            // Null where the sub-shape is in a piece left out.
            const TDF_Label copied = to_->AddSubShape(to, s.Located(unplace * s.Location()));
            if (!copied.IsNull()) copyAttributes(sub, copied);
        }
        return {to, located.Location()};
    }

    // The kept pieces of `shape` (its solids, and its faces of no solid) as one compound.
    TopoDS_Shape keptPieces(const TopoDS_Shape& shape, size_t b, size_t e) const {
        std::vector<int32_t> pieces;
        for (size_t i = b; i < e; ++i)
            if (kept_[i]) pieces.push_back(leaves_[i].solid);
        auto wanted = [&](int32_t piece) {
            return std::find(pieces.begin(), pieces.end(), piece) != pieces.end();
        };
        TopoDS_Compound compound;
        BRep_Builder builder;
        builder.MakeCompound(compound);
        int32_t n = 0;
        for (TopExp_Explorer s(shape, TopAbs_SOLID); s.More(); s.Next(), ++n)
            if (wanted(n)) builder.Add(compound, s.Current());
        if (wanted(kFreeFaces))
            for (TopExp_Explorer f(shape, TopAbs_FACE, TopAbs_SOLID); f.More(); f.Next())
                builder.Add(compound, f.Current());
        return compound;
    }

    void addRoot(const Placed& placed) {
        if (placed.location.IsIdentity()) return; // the product is a free shape already
        if (!XCAFDoc_ShapeTool::IsSimpleShape(placed.product))
            throw Bad("the file places a free assembly by a location of its own, which the STEP "
                      "export does not copy");
        const TDF_Label root = to_->AddShape(
            XCAFDoc_ShapeTool::GetShape(placed.product).Located(placed.location), false);
        if (!placed.instance.IsNull()) copyAttributes(placed.instance, root);
    }

    // The name and the colours of every kind.
    void copyAttributes(const TDF_Label& from, const TDF_Label& to) {
        // Open CASCADE names the labels it makes ("SOLID", "=>[0:1:1:2]"); a label the source left
        // unnamed stays so, for the loader to name it as it named the source's.
        Handle(TDataStd_Name) name;
        if (from.FindAttribute(TDataStd_Name::GetID(), name))
            TDataStd_Name::Set(to, name->Get());
        else
            to.ForgetAttribute(TDataStd_Name::GetID());
        for (const XCAFDoc_ColorType type :
             {XCAFDoc_ColorGen, XCAFDoc_ColorSurf, XCAFDoc_ColorCurv}) {
            Quantity_ColorRGBA color;
            if (fromColors_->GetColor(from, type, color)) toColors_->SetColor(to, color, type);
        }
    }

    Handle(XCAFDoc_ColorTool) fromColors_;
    Handle(XCAFDoc_ShapeTool) to_;
    Handle(XCAFDoc_ColorTool) toColors_;
    const std::vector<Leaf>& leaves_;
    const std::vector<bool>& kept_;
    std::map<std::string, Made> made_; // by source label entry and what is kept below it
};

// Writes `doc` at the partial path, then renames it to `out`.
void writeDocument(const Handle(TDocStd_Document) & doc, const std::string& out) {
    const std::string partial = partialStepPath(out);
    const CoutCapture quiet;
    bool written = false;
    guarded("writing the STEP file", [&] {
        std::optional<OcctLeaksIgnored> ignored(std::in_place); // the writer's one-time setup
        STEPCAFControl_Writer writer;
        ignored.reset();
        writer.SetColorMode(true);
        writer.SetNameMode(true);
        if (!writer.Transfer(doc, STEPControl_AsIs))
            throw Bad("Open CASCADE's STEP writer could not translate the kept solids");
        written = writer.Write(partial.c_str()) == IFSelect_RetDone;
    });
    std::error_code ec;
    if (written) fs::rename(partial, out, ec);
    if (!written || ec) {
        std::remove(partial.c_str());
        throw Bad(out + ": cannot write the STEP file" + (ec ? " (" + ec.message() + ")" : ""));
    }
}

} // namespace

void writeStepExport(const StepExportJob& job) {
    if (job.keep.size() != job.paths.size()) throw Bad("a STEP export job without its objects");
    quietOcct();
    setStepHealing(job.healing != Healing::Off); // as a file read whole is
    const std::string stem = fs::path(job.source).stem().string();
    XdeDocument source, out;
    std::vector<Leaf> leaves;
    std::vector<bool> kept;
    try {
        const Format format = checkedFormat(job.source, CadOptions{}, 1);
        readSource(job.source, format, stem, source);
        leaves = splitSolids(leavesOf(source.doc), stem);
        kept = keptLeaves(leaves, job, stem);
    } catch (const Bad& e) {
        throw Bad(job.source + ": " + e.what());
    }
    SubsetCopier(source.doc, out.doc, leaves, kept).run();
    writeDocument(out.doc, job.out);
}

} // namespace scene::cad
