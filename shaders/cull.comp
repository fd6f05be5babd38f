#version 460
// cull.comp - the draws of one culling pass, written as indirect commands in list order with
// their count (render/culling.h). Step "decide" flags each draw and counts per workgroup;
// step "compact" adds up the counts of the workgroups before its own and writes its draws
// there, so the commands keep the order of the whole list (where two surfaces share a depth,
// the one drawn first wins, as without culling). Between them, draws of several clusters
// whose box passed are tested cluster by cluster (steps "clusters" and "count"): a box around
// a whole object reaches past the occluders in front of it far more often than the boxes of
// its runs of 64 triangles do. Lists of cluster runs have steps of their own (cull_runs.glsl).
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_control_flow_attributes : require

#include "shared.h"
#include "cull.glsl"

layout(local_size_x = CULL_GROUP_SIZE) in;

layout(push_constant, std430) uniform CullBlock {
    CullPush cull;
};

layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer FrameRef {
    FrameData frame;
};
layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer ObjectsRef {
    ObjectData objects[];
};
layout(buffer_reference, std430, buffer_reference_align = 4) readonly buffer DrawsRef {
    DrawData draws[];
};
layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer DrawCullRef {
    DrawCull draws[];
};
layout(buffer_reference, std430, buffer_reference_align = 4) buffer StatsRef {
    CullStats stats;
};
layout(buffer_reference, std430, buffer_reference_align = 16) buffer DispatchesRef {
    CullDispatches dispatches;
};
layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer ClusterBoxesRef {
    CullBox boxes[];
};

shared uint counts[CULL_GROUP_SIZE];
shared uint levelCounts[LOD_MAX_LEVELS];

// Adds each lane's `triangles`, of a draw at `level`, to the frame's count of that level.
void countLevels(uint lane, uint level, uint triangles) {
    if (lane < LOD_MAX_LEVELS) levelCounts[lane] = 0u;
    barrier();
    if (triangles != 0u) atomicAdd(levelCounts[min(level, LOD_MAX_LEVELS - 1u)], triangles);
    barrier();
    if (lane < LOD_MAX_LEVELS && levelCounts[lane] != 0u)
        atomicAdd(StatsRef(cull.statsAddress).stats.levelTriangles[lane], levelCounts[lane]);
}

// Cluster runs: where in the state buffer an object's end of history lies: one more than its
// last pair that passed the last late test (its pairs are consecutive, its draws being so).
uint historyEndWord(uint object) {
    return cull.drawCount + cull.pairCount + object;
}

// Cluster runs: the word that says whether the last frame's late pass ran.
uint lateRanWord() {
    return cull.drawCount + cull.pairCount + cull.objectCount;
}

