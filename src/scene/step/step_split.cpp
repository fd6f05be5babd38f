// step_split.cpp - placeholder until the lexer lands: every file is read whole.
#include "scene/step/step_split.h"

namespace scene::step {

uint64_t RepLayout::faces() const {
    uint64_t n = 0;
    for (uint32_t f : objectFaces) n += f;
    return n;
}

struct StepSplit::Impl {
    std::optional<NotSplit> notSplit;
    std::vector<Piece> pieces;
};

StepSplit::StepSplit(const std::string&) : impl_(std::make_unique<Impl>()) {
    impl_->notSplit = NotSplit{"the splitter is not built yet"};
}
StepSplit::~StepSplit() = default;
const std::optional<NotSplit>& StepSplit::notSplit() const {
    return impl_->notSplit;
}
const std::vector<Piece>& StepSplit::pieces() const {
    return impl_->pieces;
}
std::string StepSplit::skeleton() const {
    return {};
}
std::string StepSplit::pieceText(size_t) const {
    return {};
}
uint64_t StepSplit::entities() const {
    return 0;
}
uint64_t StepSplit::bytes() const {
    return 0;
}
double StepSplit::lexMs() const {
    return 0;
}
double StepSplit::splitMs() const {
    return 0;
}

} // namespace scene::step
