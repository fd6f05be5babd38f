// cull_runs.glsl - cull.comp's steps for lists of cluster runs (shared_cull.h): marking the
// (draw, cluster) pairs to draw, counting the runs, and writing a command per run.
#ifndef IDVIEW_CULL_RUNS_GLSL
#define IDVIEW_CULL_RUNS_GLSL

#include "cull_list.glsl"

uint pairState(uint pair) {
    return cullState().values[pairWord(pair)];
}

// Whether the cluster of `pair` (of draw d) passes this pass's test: its own box against the
// frustum (late: the pyramid too), clusters of hidden parts never. A cluster of a draw whose
// box lies inside the frustum is in view without a test where nothing is hidden.
bool clusterPasses(FrameData frame, uint d, uint drawBits, uint pair) {
    if (!lateStep() && (drawBits & CULL_INSIDE_FRUSTUM) != 0u && (frame.flags & FRAME_HIDING) == 0u)
        return true;
    DrawCull c = listDrawCull(d);
    CullBox box = CullBoxesRef(cull.clusterBoxesAddress).boxes[c.firstCluster + pair - c.firstPair];
    ObjectData object = ObjectsRef(frame.objectsAddress).objects[listDraw(d).objectIndex];
    if ((frame.flags & FRAME_HIDING) != 0u &&
        allBitsInRange(frame.hiddenAddress, object.uniquePartOffset + box.part, 1u))
        return false;
    BoxView view = viewBox(frame, object.world, box.boxMin, box.boxMax);
    return !view.outside && (!lateStep() || !occluded(frame, view, CULL_DRAW_SPAN));
}

// Whether the early pass draws the cluster of `pair` (of `object`): the clusters before its
// object's history end, so that the early clusters of an object are always its first ones and
// no cluster is drawn after a later one (where two tie in depth, the first drawn wins); in a
// still view each cluster with history by itself (shared_cull.h says why no order changes
// then). `had`: whether it has history.
bool earlyCluster(uint pair, uint object, bool had) {
    if ((cullFrame().flags & FRAME_VIEW_UNCHANGED) != 0u) return had;
    return pair < historyEnds().values[object];
}

// One (draw, cluster) pair: whether this pass draws the cluster. Frustum: the draw may lie
// in view. Early: the draw goes early and so does the cluster (earlyCluster). Late: the
// draw's box passed the pyramid; every cluster of it is tested, those drawn early too, so
// that the pair history follows the view, and those not drawn early are listed. A pass that
// makes history writes the pair history, which this step alone writes. No atomics here: the
// draws' words are left to runs count.
void runClustersStep(uint pair) {
    if (pair >= cull.pairCount) return;
    uint d = drawOfPair(pair);
    uint bits = cullState().values[d];
    uint before = pairState(pair);
    // Loaded beside the pair's other words, not once they are in, and the history written
    // below without reading whether it changed: a load that waits on another costs every
    // pair its latency (on the H200 the runs' cull was 4 % slower with such loads).
    bool had = earlyStep() && hadHistory(pair);
    bool candidate;
    if (lateStep())
        candidate = (bits & CULL_RETEST) != 0u;
    else
        candidate = (bits & CULL_DRAW_NOW) != 0u &&
                    (!earlyStep() || earlyCluster(pair, listDraw(d).objectIndex, had));
    bool passed = candidate && clusterPasses(cullFrame(), d, bits, pair);
    if ((passBits() & CULL_PASS_HISTORY) != 0u)
        UintsRef(cull.pairHistoryAddress).values[pair] = passed ? 1u : 0u;
    // The late pass lists only what the early one did not draw.
    bool now = passed && (!lateStep() || (before & CULL_PAIR_EARLY) == 0u);
    uint after = (passed && earlyStep() ? CULL_PAIR_EARLY : 0u) | (now ? CULL_PAIR_NOW : 0u) |
                 (passed ? CULL_PAIR_PASSED : 0u);
    if (after != before) cullState().values[pairWord(pair)] = after;
}

// Runs end where pairs' indices cross a multiple of this: runs compact finds the end of a run
// by walking it, which an object's thousand clusters in one run made the longest part of the
// cull (measured on the H100); the commands it adds are a few thousand.
const uint RUN_MAX_PAIRS = 32u;

// Whether `pair` starts a run: listed now, and the pair before it is of another draw, not
// listed, or across a multiple of RUN_MAX_PAIRS.
bool runStart(uint pair, uint d) {
    if ((pairState(pair) & CULL_PAIR_NOW) == 0u) return false;
    return pair % RUN_MAX_PAIRS == 0u || drawOfPair(pair - 1u) != d ||
           (pairState(pair - 1u) & CULL_PAIR_NOW) == 0u;
}