// The state bits of draw `i` for this pass: the first pass of a frame finds them, the late
// pass reads them back.
uint decide(FrameData frame, uint i) {
    CullWordsRef state = CullWordsRef(cull.stateAddress);
    bool boundsHistory = (frame.flags & FRAME_BOUNDS_HISTORY) != 0u;
    uint bits = 0u;
    // Cluster runs: the late pass finds anew where each object's clusters that passed end.
    if (cull.phase == CULL_PHASE_LATE && (cull.flags & CULL_CLUSTER_RUNS) != 0u) {
        state.words[historyEndWord(DrawsRef(cull.drawsAddress).draws[i].objectIndex)] = 0u;
        if (i == 0u) state.words[lateRanWord()] = 1u;
    }
    if (cull.phase == CULL_PHASE_LATE) {
        bits = state.words[i] &
               (CULL_IN_FRUSTUM | CULL_INSIDE_FRUSTUM | CULL_WAS_VISIBLE | CULL_LISTED_EARLY);
    } else {
        bool passedBefore = (state.words[i] & CULL_PASSED) != 0u;
        DrawData draw = DrawsRef(cull.drawsAddress).draws[i];
        ObjectData object = ObjectsRef(frame.objectsAddress).objects[draw.objectIndex];
        uint firstId = object.uniquePartOffset + draw.firstPart;
        bool hidden = (frame.flags & FRAME_HIDING) != 0u &&
                      allBitsInRange(frame.hiddenAddress, firstId, draw.partCount);
        DrawCull box = DrawCullRef(cull.cullAddress).draws[i];
        // Another level of the object's is drawn: this draw is as good as hidden, and leaves
        // no history of its own.
        if (!lodChosen(frame, object.world, box)) return 0u;
        if (!hidden) {
            BoxView view = viewBox(frame, object.world, box.boxMin, box.boxMax);
            if (!view.outside) bits |= CULL_IN_FRUSTUM;
            if (view.inside) bits |= CULL_INSIDE_FRUSTUM;
        }
        if (cull.phase == CULL_PHASE_EARLY &&
            (boundsHistory ? passedBefore
                           : anyBitInRange(frame.visibleAddress, firstId, box.partsToEnd)))
            bits |= CULL_WAS_VISIBLE;
    }
    bool inFrustum = (bits & CULL_IN_FRUSTUM) != 0u;
    bool wasVisible = (bits & CULL_WAS_VISIBLE) != 0u;
    bool draw = inFrustum;
    if (cull.phase == CULL_PHASE_EARLY) draw = inFrustum && wasVisible;
    // What passed here is tested again cluster by cluster (steps "clusters" and "count"):
    // mesh tasks meshlet by meshlet in the late phase (the task shader tests the others).
    bool mesh = (cull.flags & CULL_MESH_DRAWS) != 0u;
    bool runs = (cull.flags & CULL_CLUSTER_RUNS) != 0u;
    bool byClusters = cull.pairCount != 0u &&
                      (mesh || runs || DrawCullRef(cull.cullAddress).draws[i].clusterCount > 1u);
    if (cull.phase == CULL_PHASE_FRUSTUM && draw && byClusters && !mesh)
        bits |= CULL_NEEDS_CLUSTERS;
    // Mesh tasks and cluster runs go through again when they were drawn early (their
    // meshlets or clusters not drawn then are tested now), and so do the floors' draws, whose
    // test is the history.
    bool retest = (cull.flags & (CULL_MESH_DRAWS | CULL_CLUSTER_RUNS)) != 0u || boundsHistory;
    if (cull.phase == CULL_PHASE_LATE && inFrustum && (!wasVisible || retest)) {
        DrawData d = DrawsRef(cull.drawsAddress).draws[i];
        ObjectData object = ObjectsRef(frame.objectsAddress).objects[d.objectIndex];
        DrawCull box = DrawCullRef(cull.cullAddress).draws[i];
        bool passed = !occluded(frame, viewBox(frame, object.world, box.boxMin, box.boxMax),
                                CULL_DRAW_SPAN);
        if (passed && boundsHistory) bits |= CULL_PASSED;
        if (passed && byClusters) bits |= CULL_NEEDS_CLUSTERS;
        draw = passed && (!wasVisible || (cull.flags & CULL_MESH_DRAWS) != 0u);
    } else if (cull.phase == CULL_PHASE_LATE) {
        draw = false;
    }
    return bits | (draw ? CULL_DRAW_NOW : 0u);
}

// Sum of counts[0 .. n) over the workgroup, left in counts[0]. n is a power of two.
void reduce(uint lane, uint n) {
    for (uint stride = n >> 1; stride > 0u; stride >>= 1) {
        barrier();
        if (lane < stride) counts[lane] += counts[lane + stride];
    }
    barrier();
}

