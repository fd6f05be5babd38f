// cad_session.cpp - a CAD load done by worker processes (cad_session.h).
#include "scene/cad/cad_session.h"

#include <algorithm>
#include <deque>
#include <filesystem>
#include <thread>
#include <unistd.h>

#include "scene/cad/cad_assembly.h"
#include "scene/cad/cad_stages.h"
#include "util/memory.h"
#include "util/program_paths.h"
#include "util/worker_pool.h"

namespace scene::cad {
namespace {

namespace fs = std::filesystem;
using Event = util::WorkerPool::Event;

constexpr auto kPoll = std::chrono::milliseconds(50);
// The process tree's memory is sampled this often while the parent waits.
constexpr auto kSampleEvery = std::chrono::milliseconds(100);
// Partial scenes go to a viewer at most this often, and sooner only once the solids shown have
// grown by kPartialGrowth: each is a copy of the scene and a new upload.
constexpr auto kPartialEvery = std::chrono::milliseconds(1500);
constexpr auto kPartialSoonest = std::chrono::milliseconds(250);
constexpr double kPartialGrowth = 0.25;

// Runs `body`, a stage of the parent's work, turning a failed allocation into words that name
// what did not fit.
template <typename Body>
auto inMemory(const std::string& what, Body&& body) -> decltype(body()) {
    try {
        return body();
    } catch (const std::bad_alloc&) {
        throw Bad("out of memory " + what + " (" +
                  std::to_string(util::mebibytes(util::residentBytes())) + " MiB in use)");
    }
}

// Thrown where the skeleton does not stand for the file: it is read whole instead.
struct Unsplittable : Bad {
    using Bad::Bad;
};

// The peak of this process's and its workers' resident memory added up, while it waits.
class TreeMemory {
  public:
    explicit TreeMemory(const util::WorkerPool& pool) : pool_(pool) {}
    void sample(uint64_t& stagePeak, bool now = false) {
        const auto at = Clock::now();
        if (!now && at - last_ < kSampleEvery) return;
        last_ = at;
        stagePeak = std::max(stagePeak, util::residentBytes() + pool_.residentBytes());
    }

  private:
    const util::WorkerPool& pool_;
    Clock::time_point last_{};
};

void addFigures(CadStageFigures& stages, const WorkerFigures& f) {
    stages.parseMs += f.parseMs;
    stages.transferMs += f.transferMs;
    stages.healingMs += f.healingMs;
    stages.piecesHealed += f.healed;
    stages.meshMs += f.meshMs;
    stages.buildMs += f.buildMs;
    stages.levelsMs += f.levelsMs;
    stages.encodeMs += f.encodeMs;
    stages.peakWorkerBytes = std::max(stages.peakWorkerBytes, f.peakBytes);
}

[[noreturn]] void cancelled(util::WorkerPool& pool) {
    pool.killAll();
    throw Bad("cancelled");
}

// A split STEP file's pieces read by the pool, put together as they come.
class SplitLoad {
  public:
    SplitLoad(const step::StepSplit& split, const CadOptions& options, uint32_t levels,
              const CadProgress& progress, const std::atomic<bool>* cancel,
              const CadPartialSink& partial, CadStageFigures& stages, Clock::time_point start)
        : split_(split), options_(options), levels_(levels), progress_(progress), cancel_(cancel),
          partial_(partial), stages_(stages), start_(start),
          pool_(loadWorkerProgram(), {}, workerCount(options)), memory_(pool_),
          inFlight_(pool_.size(), -1), sentAt_(pool_.size()) {
        stages_.workers = pool_.size();
    }

    CadLoadResult run(const std::string& stem) {
        const auto skeletonStart = Clock::now();
        const SkeletonAnswer skeleton = readSkeleton();
        try {
            inMemory("laying out the assembly",
                     [&] { assembly_.emplace(skeleton, split_.pieces(), stem); });
        } catch (const Bad& e) {
            throw Unsplittable(e.what());
        }
        stages_.skeletonMs = msSince(skeletonStart);
        deflection_ =
            options_.deflection > 0.0 ? options_.deflection : assembly_->automaticDeflection();
        publish(true);
        queuePieces();
        const auto piecesStart = Clock::now();
        readPieces();
        stages_.piecesMs = msSince(piecesStart);
        const auto assemblyStart = Clock::now();
        if (progress_) progress_("building", 0.0);
        memory_.sample(stages_.peakAssemblyBytes, true);
        CadLoadResult result =
            inMemory("putting the solids together", [&] { return assembly_->finish(levels_); });
        stages_.assemblyMs = msSince(assemblyStart);
        memory_.sample(stages_.peakAssemblyBytes, true);
        result.deflection = deflection_;
        return result;
    }

