// step_pieces.cpp - PieceWalker (step_pieces.h): a representation's closure with the styled
// items on it, its vertices' box, and its faces counted per object the way idview's loader
// counts them on Open CASCADE's shape (scene/cad/cad_read.h, splitSolids).
#include "scene/step/step_pieces.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "scene/step/step_record.h"
#include "scene/step/step_types.h"

namespace scene::step {

// Depth first over the closure of the representation's solid items (`inSolids` true), then
// of the rest of it (items, context), then of the styled items met on the way. A solid of
// another representation in there (reached through a style) would give the piece a second
// shape: the file is then read whole.
template <typename Visit>
void PieceWalker::walk(uint32_t repIndex, Visit&& visit) {
    const GeometryRep& rep = p_.reps[repIndex];
    visits_.next();
    std::vector<uint32_t> styled;
    auto drain = [&](bool inSolids) {
        while (!stack_.empty()) {
            const uint32_t r = stack_.back();
            stack_.pop_back();
            if (p_.marked(r, kSolidItem) && p_.repOfSolid.at(r) != repIndex)
                throw std::runtime_error("the piece of " + x_.describe(rep.record) +
                                         " would hold " + x_.describe(r) + " too");
            if (p_.marked(r, kStyledTarget)) {
                auto [first, last] = std::equal_range(
                    p_.styledByTarget.begin(), p_.styledByTarget.end(), std::pair(r, 0u),
                    [](const auto& a, const auto& b) { return a.first < b.first; });
                for (; first != last; ++first) styled.push_back(first->second);
            }
            visit(r, inSolids);
            for (uint32_t next : x_.refsOf(r))
                if (next != kNoRecord && visits_.first(next)) stack_.push_back(next);
        }
    };
    for (uint32_t solid : rep.solidItems)
        if (visits_.first(solid)) stack_.push_back(solid);
    drain(true);
    if (visits_.first(rep.record)) stack_.push_back(rep.record);
    drain(false);
    for (size_t i = 0; i < styled.size(); ++i) // grows while the styles' closures are walked
        if (visits_.first(styled[i])) {
            stack_.push_back(styled[i]);
            drain(false);
        }
}

PieceFacts PieceWalker::facts(uint32_t repIndex) {
    PieceFacts facts;
    facts.layout = layout(p_.reps[repIndex]);
    walk(repIndex, [&](uint32_t r, bool inSolids) {
        facts.recordBytes += x_.length[r] + 1;
        if (const uint32_t flags = p_.flagsOf(x_, r); inSolids && (flags & kBounding))
            addBounds(r, flags, facts.box);
        if (p_.marked(r, kStyledOnGeometry)) facts.styled.push_back(r);
    });
    std::sort(facts.styled.begin(), facts.styled.end());
    return facts;
}

std::vector<uint32_t> PieceWalker::records(uint32_t repIndex) {
    std::vector<uint32_t> records;
    walk(repIndex, [&](uint32_t r, bool) { records.push_back(r); });
    std::sort(records.begin(), records.end());
    return records;
}

// Solids one object each when there are two or more, or one beside faces of no solid (those
// then one more object); else one object with every face.
RepLayout PieceWalker::layout(const GeometryRep& rep) {
    RepLayout layout;
    visits_.next();
    uint32_t freeFaces = 0;
    for (uint32_t item : rep.solidItems) {
        if (p_.flagsOf(x_, item) & kSolid) ++layout.solids;
        if (p_.flagsOf(x_, item) & kSurfaceModel) freeFaces += countFaces(item);
    }
    layout.split = layout.solids >= 2 || (layout.solids >= 1 && freeFaces > 0);
    if (!layout.split) {
        visits_.next();
        uint32_t faces = 0;
        for (uint32_t item : rep.solidItems) faces += countFaces(item);
        layout.objectFaces.push_back(faces);
        return layout;
    }
    for (uint32_t item : rep.solidItems)
        if (p_.flagsOf(x_, item) & kSolid) {
            visits_.next();
            layout.objectFaces.push_back(countFaces(item));
        }
    if (freeFaces > 0) {
        layout.objectFaces.push_back(freeFaces);
        layout.freeFaces = true;
    }
    return layout;
}

// The faces under `item` not yet met in this walk: down through shells and oriented faces
// only (a face's own bounds lead to no other face).
uint32_t PieceWalker::countFaces(uint32_t item) {
    if (!visits_.first(item)) return 0;
    uint32_t faces = 0;
    stack_.assign(1, item);
    while (!stack_.empty()) {
        const uint32_t r = stack_.back();
        stack_.pop_back();
        if (p_.flagsOf(x_, r) & kFace) {
            ++faces;
            continue;
        }
        for (uint32_t next : x_.refsOf(r))
            if (next != kNoRecord && (p_.flagsOf(x_, next) & (kShell | kOrientedFace | kFace)) &&
                visits_.first(next))
                stack_.push_back(next);
    }
    return faces;
}

// VERTEX_POINT('name', #point); EDGE_CURVE('name', #start, #end, #curve, sense) closed on
// CIRCLE('name', #placement, radius) or ELLIPSE('name', #placement, semi-axis 1, semi-axis 2),
// the placement's first reference its location.
void PieceWalker::addBounds(uint32_t record, uint32_t flags, VertexBox& box) const {
    const auto refs = x_.refsOf(record);
    if (flags & kVertexPoint) {
        if (!refs.empty() && refs.back() != kNoRecord) addPoint(refs.back(), 0.0, box);
        return;
    }
    if (refs.size() < 3 || refs[0] != refs[1] || refs[2] == kNoRecord ||
        !(p_.flagsOf(x_, refs[2]) & kConic))
        return;
    addConic(refs[2], box);
}

void PieceWalker::addConic(uint32_t record, VertexBox& box) const {
    const auto refs = x_.refsOf(record);
    const std::vector<Parameter> parameters = parametersOf(x_, record);
    if (refs.empty() || refs[0] == kNoRecord || parameters.size() < 3) return;
    double radius = 0.0;
    for (size_t i = 2; i < parameters.size(); ++i)
        radius = std::max(radius, std::abs(realOf(parameters[i].text).value_or(0.0)));
    const auto location = x_.refsOf(refs[0]);
    if (!location.empty() && location[0] != kNoRecord) addPoint(location[0], radius, box);
}

// CARTESIAN_POINT('name', (x, y, z)), each coordinate widened by `pad`; not a point in
// space (2D, or no point at all): nothing.
void PieceWalker::addPoint(uint32_t point, double pad, VertexBox& box) const {
    if (point == kNoRecord || !(p_.flagsOf(x_, point) & kCartesianPoint)) return;
    const std::vector<Parameter> parameters = parametersOf(x_, point);
    const auto coordinates =
        parameters.size() == 2 ? listElements(parameters[1].text) : std::nullopt;
    if (!coordinates || coordinates->size() != 3) return;
    for (size_t axis = 0; axis < 3; ++axis) {
        const std::string_view text = (*coordinates)[axis];
        const auto value = realOf(text);
        if (!value)
            throw std::runtime_error(x_.describe(point) + " has a coordinate that is not a number");
        const double low = *value - pad, high = *value + pad;
        // The file's own text where the corner is its point, else the number written out.
        auto written = [&](double v) {
            if (pad == 0.0) return std::string(text);
            char number[32];
            std::snprintf(number, sizeof number, "%.17G", v);
            std::string out = number;
            if (out.find_first_of(".E") == std::string::npos) out += '.';
            return out;
        };
        if (!box.any || low < box.low[axis]) box.low[axis] = low, box.lowText[axis] = written(low);
        if (!box.any || high > box.high[axis])
            box.high[axis] = high, box.highText[axis] = written(high);
    }
    box.any = true;
}

} // namespace scene::step