void decideStep(uint lane, uint i) {
    uint bits = 0u;
    if (i < cull.drawCount) {
        bits = decide(FrameRef(cull.frameAddress).frame, i);
        CullWordsRef(cull.stateAddress).words[i] = bits;
    }
    counts[lane] = (bits & CULL_DRAW_NOW) != 0u ? 1u : 0u;
    reduce(lane, CULL_GROUP_SIZE);
    if (lane == 0u) CullWordsRef(cull.groupsAddress).words[gl_WorkGroupID.x] = counts[0];
    // Cluster runs count their clusters instead (runClustersStep).
    if (cull.phase != CULL_PHASE_EARLY || cull.dispatchesAddress == 0ul ||
        (cull.flags & CULL_CLUSTER_RUNS) != 0u)
        return;
    // The draws the late pass will test: in view, and not drawn now, or tested again anyway.
    barrier();
    bool retest = (cull.flags & (CULL_MESH_DRAWS | CULL_CLUSTER_RUNS)) != 0u ||
                  (FrameRef(cull.frameAddress).frame.flags & FRAME_BOUNDS_HISTORY) != 0u;
    counts[lane] = (bits & CULL_IN_FRUSTUM) != 0u && ((bits & CULL_WAS_VISIBLE) == 0u || retest)
                       ? 1u
                       : 0u;
    reduce(lane, CULL_GROUP_SIZE);
    if (lane == 0u && counts[0] != 0u)
        atomicAdd(DispatchesRef(cull.dispatchesAddress).dispatches.lateCandidates, counts[0]);
}

// After the early cull: nothing for the late pass to test leaves its dispatches empty.
void skipLateIfIdle() {
    DispatchesRef d = DispatchesRef(cull.dispatchesAddress);
    if (d.dispatches.lateCandidates != 0u) return;
    for (uint p = 0u; p < CULL_PYRAMID_PASSES; ++p) d.dispatches.pyramid[p].x = 0u;
    d.dispatches.lateCull.x = 0u;
    d.dispatches.lateClusters.x = 0u;
}

// One (draw, cluster) pair: the cluster's box, where its draw waits for its clusters, tested
// as the draw's box was (the frustum; the pyramid too in the late phase). Clusters of hidden
// parts are absent.
void clustersStep(uint pair) {
    if (pair >= cull.pairCount) return;
    uint d = CullWordsRef(cull.pairsAddress).words[pair];
    CullWordsRef state = CullWordsRef(cull.stateAddress);
    uint bits = state.words[d];
    if ((bits & CULL_NEEDS_CLUSTERS) == 0u || (bits & CULL_CLUSTER_PASSED) != 0u) return;
    FrameData frame = FrameRef(cull.frameAddress).frame;
    DrawCull drawCull = DrawCullRef(cull.cullAddress).draws[d];
    CullBox box = ClusterBoxesRef(cull.clusterBoxesAddress)
                      .boxes[drawCull.firstCluster + pair - drawCull.firstPair];
    ObjectData object =
        ObjectsRef(frame.objectsAddress).objects[DrawsRef(cull.drawsAddress).draws[d].objectIndex];
    // unused0: the cluster's part in its geometry.
    if ((frame.flags & FRAME_HIDING) != 0u &&
        allBitsInRange(frame.hiddenAddress, object.uniquePartOffset + box.unused0, 1u))
        return;
    BoxView view = viewBox(frame, object.world, box.boxMin, box.boxMax);
    bool passed = !view.outside &&
                  (cull.phase != CULL_PHASE_LATE || !occluded(frame, view, CULL_DRAW_SPAN));
    if (passed) atomicOr(state.words[d], CULL_CLUSTER_PASSED);
}

// Mesh tasks, late phase: the (draw, meshlet) pairs, 32 to a word of meshlet bits, so each
// word is one draw's. A meshlet of a draw whose box passed is tested against the frustum and
// the pyramid, as the task shader would; the word's bits become what passed, and the late
// bitset (FrameData::lateMeshletWord) what passed and the early pass did not draw, which is
// all the late task shader draws. Testing here, a thread per meshlet, spares the task stage
// a workgroup per 32 meshlets of every draw in view, nearly all of which would draw nothing.
shared uint meshletFound[CULL_GROUP_SIZE / 32u];
shared uint meshletNew[CULL_GROUP_SIZE / 32u];

