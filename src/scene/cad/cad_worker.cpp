// cad_worker.cpp - a CAD load's worker: the job loop, the skeleton and whole files
// (cad_worker.h); pieces are cad_piece.cpp's.
#include "scene/cad/cad_worker.h"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <new>
#include <sys/resource.h>

#include <BRep_TVertex.hxx>
#include <Standard_Failure.hxx>
#include <StepData_StepModel.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TransferBRep.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>

#include "scene/cad/brep_occt.h"
#include "scene/cad/cad_healing.h"
#include "scene/cad/cad_stages.h"
#include "util/memory.h"
#include "util/worker_pool.h"

namespace scene::cad {
namespace {

glm::dvec4 toColor(const Rgba& c) {
    const Quantity_Color& rgb = c.GetRGB();
    return {rgb.Red(), rgb.Green(), rgb.Blue(), c.Alpha()};
}

// The shapes the skeleton's sets became, by TShape, as piece numbers: each set is one entity
// of the model (its number in the file, the piece's dummySet), transferred to a compound of
// its two vertices.
std::map<const void*, int32_t> setShapes(const Handle(XSControl_WorkSession) & session,
                                         const std::vector<uint64_t>& dummySets) {
    std::map<uint64_t, int32_t> pieceOf;
    for (size_t i = 0; i < dummySets.size(); ++i) pieceOf[dummySets[i]] = int32_t(i);
    std::map<const void*, int32_t> out;
    const auto model = Handle(StepData_StepModel)::DownCast(session->Model());
    if (model.IsNull()) return out;
    const Handle(Transfer_TransientProcess) process = session->TransferReader()->TransientProcess();
    for (Standard_Integer i = 1; i <= model->NbEntities(); ++i) {
        const Handle(Standard_Transient) entity = model->Value(i);
        const auto found = pieceOf.find(uint64_t(model->IdentLabel(entity)));
        if (found == pieceOf.end()) continue;
        const TopoDS_Shape shape = TransferBRep::ShapeResult(process, entity);
        if (!shape.IsNull()) out[shape.TShape().get()] = found->second;
    }
    return out;
}

// A leaf as the skeleton gives it: whose set its shape is, and the set's corners.
SkeletonLeaf skeletonLeaf(const Leaf& leaf, const std::map<const void*, int32_t>& sets) {
    SkeletonLeaf out;
    out.world = toMatrix(leaf.world);
    out.name = leaf.name;
    out.product = leaf.product;
    out.group = leaf.group;
    if (leaf.color) out.color = toColor(*leaf.color);
    const auto found = sets.find(leaf.shape.TShape().get());
    if (found == sets.end()) {
        TopTools_IndexedMapOfShape faces;
        TopExp::MapShapes(leaf.shape, TopAbs_FACE, faces);
        out.faces = uint32_t(faces.Extent());
        return out;
    }
    out.piece = found->second;
    std::vector<glm::dvec3> corners;
    for (TopExp_Explorer e(leaf.shape, TopAbs_VERTEX); e.More(); e.Next()) {
        // The point as the set's own frame has it: the leaf's world places it.
        const gp_Pnt p = Handle(BRep_TVertex)::DownCast(e.Current().TShape())->Pnt();
        corners.emplace_back(p.X(), p.Y(), p.Z());
    }
    if (corners.size() == 2) {
        out.boxMin = glm::min(corners[0], corners[1]);
        out.boxMax = glm::max(corners[0], corners[1]);
    }
    return out;
}

void answer(int fd, AnswerKind kind, const std::string& bytes) {
    if (!util::sendFrame(fd, uint32_t(kind), bytes)) _exit(1); // the parent is gone
}

// Progress of a whole file, to the parent: each stage's start and every hundredth after. Open
// CASCADE calls it one thread at a time.
CadProgress progressTo(int fd) {
    auto last = std::make_shared<std::pair<std::string, int>>("", -1);
    return [fd, last](const char* stage, double fraction) {
        const int percent = int(fraction * 100.0);
        if (last->first == stage && last->second == percent) return;
        *last = {stage, percent};
        answer(fd, AnswerKind::Progress, encodeProgress(stage, fraction));
    };
}

// Fault injection for the tests of what a worker's end costs: IDVIEW_TEST_WORKER_SIGNAL=P:S
// makes the worker that is handed piece P raise signal S (9 as a kill from outside would,
// 11 as a crash inside Open CASCADE would) before it reads it.
void injectedFault(uint32_t piece) {
    const char* asked = std::getenv("IDVIEW_TEST_WORKER_SIGNAL");
    unsigned p = 0;
    int signal = 0;
    if (asked && std::sscanf(asked, "%u:%d", &p, &signal) == 2 && p == piece) std::raise(signal);
}

// One job: its answer, or its failure in words.
void runJob(int fd, const util::Frame& frame) {
    try {
        switch (JobKind(frame.kind)) {
        case JobKind::Skeleton:
            answer(fd, AnswerKind::Skeleton, encode(readSkeleton(decodeSkeletonJob(frame.bytes))));
            return;
        case JobKind::Piece: {
            const PieceJob job = decodePieceJob(frame.bytes);
            injectedFault(job.piece);
            answer(fd, AnswerKind::Piece, encode(readPiece(job)));
            return;
        }
        case JobKind::WholeFile:
            answer(fd, AnswerKind::WholeFile,
                   encode(readWholeFile(decodeWholeFileJob(frame.bytes), progressTo(fd))));
            return;
        case JobKind::StepExport:
            writeStepExport(decodeStepExportJob(frame.bytes));
            answer(fd, AnswerKind::StepExport, {});
            return;
        }
        answer(fd, AnswerKind::Failed, "a job this worker does not know");
    } catch (const OverBudget& e) {
        answer(fd, AnswerKind::Stopped, e.what());
    } catch (const std::bad_alloc&) {
        answer(fd, AnswerKind::Failed,
               "out of memory (" + std::to_string(util::mebibytes(util::residentBytes())) +
                   " MiB in use by the worker)");
    } catch (const Standard_Failure& e) {
        const char* message = e.GetMessageString();
        answer(fd, AnswerKind::Failed,
               std::string("Open CASCADE failed: ") + e.DynamicType()->Name() +
                   (message && *message ? std::string(": ") + message : std::string()));
    } catch (const std::exception& e) {
        answer(fd, AnswerKind::Failed, e.what());
    }
}

} // namespace

SkeletonAnswer readSkeleton(const SkeletonJob& job) {
    const auto start = Clock::now();
    quietOcct();
    setStepHealing(false); // the sets are points: nothing to heal
    std::map<const void*, int32_t> sets;
    Read read;
    guarded("reading the assembly structure", [&] {
        read.leaves =
            readXde({"skeleton", &job.text}, Format::Step, {}, read.losses, read.sewTolerance,
                    nullptr, [&](const Handle(XSControl_WorkSession) & session) {
                        sets = setShapes(session, job.dummySets);
                    });
    });
    SkeletonAnswer out;
    for (const Leaf& leaf : read.leaves) out.leaves.push_back(skeletonLeaf(leaf, sets));
    out.entities = read.losses.entities;
    out.failedEntities = read.losses.failedEntities;
    out.ms = msSince(start);
    return out;
}

WholeFileAnswer readWholeFile(const WholeFileJob& job, const CadProgress& progress) {
    WholeFileAnswer out;
    out.result = loadCadInProcess(job.path, job.options, progress, job.levels, nullptr);
    const auto start = Clock::now();
    const std::shared_ptr<const BrepShapes> brep = out.result.scene.brep;
    for (uint32_t g = 0; brep && g < brep->geometryCount(); ++g)
        out.brep.push_back(brep->encoded(g));
    out.result.scene.brep.reset();
    out.figures.encodeMs = msSince(start);
    out.figures.parseMs = out.result.readMs;
    out.figures.meshMs = out.result.tessellationMs;
    out.figures.levelsMs = out.result.levelsMs;
    out.figures.healingMs = takeHealingMs();
    out.figures.peakBytes = util::peakResidentBytes();
    return out;
}

int runLoadWorker(int fd) {
    // For the tests of a worker running out of memory: IDVIEW_TEST_WORKER_MEMORY=MiB bounds its
    // heap (RLIMIT_DATA), so that an allocation fails as it would on a full machine.
    if (const char* mib = std::getenv("IDVIEW_TEST_WORKER_MEMORY"); mib && *mib) {
        const rlim_t bytes = rlim_t(std::strtoull(mib, nullptr, 10)) << 20;
        const rlimit limit{bytes, bytes};
        setrlimit(RLIMIT_DATA, &limit);
    }
    util::Frame frame;
    while (util::receiveFrame(fd, frame)) runJob(fd, frame);
    return 0;
}

} // namespace scene::cad
