// step_write.cpp - the skeleton's and the pieces' texts (step_write.h).
#include "scene/step/step_write.h"

#include <array>
#include <unordered_map>

#include "scene/step/step_record.h"
#include "scene/step/step_types.h"

namespace scene::step {
namespace {

constexpr std::string_view kData = "DATA;\n";
constexpr std::string_view kTail = "ENDSEC;\nEND-ISO-10303-21;\n";

std::string refList(const StepIndex& index, const std::vector<uint32_t>& records) {
    std::string list;
    for (uint32_t r : records) {
        if (!list.empty()) list += ',';
        list += entityName(index.idOf(r));
    }
    return list;
}

// The records the skeleton keeps: the closure from the roots of everything but the dropped
// records, the styled items on geometry and the geometry itself (the points, directions and
// placements a kept record shares with it excepted).
std::vector<bool> skeletonRecords(const StepIndex& index, const Plan& plan) {
    auto skipped = [&](uint32_t r) {
        return r == kNoRecord || plan.marked(r, kDropped | kStyledOnGeometry) ||
               (plan.marked(r, kInGeometry) && !(plan.flagsOf(index, r) & kShareable));
    };
    std::vector<bool> kept(index.size(), false);
    std::vector<uint32_t> stack;
    for (uint32_t root = 0; root < index.size(); ++root) {
        if (plan.marked(root, kReferenced) || skipped(root)) continue;
        kept[root] = true;
        stack.push_back(root);
        while (!stack.empty()) {
            const uint32_t r = stack.back();
            stack.pop_back();
            for (uint32_t next : index.refsOf(r))
                if (!skipped(next) && !kept[next]) {
                    kept[next] = true;
                    stack.push_back(next);
                }
        }
    }
    return kept;
}

// "#id=TYPE(name,(items),context);" for a representation whose items change.
std::string representation(const StepIndex& index, uint32_t record, const std::string& items) {
    const std::vector<Parameter> parameters = parametersOf(index, record);
    return entityName(index.idOf(record)) + "=" + index.types.name(index.type[record]) + "(" +
           std::string(parameters[0].text) + ",(" + items + ")," + std::string(parameters[2].text) +
           ");\n";
}

// "#id=STYLED_ITEM(name,(styles),#set);": an instance's style moved from the solid to the
// set that stands for it (an OVER_RIDING_STYLED_ITEM loses the style it overrode, which is
// in the piece).
std::string instanceStyle(const StepIndex& index, uint32_t record, uint64_t set) {
    const std::vector<Parameter> parameters = parametersOf(index, record);
    return entityName(index.idOf(record)) + "=STYLED_ITEM(" + std::string(parameters[0].text) +
           "," + std::string(parameters[1].text) + "," + entityName(set) + ");\n";
}

std::string point(uint64_t id, const std::array<std::string, 3>& coordinates, bool any) {
    std::string text = entityName(id) + "=CARTESIAN_POINT('',(";
    for (size_t axis = 0; axis < 3; ++axis)
        text += std::string(axis ? "," : "") + (any ? std::string(coordinates[axis]) : "0.");
    return text + "));\n";
}

} // namespace

uint64_t dummySetId(const StepIndex& index, uint32_t rep) {
    return index.maxId + 1 + 3 * uint64_t(rep) + 2;
}

std::string skeletonText(const StepIndex& index, const Plan& plan,
                         const std::vector<PieceFacts>& pieces) {
    const std::vector<bool> kept = skeletonRecords(index, plan);
    std::unordered_map<uint32_t, uint32_t> repIndex;
    for (uint32_t k = 0; k < plan.reps.size(); ++k) repIndex.emplace(plan.reps[k].record, k);
    std::string text(index.text.substr(0, index.dataBegin));
    text += kData;
    for (uint32_t r = 0; r < index.size(); ++r) {
        if (!kept[r]) continue;
        if (plan.marked(r, kGeometryRep)) {
            const uint32_t k = repIndex.at(r);
            const std::string others = refList(index, plan.reps[k].otherItems);
            text += representation(
                index, r, others + (others.empty() ? "" : ",") + entityName(dummySetId(index, k)));
        } else if (plan.marked(r, kFiltered)) {
            text += representation(index, r, refList(index, plan.keptItems.at(r)));
        } else if (plan.marked(r, kInstanceStyle)) {
            text += instanceStyle(index, r, dummySetId(index, plan.repOfInstanceStyle.at(r)));
        } else {
            text.append(index.textOf(r)).push_back('\n');
        }
    }
    for (uint32_t k = 0; k < plan.reps.size(); ++k) {
        const uint64_t set = dummySetId(index, k);
        const VertexBox& box = pieces[k].box;
        text += point(set - 2, box.lowText, box.any) + point(set - 1, box.highText, box.any);
        text += entityName(set) + "=GEOMETRIC_SET('',(" + entityName(set - 2) + "," +
                entityName(set - 1) + "));\n";
    }
    return text += kTail;
}

std::string pieceChain(const StepIndex& index, const Plan& plan, uint32_t rep,
                       const std::vector<uint32_t>& styled) {
    const GeometryRep& geometry = plan.reps[rep];
    const uint64_t id = index.maxId + 1;
    const std::string name = "'piece of #" + std::to_string(index.idOf(geometry.record)) + "'";
    std::string text;
    text += entityName(id) + "=APPLICATION_CONTEXT('');\n";
    text += entityName(id + 1) + "=PRODUCT_CONTEXT(''," + entityName(id) + ",'mechanical');\n";
    text += entityName(id + 2) + "=PRODUCT(" + name + "," + name + ",'',(" + entityName(id + 1) +
            "));\n";
    text +=
        entityName(id + 3) + "=PRODUCT_DEFINITION_FORMATION('',''," + entityName(id + 2) + ");\n";
    text += entityName(id + 4) + "=PRODUCT_DEFINITION_CONTEXT('part definition'," + entityName(id) +
            ",'design');\n";
    text += entityName(id + 5) + "=PRODUCT_DEFINITION('design',''," + entityName(id + 3) + "," +
            entityName(id + 4) + ");\n";
    text +=
        entityName(id + 6) + "=PRODUCT_DEFINITION_SHAPE(''," + "''," + entityName(id + 5) + ");\n";
    text += entityName(id + 7) + "=SHAPE_DEFINITION_REPRESENTATION(" + entityName(id + 6) + "," +
            entityName(index.idOf(geometry.record)) + ");\n";
    if (!styled.empty())
        text += entityName(id + 8) +
                "=MECHANICAL_DESIGN_GEOMETRIC_PRESENTATION_REPRESENTATION('',(" +
                refList(index, styled) + ")," + entityName(index.idOf(geometry.context)) + ");\n";
    return text;
}

uint64_t pieceFrameBytes(const StepIndex& index) {
    return index.dataBegin + kData.size() + kTail.size();
}

std::string pieceText(const StepIndex& index, const std::vector<uint32_t>& records,
                      const std::string& chain) {
    uint64_t bytes = pieceFrameBytes(index) + chain.size();
    for (uint32_t r : records) bytes += index.length[r] + 1;
    std::string text;
    text.reserve(bytes);
    text.append(index.text.substr(0, index.dataBegin)).append(kData);
    for (uint32_t r : records) text.append(index.textOf(r)).push_back('\n');
    return text.append(chain).append(kTail);
}

} // namespace scene::step
