#version 460
// cull.comp - one step of one culling pass over a draw list (render/culling.h records the
// steps; shared_cull.h's table says which steps each phase and list take and what each does).
// Draws or (draw, cluster | meshlet) pairs are spread over workgroups of CULL_GROUP_SIZE;
// compaction keeps the list's order, so where two surfaces share a depth, the one drawn
// first wins, as without culling.
#include "cull_decide.glsl"
#include "cull_draws.glsl"
#include "cull_runs.glsl"

void main() {
    uint lane = gl_LocalInvocationID.x;
    uint i = gl_GlobalInvocationID.x; // a draw, or a pair in the pairs' steps
    switch (cull.step) {
    case CULL_STEP_LEVELS:
        levelsStep(i);
        break;
    case CULL_STEP_DECIDE:
        decideStep(lane, i);
        break;
    case CULL_STEP_CLUSTERS:
        runClustersStep(i);
        break;
    case CULL_STEP_MESHLETS:
        meshletsStep(lane, i);
        break;
    case CULL_STEP_COUNT:
        countStep(lane, i);
        break;
    case CULL_STEP_COMPACT:
        compactStep(lane, i);
        break;
    case CULL_STEP_RUNS_COUNT:
        runsCountStep(lane, i);
        break;
    case CULL_STEP_RUNS_COMPACT:
        runsCompactStep(lane, i);
        break;
    }
}
