// step_plan.cpp - makePlan (step_plan.h): the geometry representations and their solid
// items, the solids' closure, the styled items on it, and the records the skeleton drops
// because they use that geometry (and, upward, whatever uses a dropped record).
#include "scene/step/step_plan.h"

#include <algorithm>

#include "scene/step/step_record.h"
#include "scene/step/step_types.h"

namespace scene::step {
namespace {

class Planner {
  public:
    Planner(const StepIndex& index, Plan& plan) : x_(index), p_(plan) {}

    void run() {
        p_.flags = typeFlags(x_.types);
        p_.marks.assign(x_.size(), 0);
        findGeometryReps();
        if (p_.reps.empty()) refuse("no solids to split");
        checkSolidUsers();
        markGeometry();
        findStyledItems();
        for (uint32_t r = 0; r < x_.size(); ++r)
            if (candidate(r) && !p_.marked(r, kEntered)) dropFrom(r);
        checkGeometryReps();
    }

  private:
    [[noreturn]] static void refuse(const std::string& reason) { throw Refused{reason}; }
    uint32_t flags(uint32_t r) const { return p_.flagsOf(x_, r); }
    void mark(uint32_t r, uint16_t m) { p_.marks[r] |= m; }

    // A record the skeleton would lose along with the geometry: a part of a solid (points,
    // directions and placements excepted: a placement of the assembly may share them), a
    // styled item that goes to the pieces, or a record already dropped.
    bool usesGeometry(uint32_t r) const {
        if (r == kNoRecord) return false;
        if (p_.marked(r, kInGeometry)) return !(flags(r) & kShareable);
        return p_.marked(r, kStyledOnGeometry | kDropped);
    }
    // Records the drop pass judges; the others are judged by their marks.
    bool candidate(uint32_t r) const {
        return !p_.marked(r, kInGeometry | kStyledOnGeometry | kGeometryRep | kInstanceStyle);
    }

    void findGeometryReps();
    void addGeometryRep(uint32_t record);
    void checkSolidUsers();
    void markGeometry();
    void findStyledItems();
    bool instanceStyle(uint32_t styled, const Parameter& styles, uint32_t item);
    void dropFrom(uint32_t root);
    void decide(uint32_t record);
    void decidePresentation(uint32_t record);
    void checkGeometryReps() const;