// Late: the last pair of each stretch of those that passed (the new pair history, read from
// the state words runs count reads anyway) moves its object's history end, in the slot the
// frame zeroed before its first pass; this is its only writer.
void moveHistoryEnd(uint pair, uint d) {
    if ((pairState(pair) & CULL_PAIR_PASSED) == 0u) return;
    uint object = listDraw(d).objectIndex;
    if (pair + 1u < cull.pairCount && (pairState(pair + 1u) & CULL_PAIR_PASSED) != 0u) {
        uint next = drawOfPair(pair + 1u);
        if (next == d || listDraw(next).objectIndex == object) return;
    }
    atomicMax(historyEnds().values[object], pair + 1u);
}

// Counts each workgroup's runs for runs compact, and the draws listed (late: those the early
// pass did not list), a draw by the first of its runs to mark it.
void runsCountStep(uint lane, uint pair) {
    bool start = false;
    bool newDraw = false;
    if (pair < cull.pairCount) {
        uint d = drawOfPair(pair);
        start = runStart(pair, d);
        if (start) {
            uint mark = CULL_LISTED | (earlyStep() ? CULL_LISTED_EARLY : 0u);
            uint was = atomicOr(cullState().values[d], mark);
            newDraw = (was & CULL_LISTED) == 0u && (!lateStep() || (was & CULL_LISTED_EARLY) == 0u);
        }
        if (lateStep()) moveHistoryEnd(pair, d);
    }
    uint runs = workgroupSum(lane, start ? 1u : 0u);
    if (lane == 0u) UintsRef(cull.groupsAddress).values[gl_WorkGroupID.x] = runs;
    uint draws = workgroupSum(lane, newDraw ? 1u : 0u);
    if (lane == 0u && draws != 0u) {
        CullStatsRef stats = CullStatsRef(cull.statsAddress);
        if (lateStep())
            atomicAdd(stats.stats.lateNew, draws);
        else
            atomicAdd(stats.stats.listed, draws);
    }
}

// The command of the run starting at `pair` (of draw d): the whole draw's
// VkDrawIndexedIndirectCommand narrowed to the run's triangles. Returns them.
uint writeRun(uint pair, uint d, uint slot) {
    DrawCull c = listDrawCull(d);
    CullBoxesRef boxes = CullBoxesRef(cull.clusterBoxesAddress);
    uint cluster = c.firstCluster + pair - c.firstPair;
    // Clusters of a draw are consecutive triangles (its parts' runs, in order).
    uint drawFirst = boxes.boxes[c.firstCluster].triangles >> 6;
    uint runFirst = boxes.boxes[cluster].triangles >> 6;
    uint triangles = 0u;
    uint end = min(cull.pairCount, (pair / RUN_MAX_PAIRS + 1u) * RUN_MAX_PAIRS);
    for (uint j = pair; j < end && drawOfPair(j) == d && (pairState(j) & CULL_PAIR_NOW) != 0u;
         ++j, ++cluster)
        triangles += (boxes.boxes[cluster].triangles & 63u) + 1u;
    UintsRef source = UintsRef(cull.sourceAddress);
    RunCommand command;
    command.indexCount = 3u * triangles;
    command.instanceCount = source.values[d * 5u + 1u];
    command.firstIndex = source.values[d * 5u + 2u] + 3u * (runFirst - drawFirst);
    command.vertexOffset = int(source.values[d * 5u + 3u]);
    command.firstInstance = source.values[d * 5u + 4u];
    command.runOffset = runFirst - drawFirst;
    RunCommandsRef(cull.targetAddress).commands[slot] = command;
    return triangles;
}

// One indexed command per run, in list order, and the triangles drawn (per level too).
void runsCompactStep(uint lane, uint pair) {
    uint base = countedBefore(lane);
    uint d = pair < cull.pairCount ? drawOfPair(pair) : 0u;
    bool start = pair < cull.pairCount && runStart(pair, d);
    inclusivePrefix(lane, start);
    uint groupTotal = counts[CULL_GROUP_SIZE - 1u];
    uint triangles = start ? writeRun(pair, d, base + counts[lane] - 1u) : 0u;
    uint total = workgroupSum(lane, triangles);
    countLevels(lane, start ? listDraw(d).lodLevel : 0u, triangles);
    if (lane != 0u) return;
    if (total != 0u) atomicAdd(CullStatsRef(cull.statsAddress).stats.triangles, total);
    if (gl_WorkGroupID.x + 1u == gl_NumWorkGroups.x) finishList(base + groupTotal);
}

#endif
