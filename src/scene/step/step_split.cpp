// step_split.cpp - StepSplit (step_split.h): the file mapped, lexed (step_lexer.cpp), planned
// (step_plan.cpp) and its pieces worked out (step_pieces.cpp); texts made on demand
// (step_write.cpp).
#include "scene/step/step_split.h"

#include <chrono>
#include <mutex>
#include <numeric>
#include <stdexcept>

#include "scene/step/step_index.h"
#include "scene/step/step_pieces.h"
#include "scene/step/step_plan.h"
#include "scene/step/step_write.h"
#include "util/mapped_file.h"

namespace scene::step {
namespace {

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

} // namespace

uint64_t RepLayout::faces() const {
    return std::accumulate(objectFaces.begin(), objectFaces.end(), uint64_t(0));
}

struct StepSplit::Impl {
    explicit Impl(const std::string& path) : file(path) {}

    util::MappedFile file;
    StepIndex index;
    Plan plan;
    std::optional<PieceWalker> walker;
    std::vector<PieceFacts> facts;
    std::vector<Piece> pieces;
    std::optional<NotSplit> notSplit;
    uint64_t entities = 0;
    uint64_t indexBytes = 0;
    double lexMs = 0.0;
    double splitMs = 0.0;
    mutable std::mutex walking; // pieceText calls share the walker's marks

    void refuse(std::string reason) {
        notSplit = NotSplit{std::move(reason)};
        walker.reset();
        facts.clear();
        pieces.clear();
        plan = Plan();
        index = StepIndex();
    }
    void split();
    void addPieces();
};

void StepSplit::Impl::split() {
    auto start = std::chrono::steady_clock::now();
    std::optional<std::string> refused = lexStep(file.text(), index);
    lexMs = msSince(start);
    entities = index.size();
    if (refused) return refuse(*refused);
    start = std::chrono::steady_clock::now();
    refused = makePlan(index, plan);
    if (refused) return refuse(*refused);
    try {
        addPieces();
    } catch (const std::runtime_error& error) {
        return refuse(error.what());
    }
    splitMs = msSince(start);
    indexBytes = index.memoryBytes() + plan.marks.capacity() * sizeof(uint16_t) +
                 walker->memoryBytes() + plan.styledByTarget.capacity() * 8;
}

void StepSplit::Impl::addPieces() {
    walker.emplace(index, plan);
    for (uint32_t k = 0; k < plan.reps.size(); ++k) {
        PieceFacts piece = walker->facts(k);
        Piece& out = pieces.emplace_back();
        out.rep = index.idOf(plan.reps[k].record);
        out.dummySet = dummySetId(index, k);
        out.layout = piece.layout;
        out.hasBox = piece.box.any;
        out.boxMin = piece.box.low;
        out.boxMax = piece.box.high;
        out.bytes = pieceFrameBytes(index) + piece.recordBytes +
                    pieceChain(index, plan, k, piece.styled).size();
        facts.push_back(std::move(piece));
    }
}

StepSplit::StepSplit(const std::string& path) : impl_(std::make_unique<Impl>(path)) {
    impl_->split();
}

StepSplit::~StepSplit() = default;

const std::optional<NotSplit>& StepSplit::notSplit() const {
    return impl_->notSplit;
}
const std::vector<Piece>& StepSplit::pieces() const {
    return impl_->pieces;
}

std::string StepSplit::skeleton() const {
    if (impl_->notSplit) throw std::logic_error("skeleton of a file not split");
    return skeletonText(impl_->index, impl_->plan, impl_->facts);
}

std::string StepSplit::pieceText(size_t index) const {
    if (index >= impl_->pieces.size()) throw std::out_of_range("no piece " + std::to_string(index));
    const auto k = uint32_t(index);
    std::vector<uint32_t> records;
    {
        const std::lock_guard<std::mutex> lock(impl_->walking);
        records = impl_->walker->records(k);
    }
    return step::pieceText(impl_->index, records,
                           pieceChain(impl_->index, impl_->plan, k, impl_->facts[k].styled));
}

uint64_t StepSplit::entities() const {
    return impl_->entities;
}
uint64_t StepSplit::bytes() const {
    return impl_->file.text().size();
}
uint64_t StepSplit::indexBytes() const {
    return impl_->indexBytes;
}
double StepSplit::lexMs() const {
    return impl_->lexMs;
}
double StepSplit::splitMs() const {
    return impl_->splitMs;
}

} // namespace scene::step
