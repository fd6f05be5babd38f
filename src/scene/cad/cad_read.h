// cad_read.h - STEP and IGES read into an XDE document and BREP into one shape, down to the
// leaf instances of the assembly tree, for cad_loader.cpp. Internal to src/scene: unlike
// cad_loader.h it holds Open CASCADE types.
#pragma once

#include <atomic>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Message_ProgressIndicator.hxx>
#include <Message_ProgressScope.hxx>
#include <Quantity_ColorRGBA.hxx>
#include <TDF_Label.hxx>
#include <TDocStd_Document.hxx>
#include <TopoDS_Shape.hxx>
#include <XCAFApp_Application.hxx>
#include <gp_Trsf.hxx>

#include "scene/cad/cad_loader.h"
#include "scene/cad/cad_reader_losses.h"

namespace scene::cad {

// A reason without the file name; loadCad puts "<path>: " in front.
struct Bad : std::runtime_error {
    using std::runtime_error::runtime_error;
};
// A tessellation past --max-triangles: in a worker, it stops the whole load, not its piece.
struct OverBudget : Bad {
    using Bad::Bad;
};
enum class Format { Step, Iges, Brep, None };

// By the file name's extension, in any case (scene/formats.h's table); None for the formats
// of other readers and unknown names.
Format formatOf(const std::string& path);

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

// Hands OCCT's progress of one stage on to a CadProgress (OCCT serialises Show calls), and
// tells OCCT to stop (UserBreak, polled by the readers and the mesher) while `stop` says so.
class ProgressRelay : public Message_ProgressIndicator {
  public:
    ProgressRelay(const CadProgress& to, const char* stage, std::function<bool()> stop)
        : to_(to), stage_(stage), stop_(std::move(stop)) {
        if (to_) to_(stage_, 0.0);
    }
    Standard_Boolean UserBreak() override { return stop_ && stop_(); }

  protected:
    void Show(const Message_ProgressScope&, const Standard_Boolean) override {
        if (to_) to_(stage_, GetPosition());
    }

  private:
    const CadProgress& to_;
    const char* stage_;
    std::function<bool()> stop_;
};

// A progress range for `stage` that reports to `to` while `relay` lives, and breaks off
// while `stop` returns true.
inline Message_ProgressRange startStage(Handle(ProgressRelay) & relay, const CadProgress& to,
                                        const char* stage, std::function<bool()> stop = {}) {
    relay = new ProgressRelay(to, stage, std::move(stop));
    return relay->Start();
}

// The stop test of a `cancel` flag that may be null.
inline std::function<bool()> cancelled(const std::atomic<bool>* cancel) {
    return [cancel] { return cancel && cancel->load(); };
}
using Rgba = Quantity_ColorRGBA;

// Leaf::solid of a leaf that is its whole shape, and of the faces of no solid of a split one.
constexpr int32_t kWholeShape = -1, kFreeFaces = -2;

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
    // The labels walked from a free shape down to the leaf's shape (references, assemblies, the
    // shape), from leavesOf only (readXde's document is closed): what an export
    // (step_exterior.h) copies. And which piece of that shape splitSolids made this leaf:
    // solid N (from 0), or the free faces.
    std::vector<TDF_Label> trail;
    int32_t solid = kWholeShape;
};

// An XDE document, closed however its user ends, so that its memory goes.
struct XdeDocument {
    Handle(XCAFApp_Application) app;
    Handle(TDocStd_Document) doc;
    XdeDocument();
    ~XdeDocument();
    XdeDocument(const XdeDocument&) = delete;
    XdeDocument& operator=(const XdeDocument&) = delete;
};

// What an XDE reader reads: a file, or (STEP only) text in memory, `path` then naming it in
// Open CASCADE's messages.
struct XdeSource {
    std::string path;
    const std::string* text = nullptr;
};
// Sees the reader's session once the file is transferred (its model and what each entity
// became), before the document is walked.
using SessionInspector = std::function<void(const Handle(XSControl_WorkSession)&)>;

// The leaves of a STEP or IGES file with names and colours; `losses`: what the reader dropped;
// `sewTolerance`: for IGES, the file's resolution, within which its faces are sewn (else
// left as it is). Throws Bad with the reader's verdict. Translation stops while `cancel` is
// set (the caller then says so).
std::vector<Leaf> readXde(const XdeSource& source, Format format, const CadProgress& progress,
                          ReaderLosses& losses, double& sewTolerance,
                          const std::atomic<bool>* cancel, const SessionInspector& inspect = {});

// readXde's first half: the file read into `doc` with names and colours; returns what the
// reader dropped. Throws Bad.
ReaderLosses readDocument(const XdeSource& source, Format format, Handle(TDocStd_Document) & doc,
                          const CadProgress& progress, double& sewTolerance,
                          const std::atomic<bool>* cancel, const SessionInspector& inspect = {});
// Its second half: the document walked from its free shapes down to the leaves.
std::vector<Leaf> leavesOf(const Handle(TDocStd_Document) & doc);

// A BREP file's shape as one leaf named `stem`. Throws Bad.
std::vector<Leaf> readBrep(const std::string& path, const std::string& stem,
                           const CadProgress& progress, const std::atomic<bool>* cancel);

// Each leaf whose shape holds several solids (a compound, as BREP files and some STEP products
// are), or a solid beside faces of no solid, becomes one leaf per solid, so that a solid is an
// object of its own to pick and select as a whole. They are named "solid N" (N from 1, in
// TopExp_Explorer order) under the compound's path (its name, else its product's, else "<stem>
// compound N"); the faces of no solid, if any, become one more leaf, "free faces". Each keeps
// the compound's colour and the sub-shape colours that touch its faces. Other leaves stay.
std::vector<Leaf> splitSolids(std::vector<Leaf> leaves, const std::string& stem);

} // namespace scene::cad
