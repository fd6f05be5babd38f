// cull_runs.glsl - cull.comp's steps for lists of cluster runs (CULL_CLUSTER_RUNS in
// shared.h): marking the (draw, cluster) pairs to draw, counting the runs, and writing a
// command per run. Included by cull.comp after its buffers, counts[] and reduce().

// Cluster runs (CULL_CLUSTER_RUNS): the pair state words follow the draws'.
uint pairState(uint pair) {
    return CullWordsRef(cull.stateAddress).words[cull.drawCount + pair];
}

// One (draw, cluster) pair of a list of cluster runs: whether this pass draws the cluster.
// Early: the draw is drawn early by the last ID image (CULL_DRAW_NOW), and the cluster comes
// before the end of its object's history: the early clusters of an object are always the
// first of its clusters, as its early draws are its first draws, so no cluster is drawn after
// a later one (where two tie in depth, the first drawn wins). Frustum: the draw may lie in
// view. Late: the draw's box passed, and the cluster's passes too and was not drawn early.
// Every pass tests the cluster's own box against the frustum (the late one against the
// pyramid too, for every cluster in view, so that the history follows the view) and leaves
// out clusters of hidden parts. No atomics here: the draws' words are left to "runs count".
// stillHistory: in a still view (FRAME_VIEW_UNCHANGED), after a frame whose late pass ran,
// each cluster that passed that test goes first by itself, and the images stay those of
// culling off. A cluster that did not pass lay wholly behind that frame's early depth, so
// behind its final depth, which a still view draws again: drawn late, it writes no sample
// and ties none. A cluster that wins a tie without culling showed in the last image, so it
// passed, and its draw goes early by that image.
// Returns whether the late pass has the cluster to test: in a draw in view, not drawn early
// nor found outside the view or hidden now. Where no cluster is left to it, the late pass is
// skipped (the view shows all it holds), and the history stays as it is. The floors test
// every cluster in view again: their history, not the ID image, is all that drops a draw.
bool runClustersStep(uint pair) {
    if (pair >= cull.pairCount) return false;
    CullWordsRef state = CullWordsRef(cull.stateAddress);
    uint d = CullWordsRef(cull.pairsAddress).words[pair];
    uint bits = state.words[d];
    uint before = state.words[cull.drawCount + pair];
    bool late = cull.phase == CULL_PHASE_LATE;
    uint objectIndex = DrawsRef(cull.drawsAddress).draws[d].objectIndex;
    // In a still view whose last frame tested every cluster in view, the clusters that
    // passed that test go first, each by itself (see stillHistory below).
    bool still = cull.phase == CULL_PHASE_EARLY &&
                 (FrameRef(cull.frameAddress).frame.flags & FRAME_VIEW_UNCHANGED) != 0u &&
                 state.words[lateRanWord()] != 0u;
    bool early = still ? (before & CULL_PAIR_HISTORY) != 0u
                       : pair < state.words[historyEndWord(objectIndex)];
    bool candidate = late ? (bits & CULL_NEEDS_CLUSTERS) != 0u
                          : (bits & CULL_DRAW_NOW) != 0u &&
                                (cull.phase != CULL_PHASE_EARLY || early);
    bool passed = false;
    // Clusters of a draw whose box lies inside the frustum do too; without hiding, nothing
    // else is left to test before the late pass.
    if (candidate && !late && (bits & CULL_INSIDE_FRUSTUM) != 0u &&
        (FrameRef(cull.frameAddress).frame.flags & FRAME_HIDING) == 0u) {
        passed = true;
    } else if (candidate) {
        FrameData frame = FrameRef(cull.frameAddress).frame;
        DrawCull drawCull = DrawCullRef(cull.cullAddress).draws[d];
        CullBox box = ClusterBoxesRef(cull.clusterBoxesAddress)
                          .boxes[drawCull.firstCluster + pair - drawCull.firstPair];
        ObjectData object = ObjectsRef(frame.objectsAddress).objects[objectIndex];
        bool hidden = (frame.flags & FRAME_HIDING) != 0u &&
                      allBitsInRange(frame.hiddenAddress, object.uniquePartOffset + box.unused0, 1u);
        if (!hidden) {
            BoxView view = viewBox(frame, object.world, box.boxMin, box.boxMax);
            passed = !view.outside && (!late || !occluded(frame, view, CULL_DRAW_SPAN));
        }
    }
    uint after;
    if (cull.phase == CULL_PHASE_EARLY) {
        after = (before & CULL_PAIR_HISTORY) | (passed ? CULL_PAIR_EARLY | CULL_PAIR_NOW : 0u);
    } else if (late) {
        bool now = passed && (before & CULL_PAIR_EARLY) == 0u;
        after = (passed ? CULL_PAIR_HISTORY : 0u) | (now ? CULL_PAIR_NOW : 0u);
    } else {
        after = passed ? CULL_PAIR_HISTORY | CULL_PAIR_NOW : 0u;
    }
    if (after != before) state.words[cull.drawCount + pair] = after;
    bool boundsHistory =
        (FrameRef(cull.frameAddress).frame.flags & FRAME_BOUNDS_HISTORY) != 0u;
    return (bits & CULL_IN_FRUSTUM) != 0u && (!candidate || boundsHistory);
}

