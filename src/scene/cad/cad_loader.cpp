// cad_loader.cpp - loadCad: the file read down to its leaf instances (cad_read.h); every
// distinct shape sewn where the format needs it, tessellated once (in parallel) and turned
// into a geometry with one part per triangulated face.
#include "scene/cad/cad_loader.h"

#include "scene/cad/brep_occt.h"
#include "scene/cad/cad_check.h"

#include "scene/cad/cad_mesh.h"
#include "scene/cad/cad_read.h"
#include "scene/cad/cad_reader_losses.h"
#include "scene/cad/cad_sew.h"
#include "scene/cad/cad_surface.h"
#include "scene/cad/fault_guard.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <mutex>
#include <new>
#include <optional>

#include <BRepBndLib.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Quantity_ColorRGBA.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>

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

using namespace cad;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Far beyond any sample; a bound on what the readers are asked to hold in memory.
constexpr uintmax_t kMaxFileBytes = uintmax_t(1) << 31;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The readers trace to OCCT's default messenger, which prints on stdout, where idview writes
// its JSON lines: take its console printers away, once per process.
void quietOcct() {
    static std::once_flag once;
    std::call_once(once, [] {
        Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    });
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

// Double, as Open CASCADE keeps it: a part placed kilometres away keeps its millimetres.
glm::dmat4 toMatrix(const gp_Trsf& t) {
    glm::dmat4 m(1.0);
    for (int row = 1; row <= 3; ++row)
        for (int col = 1; col <= 4; ++col) m[col - 1][row - 1] = t.Value(row, col);
    return m;
}

uint32_t packed(const Rgba& c) {
    auto byte = [](double v) { return uint32_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
    // Colours as stored (XCAF keeps them linear); 8 bits each is plenty to tell them apart.
    const Quantity_Color& rgb = c.GetRGB();
    return byte(rgb.Red()) << 24 | byte(rgb.Green()) << 16 | byte(rgb.Blue()) << 8 |
           byte(c.Alpha());
}

std::string hex(const Rgba& color) {
    char text[16];
    std::snprintf(text, sizeof text, "#%08x", packed(color));
    return text;
}

// Open CASCADE crashes on some damaged files (7.6's IGES reader on a B-spline surface whose
// parameter lines are blank dereferences a null array): such a crash on this thread is
// refused in words that name the stage. Faults on the mesher's worker threads are not caught.
template <typename Body>
void guarded(const char* stage, Body&& body) {
    if (const int signal = runGuarded(body))
        throw Bad(std::string("Open CASCADE crashed while ") + stage + " (" + faultName(signal) +
                  "): the file is damaged or holds something its reader does not handle");
}

// The shapes the scene's geometries were tessellated from, for exact inspection
// (brep_shapes.h); their triangulations are dropped, the scene has its own copy.
template <typename Distinct>
std::shared_ptr<const BrepShapes> keptShapes(const std::vector<Distinct>& distinct,
                                             size_t geometries) {
    auto impl = std::make_unique<BrepShapes::Impl>();
    impl->geometries.resize(geometries);
    for (const Distinct& d : distinct) {
        if (d.geometry < 0) continue;
        BRepTools::Clean(d.shape);
        auto& kept = impl->geometries[size_t(d.geometry)];
        kept.shape = d.shape;
        for (int f = 1; f <= d.faces.Extent(); ++f) kept.faces.push_back(TopoDS::Face(d.faces(f)));
    }
    return std::make_shared<const BrepShapes>(std::move(impl));
}

CadLoadResult load(const std::string& path, const CadOptions& options, const CadProgress& progress,
                   uint32_t levels, const std::atomic<bool>* cancel) {
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
        guarded("reading the file", [&] {
            leaves = format == Format::Brep
                         ? readBrep(path, stem, progress, cancel)
                         : readXde(path, format, progress, losses, sewTolerance, cancel);
        });
    }
    leaves = splitSolids(std::move(leaves), stem);
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
    const double diagonal =
        world.IsVoid() || world.IsOpen() ? 0.0 : std::sqrt(world.SquareExtent());
    const double automatic =
        std::isfinite(diagonal) && diagonal > 0.0 ? diagonal * kRelativeDeflection : 0.01;
    const double deflection = options.deflection == 0.0 ? automatic : options.deflection;
    result.deflection = deflection;
    start = Clock::now();
    // Colours were matched above by the faces as read; sewing keeps their order. A gap the
    // file's resolution leaves open but narrower than the deflection is below what the
    // tessellation draws (its triangles stray that far from the surface anyway), yet each side
    // would be sampled on its own and the background would show through: such gaps are sewn
    // too, never wider than the automatic deflection, so that a coarse --deflection cannot
    // join edges that are apart in the model. STEP and BREP files state their faces' shared
    // edges; only IGES files (sewTolerance set) are sewn.
    const double gapTolerance = std::min(deflection, automatic);
    guarded("sewing the faces", [&] {
        for (Distinct& d : distinct) sewFaces(d.shape, d.faces, sewTolerance, gapTolerance);
    });
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
    MeshBudget budget;
    budget.maxTriangles = options.maxTriangles;
    budget.cancel = cancel;
    guarded("checking the faces", [&] { budget.skipped = facesLeavingTheirSurface(all); });
    guarded("tessellating", [&] {
        meshCounted(all, parameters, budget, startStage(relay, progress, "tessellating", [&budget] {
                        return budget.stop();
                    }));
    });
    if (cancel && *cancel) throw Bad("cancelled");
    if (budget.over) {
        // What the whole would have come to, at the rate of the faces counted so far.
        uint64_t faces = 0;
        for (const Distinct& d : distinct) faces += uint64_t(d.faces.Extent());
        const double meshed = std::max(1.0, double(budget.facesMeshed.load()));
        const double estimate = double(budget.triangles) * std::max(1.0, double(faces) / meshed);
        throw Bad(triangleLimitReason(uint64_t(estimate), options.maxTriangles, deflection));
    }
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
        if (cancel && *cancel) throw Bad("cancelled");
        if (d.faces.Extent() == 0) continue;
        Geometry& g = scene.geometries.emplace_back();
        g.name = d.name.empty() ? stem + " shape " + std::to_string(++unnamedShapes) : d.name;
        g.firstVertex = uint32_t(scene.vertices.size());
        g.firstIndex = uint32_t(scene.indices.size());
        g.firstPart = uint32_t(scene.parts.size());
        SharedPoints shared;
        for (Standard_Integer f = 1; f <= d.faces.Extent(); ++f) {
            ++result.faces;
            if (appendFace(scene, TopoDS::Face(d.faces(f)), g.firstVertex, &shared)) {
                Geometry& built = scene.geometries.back();
                built.partFaces.push_back(uint32_t(f - 1));
                built.partSurfaces.push_back(surfaceOf(TopoDS::Face(d.faces(f))));
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
                     LodOptions{}, budget.skipped, [&](double fraction) {
                         if (cancel && *cancel) throw Bad("cancelled");
                         if (progress) progress("levels of detail", fraction);
                     });
        result.levelsMs = msSince(start);
    }
    if (const auto dropped =
            lossWarning(losses, result.faces, format == Format::Step ? "STEP" : "IGES"))
        result.warnings.push_back(*dropped);
    if (!budget.skipped.empty())
        result.warnings.push_back(std::to_string(budget.skipped.size()) +
                                  " faces have edges that run off their surface (a damaged "
                                  "file) and are not meshed");
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
        addObject(scene, uint32_t(d.geometry), material, toMatrix(leaf.world), name,
                  joinPath(leaf.group, name));
    }
    if (scene.objects.empty()) throw Bad("no face of the model could be triangulated");
    scene.brep = keptShapes(distinct, scene.geometries.size());
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

std::string triangleLimitReason(uint64_t estimate, uint64_t limit, double deflection) {
    // A curved face's triangles grow as 1 / deflection: aim at half the limit.
    double suggested =
        deflection * std::max(2.0, 2.0 * double(estimate) / double(std::max<uint64_t>(limit, 1)));
    const double step = std::pow(10.0, std::floor(std::log10(suggested)) - 1.0);
    suggested = std::ceil(suggested / step) * step;
    char text[200];
    std::snprintf(text, sizeof text,
                  "the tessellation passes --max-triangles %llu (about %llu triangles at "
                  "deflection %.3g); try --deflection %g",
                  static_cast<unsigned long long>(limit), static_cast<unsigned long long>(estimate),
                  deflection, suggested);
    return text;
}

CadLoadResult loadCad(const std::string& path, const CadOptions& options,
                      const CadProgress& progress, uint32_t levels,
                      const std::atomic<bool>* cancel) {
    try {
        return load(path, options, progress, levels, cancel);
    } catch (const Bad& e) {
        // A reader broken off by the flag says only that it read nothing.
        if (cancel && *cancel) throw ModelError(path + ": cancelled");
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
