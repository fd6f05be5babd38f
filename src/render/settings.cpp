// settings.cpp - the effective pipeline key: what a technique ignores does not split the cache.
#include "render/settings.h"

namespace render {

PipelineKey PipelineKey::effective(bool devicePassthrough) const {
    PipelineKey key = *this;
    const PipelineKey defaults;
    if (!technique->readsSearchBatch()) key.searchBatch = defaults.searchBatch;
    if (!technique->narySearch) key.nsearch = defaults.nsearch;
    key.gsPassthrough =
        technique->stage == LookupStage::Geometry && gsPassthrough && devicePassthrough;
    if (technique->isFloor()) key.hiding = false; // no part IDs: nothing to hide by
    key.taskCulling = key.taskCulling && technique->usesMeshShader();
    key.runOffsets = key.runOffsets && technique->readsPrimitiveId() && mode->indirect;
    if (key.msaa == 1) key.clear = ClearPath::Pass;
    key.overVisibility = key.overVisibility && key.translucent;
    return key;
}

const char* clearPathName(ClearPath path) {
    switch (path) {
    case ClearPath::Pass:
        return "pass";
    case ClearPath::Compute:
        return "compute";
    default:
        return "auto";
    }
}

std::optional<ClearPath> findClearPath(std::string_view name) {
    for (ClearPath path : {ClearPath::Auto, ClearPath::Pass, ClearPath::Compute})
        if (name == clearPathName(path)) return path;
    return std::nullopt;
}

} // namespace render