  private:
    SkeletonAnswer readSkeleton() {
        if (progress_) progress_("reading the assembly structure", 0.0);
        SkeletonJob job;
        job.text = split_.skeleton();
        for (const step::Piece& piece : split_.pieces()) job.dummySets.push_back(piece.dummySet);
        pool_.send(0, uint32_t(JobKind::Skeleton), encode(job));
        for (;;) {
            const Event event = waitEvent(stages_.peakSkeletonBytes);
            if (event.kind == Event::Kind::Ended && event.worker == 0)
                throw Unsplittable("the worker reading its assembly structure was " + event.reason);
            if (event.kind != Event::Kind::Message || event.worker != 0) continue;
            if (event.frame.kind == uint32_t(AnswerKind::Skeleton))
                return decodeSkeletonAnswer(event.frame.bytes);
            if (event.frame.kind == uint32_t(AnswerKind::Failed) ||
                event.frame.kind == uint32_t(AnswerKind::Stopped))
                throw Unsplittable(event.frame.bytes);
        }
    }

    Event waitEvent(uint64_t& stagePeak) {
        for (;;) {
            if (cancel_ && *cancel_) cancelled(pool_);
            memory_.sample(stagePeak);
            // Solids held back by the pace go out once their time has come, though no piece
            // answers meanwhile: a long last piece would hide them for as long as it takes.
            if (assembly_) publish(false);
            Event event = pool_.wait(kPoll);
            if (event.kind != Event::Kind::Timeout) return event;
        }
    }

    // Largest first, so that no large piece starts last; but the first worker's first piece is
    // the smallest, so that a solid shows within moments.
    void queuePieces() {
        for (uint32_t p = 0; p < split_.pieces().size(); ++p)
            if (assembly_->used(p)) queue_.push_back(p);
        std::stable_sort(queue_.begin(), queue_.end(), [&](uint32_t a, uint32_t b) {
            return split_.pieces()[a].bytes > split_.pieces()[b].bytes;
        });
        stages_.pieces = uint32_t(queue_.size());
        left_ = queue_.size();
    }

    void send(unsigned worker) {
        if (queue_.empty() || inFlight_[worker] >= 0 || !pool_.running(worker)) return;
        const bool quick = worker == 0 && !sentAny_;
        const uint32_t piece = quick ? queue_.back() : queue_.front();
        quick ? queue_.pop_back() : queue_.pop_front();
        sentAny_ = true;
        PieceJob job;
        job.piece = piece;
        job.text = split_.pieceText(piece);
        job.objectFaces = split_.pieces()[piece].layout.objectFaces;
        job.mesh = {deflection_, options_.angularDeflection, levels_, options_.healing,
                    options_.maxTriangles};
        inFlight_[worker] = piece;
        sentAt_[worker] = Clock::now();
        pool_.send(worker, uint32_t(JobKind::Piece), encode(job));
    }

    void readPieces() {
        while (left_ > 0) {
            for (unsigned w = 0; w < pool_.size(); ++w) send(w);
            const Event event = waitEvent(stages_.peakPiecesBytes);
            if (event.kind == Event::Kind::Ended)
                ended(event.worker, event.reason);
            else if (event.kind == Event::Kind::Message)
                answered(event.worker, event.frame);
        }
        if (answered_ == 0 && stages_.piecesLost > 0)
            throw Bad("no solid could be read (" + firstLoss_ + ")");
    }

    void answered(unsigned worker, const util::Frame& frame) {
        const int64_t piece = inFlight_[worker];
        if (piece < 0) return; // nothing asked of it: not an answer to take
        if (frame.kind == uint32_t(AnswerKind::Stopped)) {
            pool_.killAll();
            throw Bad(frame.bytes);
        }
        inFlight_[worker] = -1;
        --left_;
        if (frame.kind != uint32_t(AnswerKind::Piece)) {
            lose(uint32_t(piece), frame.bytes);
            return;
        }
        PieceAnswer answer;
        try {
            answer = decodePieceAnswer(frame.bytes);
        } catch (const std::runtime_error& e) {
            lose(uint32_t(piece), std::string("its answer was damaged (") + e.what() + ")");
            return;
        }
        stages_.largestPieceMs = std::max(stages_.largestPieceMs, msSince(sentAt_[worker]));
        addFigures(stages_, answer.figures);
        triangles_ += countTriangles(answer);
        if (triangles_ > options_.maxTriangles) {
            pool_.killAll();
            throw Bad(triangleLimitReason(estimate(), options_.maxTriangles, deflection_));
        }
        inMemory("putting the solids together", [&] { assembly_->add(answer); });
        if (answered_++ == 0) stages_.firstSolidMs = msSince(start_);
        report();
        publish(false);
    }