layout(buffer_reference, std430, buffer_reference_align = 4) writeonly buffer RunCommandsRef {
    RunCommand commands[];
};

// Runs end where pairs' indices cross a multiple of this: "runs compact" finds the end of a
// run by walking it, which an object's thousand clusters in one run made the longest part
// of the cull (measured on the H100); the commands it adds are a few thousand.
const uint RUN_MAX_PAIRS = 32u;

// Whether `pair` starts a run: listed now, and the pair before it is of another draw, not
// listed, or across a multiple of RUN_MAX_PAIRS.
bool runStart(uint pair, uint d) {
    if ((pairState(pair) & CULL_PAIR_NOW) == 0u) return false;
    return pair % RUN_MAX_PAIRS == 0u || CullWordsRef(cull.pairsAddress).words[pair - 1u] != d ||
           (pairState(pair - 1u) & CULL_PAIR_NOW) == 0u;
}

// Counts each workgroup's runs for "runs compact", and the draws listed (late: those the
// early pass did not list), a draw by the first of its runs to mark it. In the late phase
// the last pair of each run of clusters that passed moves its object's end of history and
// marks its draw as passed.
void runsCountStep(uint lane, uint pair) {
    bool start = false;
    uint listedDraw = 0u;
    bool late = cull.phase == CULL_PHASE_LATE;
    if (pair < cull.pairCount) {
        CullWordsRef state = CullWordsRef(cull.stateAddress);
        CullWordsRef pairs = CullWordsRef(cull.pairsAddress);
        uint d = pairs.words[pair];
        start = runStart(pair, d);
        if (start) {
            uint mark = CULL_LISTED | (cull.phase == CULL_PHASE_EARLY ? CULL_LISTED_EARLY : 0u);
            uint was = atomicOr(state.words[d], mark);
            bool first = (was & CULL_LISTED) == 0u;
            listedDraw = first && (!late || (was & CULL_LISTED_EARLY) == 0u) ? 1u : 0u;
        }
        if (late && (pairState(pair) & CULL_PAIR_HISTORY) != 0u) {
            uint objectIndex = DrawsRef(cull.drawsAddress).draws[d].objectIndex;
            bool nextToo = false;
            if (pair + 1u < cull.pairCount && (pairState(pair + 1u) & CULL_PAIR_HISTORY) != 0u) {
                uint next = pairs.words[pair + 1u];
                nextToo = next == d ||
                          DrawsRef(cull.drawsAddress).draws[next].objectIndex == objectIndex;
            }
            if (!nextToo) {
                atomicMax(state.words[historyEndWord(objectIndex)], pair + 1u);
                atomicOr(state.words[d], CULL_CLUSTER_PASSED);
            }
        }
    }
    counts[lane] = start ? 1u : 0u;
    reduce(lane, CULL_GROUP_SIZE);
    if (lane == 0u) CullWordsRef(cull.groupsAddress).words[gl_WorkGroupID.x] = counts[0];
    barrier();
    counts[lane] = listedDraw;
    reduce(lane, CULL_GROUP_SIZE);
    if (lane == 0u && counts[0] != 0u) {
        StatsRef stats = StatsRef(cull.statsAddress);
        if (late)
            atomicAdd(stats.stats.lateNew, counts[0]);
        else
            atomicAdd(stats.stats.listed, counts[0]);
    }
}