void meshletsStep(uint lane, uint pair) {
    uint slot = lane >> 5;
    uint bit = 1u << (lane & 31u);
    if ((lane & 31u) == 0u) {
        meshletFound[slot] = 0u;
        meshletNew[slot] = 0u;
    }
    barrier();
    FrameData frame = FrameRef(cull.frameAddress).frame;
    CullWordsRef state = CullWordsRef(cull.stateAddress);
    CullWordsRef meshletBits = CullWordsRef(frame.meshletBitsAddress);
    uint d = 0u;
    uint bits = 0u;
    if (pair < cull.pairCount) {
        d = CullWordsRef(cull.pairsAddress).words[pair];
        bits = state.words[d];
    }
    bool tested = (bits & CULL_NEEDS_CLUSTERS) != 0u;
    if (tested) {
        DrawCull drawCull = DrawCullRef(cull.cullAddress).draws[d];
        uint local = pair - drawCull.meshletBit;
        if (local < drawCull.meshletCount) {
            DrawData draw = DrawsRef(cull.drawsAddress).draws[d];
            ObjectData object = ObjectsRef(frame.objectsAddress).objects[draw.objectIndex];
            CullBox box =
                ClusterBoxesRef(frame.meshletBoxesAddress).boxes[draw.firstElement + local];
            BoxView view = viewBox(frame, object.world, box.boxMin, box.boxMax);
            if (!view.outside && !occluded(frame, view, CULL_MESHLET_SPAN)) {
                atomicOr(meshletFound[slot], bit);
                bool drawnEarly = (bits & CULL_WAS_VISIBLE) != 0u &&
                                  (meshletBits.words[pair >> 5] & bit) != 0u;
                if (!drawnEarly) atomicOr(meshletNew[slot], bit);
            }
        }
    }
    barrier();
    if (tested && (lane & 31u) == 0u) {
        meshletBits.words[pair >> 5] = meshletFound[slot];
        meshletBits.words[frame.lateMeshletWord + (pair >> 5)] = meshletNew[slot];
        uint flags = (meshletFound[slot] != 0u ? CULL_CLUSTER_PASSED : 0u) |
                     (meshletNew[slot] != 0u ? CULL_MESHLETS_NEW : 0u);
        if (flags != 0u) atomicOr(state.words[d], flags);
    }
}

// After the clusters: a draw that waited for them is drawn (and passed) only if one passed;
// mesh tasks are drawn late only with a meshlet the early pass did not draw. Each
// workgroup's draws are counted again for "compact".
void countStep(uint lane, uint i) {
    uint bits = 0u;
    if (i < cull.drawCount) {
        CullWordsRef state = CullWordsRef(cull.stateAddress);
        bits = state.words[i];
        uint before = bits;
        if ((bits & (CULL_NEEDS_CLUSTERS | CULL_CLUSTER_PASSED)) == CULL_NEEDS_CLUSTERS)
            bits &= ~(CULL_DRAW_NOW | CULL_PASSED);
        if ((cull.flags & CULL_MESH_DRAWS) != 0u &&
            (bits & (CULL_NEEDS_CLUSTERS | CULL_MESHLETS_NEW)) == CULL_NEEDS_CLUSTERS)
            bits &= ~CULL_DRAW_NOW;
        if (bits != before) state.words[i] = bits;
    }
    counts[lane] = (bits & CULL_DRAW_NOW) != 0u ? 1u : 0u;
    reduce(lane, CULL_GROUP_SIZE);
    if (lane == 0u) CullWordsRef(cull.groupsAddress).words[gl_WorkGroupID.x] = counts[0];
}

// What the workgroups before this one counted ("count" or "runs count"): where this
// workgroup's commands start.
uint countedBefore(uint lane) {
    CullWordsRef groups = CullWordsRef(cull.groupsAddress);
    uint before = 0u;
    for (uint g = lane; g < gl_WorkGroupID.x; g += CULL_GROUP_SIZE) before += groups.words[g];
    counts[lane] = before;
    reduce(lane, CULL_GROUP_SIZE);
    uint base = counts[0];
    barrier();
    return base;
}

// Inclusive prefix of the flags over the workgroup (Hillis-Steele), left in counts[]; the
// workgroup's total is counts[CULL_GROUP_SIZE - 1].
void inclusivePrefix(uint lane, bool flag) {
    counts[lane] = flag ? 1u : 0u;
    barrier();
    for (uint stride = 1u; stride < CULL_GROUP_SIZE; stride <<= 1) {
        uint add = lane >= stride ? counts[lane - stride] : 0u;
        barrier();
        counts[lane] += add;
        barrier();
    }
}