    const StepIndex& x_;
    Plan& p_;
};

void Planner::findGeometryReps() {
    for (uint32_t r = 0; r < x_.size(); ++r) {
        if (!(flags(r) & kGeometryRepType)) continue;
        const auto refs = x_.refsOf(r);
        if (std::any_of(refs.begin(), refs.end(), [&](uint32_t item) {
                return item != kNoRecord && (flags(item) & kSolidLike);
            }))
            addGeometryRep(r);
    }
}

// A representation is ('name', (items), #context); its solid items go to its piece.
void Planner::addGeometryRep(uint32_t record) {
    const std::vector<Parameter> parameters = parametersOf(x_, record);
    if (parameters.size() != 3 || !listElements(parameters[1].text) ||
        referenceIn(x_, record, parameters[2]) == kNoRecord)
        refuse(x_.describe(record) + " holds solids but is not ('name', (items), #context)");
    GeometryRep rep;
    rep.record = record;
    rep.context = referenceIn(x_, record, parameters[2]);
    const auto refs = x_.refsOf(record);
    for (uint32_t i = 0; i < parameters[1].refCount; ++i) {
        const uint32_t item = refs[parameters[1].firstRef + i];
        if (item == kNoRecord) continue;
        if (flags(item) & kMappedItem)
            refuse(x_.describe(record) + " holds solids beside a mapped item, " +
                   x_.describe(item));
        (flags(item) & kSolidLike ? rep.solidItems : rep.otherItems).push_back(item);
    }
    const auto index = uint32_t(p_.reps.size());
    for (uint32_t solid : rep.solidItems) {
        const auto [at, added] = p_.repOfSolid.emplace(solid, index);
        if (!added && at->second != index)
            refuse(x_.describe(solid) + " is in two representations, " +
                   x_.describe(p_.reps[at->second].record) + " and " + x_.describe(record));
        mark(solid, kSolidItem);
    }
    mark(record, kGeometryRep);
    p_.reps.push_back(std::move(rep));
}

// A solid-like record may be used by its one representation, styled items and layer
// assignments only: the skeleton could not stand for any other use.
void Planner::checkSolidUsers() {
    for (uint32_t user = 0; user < x_.size(); ++user)
        for (uint32_t used : x_.refsOf(user)) {
            if (used == kNoRecord) continue;
            mark(used, kReferenced);
            if (!(flags(used) & kSolidLike) || p_.marked(user, kGeometryRep) ||
                (flags(user) & (kStyled | kContextStyled | kLayer)))
                continue;
            refuse(x_.describe(used) + " is used by " + x_.describe(user) +
                   ", which the skeleton could not stand for");
        }
    for (uint32_t r = 0; r < x_.size(); ++r)
        if ((flags(r) & kSolidLike) && !p_.marked(r, kSolidItem))
            refuse(x_.describe(r) + " is in no representation");
}

void Planner::markGeometry() {
    std::vector<uint32_t> stack;
    for (const GeometryRep& rep : p_.reps)
        stack.insert(stack.end(), rep.solidItems.begin(), rep.solidItems.end());
    for (uint32_t r : stack) mark(r, kInGeometry);
    while (!stack.empty()) {
        const uint32_t r = stack.back();
        stack.pop_back();
        for (uint32_t next : x_.refsOf(r))
            if (next != kNoRecord && !p_.marked(next, kInGeometry)) {
                mark(next, kInGeometry);
                stack.push_back(next);
            }
    }
}

// STYLED_ITEM('name', (styles), #item, ...): those on geometry follow it into the pieces.
void Planner::findStyledItems() {
    for (uint32_t r = 0; r < x_.size(); ++r) {
        if (!(flags(r) & (kStyled | kContextStyled))) continue;
        const std::vector<Parameter> parameters = parametersOf(x_, r);
        if (parameters.size() < 3) continue;
        const uint32_t item = referenceIn(x_, r, parameters[2]);
        if (item == kNoRecord || !p_.marked(item, kInGeometry)) continue;
        if (flags(r) & kContextStyled)
            refuse("styles that depend on the assembly context (" + x_.describe(r) + " on " +
                   x_.describe(item) + ")");
        if (instanceStyle(r, parameters[1], item)) continue;
        mark(r, kStyledOnGeometry);
        mark(item, kStyledTarget);
        p_.styledByTarget.emplace_back(item, r);
    }
    std::sort(p_.styledByTarget.begin(), p_.styledByTarget.end());
}

// A style by context on the whole of a representation's shape can stand on its set in the
// skeleton; on a part of it (a face, one solid of several) the skeleton could not.
bool Planner::instanceStyle(uint32_t styled, const Parameter& styles, uint32_t item) {
    const auto refs = x_.refsOf(styled);
    bool byContext = false;
    for (uint32_t i = 0; i < styles.refCount; ++i) {
        const uint32_t style = refs[styles.firstRef + i];
        byContext = byContext || (style != kNoRecord && (flags(style) & kStyleByContext));
    }
    if (!byContext) return false;
    const auto rep = p_.repOfSolid.find(item);
    if (rep == p_.repOfSolid.end() || p_.reps[rep->second].solidItems.size() != 1)
        refuse("styles that depend on the assembly context (" + x_.describe(styled) + " on " +
               x_.describe(item) + ", a part of its representation's shape)");
    mark(styled, kInstanceStyle);
    p_.repOfInstanceStyle.emplace(styled, rep->second);
    return true;
}

// Depth first from `root` through candidates, each judged once all it references is.
void Planner::dropFrom(uint32_t root) {
    struct Frame {
        uint32_t record;
        uint32_t next;
    };
    std::vector<Frame> stack{{root, 0}};
    mark(root, kEntered);
    while (!stack.empty()) {
        const uint32_t record = stack.back().record;
        const auto refs = x_.refsOf(record);
        if (stack.back().next < refs.size()) {
            const uint32_t next = refs[stack.back().next++];
            if (next == kNoRecord || !candidate(next) || p_.marked(next, kEntered)) continue;
            mark(next, kEntered); // a cycle back to it finds it undecided: kept
            stack.push_back({next, 0});
            continue;
        }
        decide(record);
        stack.pop_back();
    }
}

void Planner::decide(uint32_t record) {
    if (flags(record) & kPresentation) {
        decidePresentation(record);
    } else {
        const auto refs = x_.refsOf(record);
        if (std::any_of(refs.begin(), refs.end(), [&](uint32_t r) { return usesGeometry(r); }))
            mark(record, kDropped);
    }
    // Representations and what ties them together carry the assembly: losing one would lose
    // a part of the tree without a word.
    if (p_.marked(record, kDropped) && (flags(record) & kRepresentation))
        refuse(x_.describe(record) + " uses the geometry of a solid");
}

// A presentation representation keeps the items that stay, and goes when none is left.
void Planner::decidePresentation(uint32_t record) {
    const std::vector<Parameter> parameters = parametersOf(x_, record);
    const auto refs = x_.refsOf(record);
    std::vector<uint32_t> kept;
    bool lost = false;
    for (uint32_t p = 0; p < parameters.size(); ++p)
        for (uint32_t i = 0; i < parameters[p].refCount; ++i) {
            const uint32_t r = refs[parameters[p].firstRef + i];
            if (p == 1 && usesGeometry(r)) {
                lost = true;
            } else if (p == 1) {
                kept.push_back(r);
            } else if (usesGeometry(r)) { // its context: nothing left to keep
                mark(record, kDropped);
                return;
            }
        }
    if (!lost) return;
    if (kept.empty() || parameters.size() != 3) {
        mark(record, kDropped);
        return;
    }
    mark(record, kFiltered);
    p_.keptItems.emplace(record, std::move(kept));
}

void Planner::checkGeometryReps() const {
    for (const GeometryRep& rep : p_.reps) {
        std::vector<uint32_t> kept = rep.otherItems;
        kept.push_back(rep.context);
        for (uint32_t r : kept)
            if (usesGeometry(r))
                refuse(x_.describe(rep.record) + " holds " + x_.describe(r) +
                       ", which uses the geometry of a solid");
    }
}

} // namespace

std::optional<std::string> makePlan(const StepIndex& index, Plan& plan) {
    return refusalOf(plan, [&] { Planner(index, plan).run(); });
}

} // namespace scene::step
