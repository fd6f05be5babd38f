#version 460
// census.comp - the visibility census's two steps (shared_census.h): counting a view's ID
// image into per-part counters, and folding those into the totals.
// Counting: neighbouring pixels mostly show one part, so the invocations of a subgroup first
// agree on their distinct parts (a loop that retires one part per turn, as part_set.comp) and
// one invocation per part adds the number that showed it: a part covering the whole image
// costs one atomic per subgroup, not one per pixel.
#extension GL_KHR_shader_subgroup_ballot : require

#include "buffers.glsl"

layout(local_size_x = ID_PASS_TILE, local_size_y = ID_PASS_TILE) in;

layout(set = 0, binding = 0, r32ui) uniform readonly uimage2D ids;

layout(push_constant, std430) uniform CensusBlock {
    CensusPush census;
};

void count(uint id) {
    bool pending = id < census.parts;
    while (pending) {
        const uint part = subgroupBroadcastFirst(id);
        if (id != part) continue;
        pending = false;
        // The active invocations are now those showing `part`.
        const uint pixels = subgroupBallotBitCount(subgroupBallot(true));
        if (subgroupElect()) atomicAdd(UintsRef(census.viewAddress).values[part], pixels);
    }
}

void fold(uint part) {
    if (part >= census.parts) return;
    UintsRef view = UintsRef(census.viewAddress);
    const uint pixels = view.values[part];
    if (pixels == 0u) return;
    view.values[part] = 0u;
    CensusTotalsRef totals = CensusTotalsRef(census.totalsAddress);
    totals.parts[part].pixels += uint64_t(pixels);
    totals.parts[part].views += 1u;
    totals.parts[part].largest = max(totals.parts[part].largest, pixels);
}

void main() {
    if (census.step == CENSUS_FOLD) {
        // One invocation per part, the workgroups numbered row by row.
        const uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
        fold(group * ID_PASS_TILE * ID_PASS_TILE + gl_LocalInvocationIndex);
        return;
    }
    const uvec2 p = gl_GlobalInvocationID.xy;
    const bool inside = all(lessThan(p, census.extent));
    count(inside ? imageLoad(ids, ivec2(p)).r : BACKGROUND_ID);
}
