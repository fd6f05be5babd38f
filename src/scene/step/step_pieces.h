// step_pieces.h - each geometry representation's piece worked out from the plan
// (step_pieces.cpp): the objects idview will make of its shape (RepLayout), the box of its
// vertices, its styled items, and the records its text holds. Internal to the splitter.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "scene/step/step_index.h"
#include "scene/step/step_plan.h"
#include "scene/step/step_split.h"

namespace scene::step {

// Marks of visits that a new walk forgets by taking the next epoch, never by clearing.
class Visits {
  public:
    explicit Visits(size_t records) : stamps_(records, 0) {}
    void next() {
        if (++epoch_ == 0) { // after 2^32 walks: start again from a clean slate
            std::fill(stamps_.begin(), stamps_.end(), 0);
            epoch_ = 1;
        }
    }
    // True the first time `record` is met in this walk.
    bool first(uint32_t record) {
        if (stamps_[record] == epoch_) return false;
        stamps_[record] = epoch_;
        return true;
    }
    uint64_t memoryBytes() const { return stamps_.capacity() * sizeof(uint32_t); }

  private:
    std::vector<uint32_t> stamps_;
    uint32_t epoch_ = 0;
};

// The box of a piece's vertices, with each bound's text as the file writes it, so that the
// skeleton's two points carry the very numbers of the file.
// The box of the points that bound a piece's geometry: its vertices, and the centres of its
// closed circles and ellipses (an edge from a vertex round to itself) widened by their radius,
// as such an edge has one vertex only. Not the radius of an arc between two vertices (an arc
// of screw.step's radius-55 circle spans a millimetre), nor B-spline control points (a face
// trims a small part of a large surface, whose poles lie far out: linkrods.step's would make
// its 5.6 mm box 46 mm). Within a few percent of Open CASCADE's exact box on the samples
// (screw.step: 48.05 against 50.82 mm diagonal, where the box it computes without AddOptimal
// is 103). In the file's numbers: a corner that is a point of the file keeps its own text.
struct VertexBox {
    bool any = false;
    std::array<double, 3> low{}, high{};
    std::array<std::string, 3> lowText{}, highText{};
};

// What the splitter keeps of each piece.
struct PieceFacts {
    RepLayout layout;
    VertexBox box;
    std::vector<uint32_t> styled; // the styled items on its geometry, in file order
    uint64_t recordBytes = 0;     // its records' bytes, one newline after each
};

class PieceWalker {
  public:
    PieceWalker(const StepIndex& index, const Plan& plan)
        : x_(index), p_(plan), visits_(index.size()) {}

    // Throws std::runtime_error where the piece cannot be cut out (another piece's solid in
    // its closure, a vertex whose point is not three numbers).
    PieceFacts facts(uint32_t rep);
    // The piece's records in file order.
    std::vector<uint32_t> records(uint32_t rep);
    uint64_t memoryBytes() const { return visits_.memoryBytes(); }

  private:
    template <typename Visit>
    void walk(uint32_t rep, Visit&& visit);
    RepLayout layout(const GeometryRep& rep);
    uint32_t countFaces(uint32_t item);
    void addBounds(uint32_t record, uint32_t flags, VertexBox& box) const;
    void addConic(uint32_t record, VertexBox& box) const;
    void addPoint(uint32_t point, double pad, VertexBox& box) const;

    const StepIndex& x_;
    const Plan& p_;
    Visits visits_;
    std::vector<uint32_t> stack_;
};

} // namespace scene::step
