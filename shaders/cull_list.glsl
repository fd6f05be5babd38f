// cull_list.glsl - what every step of cull.comp shares (shared_cull.h has the steps): its
// push constants, the workgroup's scratch, sums over a workgroup and over the workgroups
// before it, the state words, and the counters only the last workgroup can write.
#ifndef IDVIEW_CULL_LIST_GLSL
#define IDVIEW_CULL_LIST_GLSL

#include "cull.glsl"

layout(local_size_x = CULL_GROUP_SIZE) in;

layout(push_constant, std430) uniform CullBlock {
    CullPush cull;
};

shared uint counts[CULL_GROUP_SIZE];
shared uint levelCounts[LOD_MAX_LEVELS];

FrameData cullFrame() {
    return FrameRef(cull.frameAddress).frame;
}

UintsRef cullState() {
    return UintsRef(cull.stateAddress);
}

DrawData listDraw(uint i) {
    return DrawsRef(cull.drawsAddress).draws[i];
}

DrawCull listDrawCull(uint i) {
    return DrawCullsRef(cull.cullAddress).draws[i];
}

uint drawOfPair(uint pair) {
    return UintsRef(cull.pairsAddress).values[pair];
}

// What this pass's steps do: its phase's row of shared_cull.h's table (CULL_PASS_*).
uint passBits() {
    return CULL_PHASES[cull.phase].pass;
}

bool lateStep() {
    return (passBits() & CULL_PASS_LATE) != 0u;
}

bool earlyStep() {
    return (passBits() & CULL_PASS_EARLY) != 0u;
}

bool meshDraws() {
    return (cull.flags & CULL_MESH_DRAWS) != 0u;
}

bool clusterRuns() {
    return (cull.flags & CULL_CLUSTER_RUNS) != 0u;
}

// Runs: the state word of a (draw, cluster) pair (CULL_PAIR_*).
uint pairWord(uint pair) {
    return cull.drawCount + pair;
}

// Runs: whether the cluster of `pair` passed the last test that made history.
bool hadHistory(uint pair) {
    return UintsRef(cull.pairHistoryAddress).values[pair] != 0u;
}

// Runs: the history ends of this pass's slot (shared_cull.h's History), a word per object.
UintsRef historyEnds() {
    return UintsRef(cull.historyEndsAddress);
}

// Sum of counts[0 .. n) over the workgroup, left in counts[0]. n is a power of two.
void reduce(uint lane, uint n) {
    for (uint stride = n >> 1; stride > 0u; stride >>= 1) {
        barrier();
        if (lane < stride) counts[lane] += counts[lane + stride];
    }
    barrier();
}

// Every lane's `value` added up, returned to every lane (the workgroup calls it together).
uint workgroupSum(uint lane, uint value) {
    barrier(); // earlier readers of counts[] are done
    counts[lane] = value;
    reduce(lane, CULL_GROUP_SIZE);
    uint total = counts[0];
    barrier();
    return total;
}

// What the workgroups before this one counted (decide, count or runs count wrote it): where
// this workgroup's commands start.
uint countedBefore(uint lane) {
    UintsRef groups = UintsRef(cull.groupsAddress);
    uint before = 0u;
    for (uint g = lane; g < gl_WorkGroupID.x; g += CULL_GROUP_SIZE) before += groups.values[g];
    return workgroupSum(lane, before);
}

// Inclusive prefix of the flags over the workgroup (Hillis-Steele), left in counts[]; the
// workgroup's total is counts[CULL_GROUP_SIZE - 1].
void inclusivePrefix(uint lane, bool flag) {
    barrier();
    counts[lane] = flag ? 1u : 0u;
    barrier();
    for (uint stride = 1u; stride < CULL_GROUP_SIZE; stride <<= 1) {
        uint add = lane >= stride ? counts[lane - stride] : 0u;
        barrier();
        counts[lane] += add;
        barrier();
    }
}

// Adds each lane's `triangles`, of a draw at `level`, to the frame's count of that level.
void countLevels(uint lane, uint level, uint triangles) {
    if (lane < LOD_MAX_LEVELS) levelCounts[lane] = 0u;
    barrier();
    if (triangles != 0u) atomicAdd(levelCounts[min(level, LOD_MAX_LEVELS - 1u)], triangles);
    barrier();
    if (lane < LOD_MAX_LEVELS && levelCounts[lane] != 0u)
        atomicAdd(CullStatsRef(cull.statsAddress).stats.levelTriangles[lane], levelCounts[lane]);
}

// The last workgroup of a compaction knows the pass's total: the indirect draw count.
void finishList(uint total) {
    CullStatsRef(cull.statsAddress).stats.draws[lateStep() ? 1 : 0] = total;
}

#endif