// One indexed command per run, in list order: its draw's command over the run's triangles.
void runsCompactStep(uint lane, uint pair) {
    uint base = countedBefore(lane);
    bool start = false;
    uint d = 0u;
    if (pair < cull.pairCount) {
        d = CullWordsRef(cull.pairsAddress).words[pair];
        start = runStart(pair, d);
        // The floors' history: a draw none of whose clusters passed did not pass.
        bool firstOfDraw = pair == 0u || CullWordsRef(cull.pairsAddress).words[pair - 1u] != d;
        CullWordsRef state = CullWordsRef(cull.stateAddress);
        const uint failed = CULL_NEEDS_CLUSTERS | CULL_PASSED;
        if (cull.phase == CULL_PHASE_LATE && firstOfDraw &&
            (state.words[d] & (failed | CULL_CLUSTER_PASSED)) == failed)
            state.words[d] &= ~CULL_PASSED;
    }
    inclusivePrefix(lane, start);
    uint groupTotal = counts[CULL_GROUP_SIZE - 1u];
    uint triangles = 0u;
    uint level = 0u;
    if (start) {
        level = DrawsRef(cull.drawsAddress).draws[d].lodLevel;
        DrawCull drawCull = DrawCullRef(cull.cullAddress).draws[d];
        ClusterBoxesRef boxes = ClusterBoxesRef(cull.clusterBoxesAddress);
        uint cluster = drawCull.firstCluster + pair - drawCull.firstPair;
        // Clusters of a draw are consecutive triangles (its parts' runs, in order).
        uint drawFirst = boxes.boxes[drawCull.firstCluster].triangles >> 6;
        uint runFirst = boxes.boxes[cluster].triangles >> 6;
        CullWordsRef pairs = CullWordsRef(cull.pairsAddress);
        uint end = min(cull.pairCount, (pair / RUN_MAX_PAIRS + 1u) * RUN_MAX_PAIRS);
        for (uint j = pair; j < end && pairs.words[j] == d && (pairState(j) & CULL_PAIR_NOW) != 0u;
             ++j, ++cluster)
            triangles += (boxes.boxes[cluster].triangles & 63u) + 1u;
        uint slot = base + counts[lane] - 1u;
        CullWordsRef source = CullWordsRef(cull.sourceAddress);
        // The whole draw's VkDrawIndexedIndirectCommand, narrowed to the run.
        RunCommand command;
        command.indexCount = 3u * triangles;
        command.instanceCount = source.words[d * 5u + 1u];
        command.firstIndex = source.words[d * 5u + 2u] + 3u * (runFirst - drawFirst);
        command.vertexOffset = int(source.words[d * 5u + 3u]);
        command.firstInstance = source.words[d * 5u + 4u];
        command.runOffset = runFirst - drawFirst;
        RunCommandsRef(cull.targetAddress).commands[slot] = command;
    }
    barrier();
    counts[lane] = triangles;
    reduce(lane, CULL_GROUP_SIZE);
    countLevels(lane, level, triangles);
    if (lane == 0u) {
        StatsRef stats = StatsRef(cull.statsAddress);
        if (counts[0] != 0u) atomicAdd(stats.stats.triangles, counts[0]);
        uint pass = cull.phase == CULL_PHASE_LATE ? 1u : 0u;
        if (gl_WorkGroupID.x + 1u == (cull.pairCount + CULL_GROUP_SIZE - 1u) / CULL_GROUP_SIZE) {
            stats.stats.draws[pass] = base + groupTotal;
            if (cull.phase == CULL_PHASE_EARLY && cull.dispatchesAddress != 0ul) skipLateIfIdle();
            // Read by this pass's clusters; the late pass, if it runs, sets it again.
            if (cull.phase != CULL_PHASE_LATE)
                CullWordsRef(cull.stateAddress).words[lateRanWord()] = 0u;
        }
    }
}