void compactStep(uint lane, uint i) {
    uint base = countedBefore(lane);
    uint bits = i < cull.drawCount ? CullWordsRef(cull.stateAddress).words[i] : 0u;
    bool drawn = (bits & CULL_DRAW_NOW) != 0u;
    inclusivePrefix(lane, drawn);
    uint groupTotal = counts[CULL_GROUP_SIZE - 1u];
    StatsRef stats = StatsRef(cull.statsAddress);
    if (drawn) {
        uint slot = base + counts[lane] - 1u;
        CullWordsRef source = CullWordsRef(cull.sourceAddress);
        CullWordsRef target = CullWordsRef(cull.targetAddress);
        for (uint w = 0u; w < cull.commandWords; ++w)
            target.words[slot * cull.commandWords + w] = source.words[i * cull.commandWords + w];
    }
    // Triangles (indexed draws: indexCount / 3) and late draws the early pass did not list.
    barrier();
    uint drawTriangles =
        drawn && cull.commandWords == 5u ? CullWordsRef(cull.sourceAddress).words[i * 5u] / 3u : 0u;
    counts[lane] = drawTriangles;
    reduce(lane, CULL_GROUP_SIZE);
    uint triangles = counts[0];
    countLevels(lane, drawn ? DrawsRef(cull.drawsAddress).draws[i].lodLevel : 0u, drawTriangles);
    barrier();
    counts[lane] = drawn && (bits & CULL_WAS_VISIBLE) == 0u ? 1u : 0u;
    reduce(lane, CULL_GROUP_SIZE);
    if (lane == 0u) {
        uint pass = cull.phase == CULL_PHASE_LATE ? 1u : 0u;
        if (triangles != 0u) atomicAdd(stats.stats.triangles, triangles);
        if (pass == 1u && counts[0] != 0u) atomicAdd(stats.stats.lateNew, counts[0]);
        // The last workgroup knows the total: the pass's indirect draw count.
        if (gl_WorkGroupID.x + 1u == cull.groupCount) {
            stats.stats.draws[pass] = base + groupTotal;
            if (pass == 0u) stats.stats.listed = base + groupTotal;
            if (cull.phase == CULL_PHASE_EARLY && cull.dispatchesAddress != 0ul) skipLateIfIdle();
        }
    }
}

#include "cull_runs.glsl"

void main() {
    uint lane = gl_LocalInvocationID.x;
    uint i = gl_GlobalInvocationID.x;
    if (cull.step == CULL_STEP_CLUSTERS && (cull.flags & CULL_MESH_DRAWS) != 0u) {
        meshletsStep(lane, i);
    } else if (cull.step == CULL_STEP_CLUSTERS && (cull.flags & CULL_CLUSTER_RUNS) != 0u) {
        bool lateCandidate = runClustersStep(i);
        if (cull.phase == CULL_PHASE_EARLY && cull.dispatchesAddress != 0ul) {
            counts[lane] = lateCandidate ? 1u : 0u;
            reduce(lane, CULL_GROUP_SIZE);
            if (lane == 0u && counts[0] != 0u)
                atomicAdd(DispatchesRef(cull.dispatchesAddress).dispatches.lateCandidates,
                          counts[0]);
        }
    } else if (cull.step == CULL_STEP_CLUSTERS) {
        clustersStep(i);
    } else if (cull.step == CULL_STEP_COUNT) {
        countStep(lane, i);
    } else if (cull.step == CULL_STEP_RUNS_COUNT) {
        runsCountStep(lane, i);
    } else if (cull.step == CULL_STEP_RUNS_COMPACT) {
        runsCompactStep(lane, i);
    } else {
        if (cull.step != CULL_STEP_COMPACT) decideStep(lane, i);
        if (cull.step != CULL_STEP_DECIDE) compactStep(lane, i);
    }
}