    void ended(unsigned worker, const std::string& reason) {
        const int64_t piece = inFlight_[worker];
        inFlight_[worker] = -1;
        if (piece >= 0) {
            --left_;
            lose(uint32_t(piece), "the worker reading it was " + reason);
        }
        if (left_ > 0 && !queue_.empty()) {
            ++stages_.workerRestarts;
            pool_.restart(worker);
        }
    }

    void lose(uint32_t piece, const std::string& why) {
        if (firstLoss_.empty()) firstLoss_ = why;
        ++stages_.piecesLost;
        assembly_->lose(piece, why);
        report();
        publish(false);
    }

    static uint64_t countTriangles(const PieceAnswer& answer) {
        uint64_t triangles = 0;
        for (const Geometry& g : answer.mesh.geometries) triangles += g.triangleCount;
        return triangles;
    }

    // The whole's triangles at the rate of the pieces' bytes read so far.
    uint64_t estimate() const {
        uint64_t total = 0;
        for (const step::Piece& p : split_.pieces()) total += p.bytes;
        const double done = std::max<double>(1.0, double(assembly_->bytesDone()));
        return uint64_t(double(triangles_) * std::max(1.0, double(total) / done));
    }

    void report() {
        if (!progress_ || stages_.pieces == 0) return;
        progress_("loading solids", double(stages_.pieces - left_) / double(stages_.pieces));
    }

    // A partial scene for the viewer, when it has one and enough is new.
    void publish(bool force) {
        if (!partial_) return;
        const auto now = Clock::now();
        const bool grown =
            double(answered_ + stages_.piecesLost) >= double(published_) * (1.0 + kPartialGrowth);
        const bool due = now - lastPublished_ >= kPartialEvery ||
                         (now - lastPublished_ >= kPartialSoonest && grown) ||
                         (answered_ == 1 && published_ == 0);
        if (!force && !(due && answered_ + stages_.piecesLost > published_)) return;
        lastPublished_ = now;
        published_ = answered_ + stages_.piecesLost;
        partial_(assembly_->partial());
    }

    const step::StepSplit& split_;
    const CadOptions& options_;
    uint32_t levels_;
    const CadProgress& progress_;
    const std::atomic<bool>* cancel_;
    const CadPartialSink& partial_;
    CadStageFigures& stages_;
    Clock::time_point start_;
    util::WorkerPool pool_;
    TreeMemory memory_;
    std::optional<CadAssembly> assembly_;
    double deflection_ = 0.0;
    std::deque<uint32_t> queue_;
    std::vector<int64_t> inFlight_; // by worker: its piece, or -1
    std::vector<Clock::time_point> sentAt_;
    size_t left_ = 0;
    uint32_t answered_ = 0, published_ = 0;
    bool sentAny_ = false;
    uint64_t triangles_ = 0;
    std::string firstLoss_;
    Clock::time_point lastPublished_{};
};

} // namespace
} // namespace scene::cad

namespace scene::cad {
namespace {

// A file read whole by one worker, its progress passed on.
CadLoadResult loadWhole(const std::string& path, const CadOptions& options, uint32_t levels,
                        const CadProgress& progress, const std::atomic<bool>* cancel,
                        CadStageFigures& stages) {
    util::WorkerPool pool(loadWorkerProgram(), {}, 1);
    TreeMemory memory(pool);
    stages.workers = 1;
    stages.pieces = 1;
    WholeFileJob job{path, options, levels};
    pool.send(0, uint32_t(JobKind::WholeFile), encode(job));
    const auto start = Clock::now();
    for (;;) {
        if (cancel && *cancel) cancelled(pool);
        memory.sample(stages.peakPiecesBytes);
        const Event event = pool.wait(kPoll);
        if (event.kind == Event::Kind::Ended)
            throw Bad("the worker reading it was " + event.reason +
                      " (the file is damaged or holds something its reader does not handle)");
        if (event.kind != Event::Kind::Message) continue;
        const uint32_t kind = event.frame.kind;
        if (kind == uint32_t(AnswerKind::Progress)) {
            const auto [stage, fraction] = decodeProgress(event.frame.bytes);
            if (progress) progress(stage.c_str(), fraction);
            continue;
        }
        if (kind != uint32_t(AnswerKind::WholeFile)) throw ModelError(event.frame.bytes);
        WholeFileAnswer answer = decodeWholeFileAnswer(event.frame.bytes);
        stages.piecesMs = stages.largestPieceMs = msSince(start);
        addFigures(stages, answer.figures);
        std::vector<BrepShapes::Stored> stored(answer.brep.size());
        for (size_t g = 0; g < stored.size(); ++g) {
            stored[g].present = !answer.brep[g].empty();
            stored[g].faces = stored[g].present ? encodedFaceCount(answer.brep[g]) : 0;
            stored[g].bytes = std::move(answer.brep[g]);
        }
        answer.result.scene.brep = std::make_shared<const BrepShapes>(std::move(stored));
        return std::move(answer.result);
    }
}

} // namespace

std::string loadWorkerProgram() {
    if (const char* set = std::getenv("IDVIEW_LOAD_WORKER"); set && *set) return set;
    const fs::path self = util::programDir();
    const fs::path installed = util::installedHelperDir();
    for (const fs::path& folder : {self, installed, fs::path(IDVIEW_BINARY_DIR)}) {
        const fs::path program = folder / "idview-load-worker";
        if (!folder.empty() && access(program.c_str(), X_OK) == 0) return program.string();
    }
    throw Bad("idview-load-worker, which reads CAD files, is neither beside idview in " +
              self.string() + ", nor in " + installed.string() + ", nor in " + IDVIEW_BINARY_DIR +
              " (set IDVIEW_LOAD_WORKER to it)");
}

unsigned workerCount(const CadOptions& options) {
    return options.workers > 0 ? options.workers
                               : std::max(1u, std::thread::hardware_concurrency());
}

namespace {

CadLoadResult loadSplitOrWhole(const std::string& path, const CadOptions& options,
                               const CadProgress& progress, uint32_t levels,
                               const std::atomic<bool>* cancel, const CadPartialSink& partial) {
    const auto start = Clock::now();
    const Format format = checkedFormat(path, options, levels);
    CadStageFigures stages;
    // Said at once, before any worker starts, so that a load shows it began.
    if (progress) progress("reading", 0.0);
    if (format == Format::Step) {
        std::optional<step::StepSplit> split;
        try {
            inMemory("indexing the file's entities", [&] { split.emplace(path); });
        } catch (const Bad&) {
            throw;
        } catch (const std::runtime_error& e) {
            // The mapping names the file; the loader puts its name in front already.
            const std::string said = e.what(), named = path + ": ";
            throw Bad(said.rfind(named, 0) == 0 ? said.substr(named.size()) : said);
        }
        stages.lexMs = split->lexMs();
        stages.splitMs = split->splitMs();
        stages.peakLexBytes = util::residentBytes();
        if (!split->notSplit()) {
            try {
                SplitLoad load(*split, options, levels, progress, cancel, partial, stages, start);
                CadLoadResult result = load.run(fs::path(path).stem().string());
                stages.split = true;
                result.readMs = stages.lexMs + stages.splitMs + stages.skeletonMs;
                result.tessellationMs = stages.piecesMs;
                result.levelsMs = stages.levelsMs;
                result.stages = stages;
                return result;
            } catch (const Unsplittable& e) {
                CadStageFigures lexed;
                lexed.lexMs = stages.lexMs;
                lexed.splitMs = stages.splitMs;
                lexed.peakLexBytes = stages.peakLexBytes;
                lexed.notSplit = e.what();
                stages = lexed;
            }
        } else {
            stages.notSplit = split->notSplit()->reason;
        }
    }
    checkWholeFileSize(path);
    CadLoadResult result = loadWhole(path, options, levels, progress, cancel, stages);
    stages.firstSolidMs = msSince(start);
    result.stages = stages;
    return result;
}

} // namespace

CadLoadResult loadWithWorkers(const std::string& path, const CadOptions& options,
                              const CadProgress& progress, uint32_t levels,
                              const std::atomic<bool>* cancel, const CadPartialSink& partial) {
    try {
        return loadSplitOrWhole(path, options, progress, levels, cancel, partial);
    } catch (const ModelError&) {
        throw;
    } catch (const Bad&) {
        throw;
    } catch (const std::runtime_error& e) { // a worker that cannot start, a damaged answer
        throw Bad(e.what());
    }
}

} // namespace scene::cad
