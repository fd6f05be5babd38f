// cull_draws.glsl - cull.comp's steps for lists of whole draws (shared_cull.h): the late
// pass's meshlets and count steps of the mesh techniques, and compact, which writes each
// listed draw's command in list order.
#ifndef IDVIEW_CULL_DRAWS_GLSL
#define IDVIEW_CULL_DRAWS_GLSL

#include "cull_list.glsl"

// Mesh draws, late: the (draw, meshlet) pairs, 32 to a word of meshlet bits, so each word is
// one draw's. A meshlet of a draw whose box passed is tested against the frustum and the
// pyramid, as the task shader would; the word's bits become what passed (the meshlet
// history, which this step alone writes in the pass), and the late bitset
// (FrameData::lateMeshletsAddress) what passed and the early pass did not draw, which is all
// the late task shader draws. A draw whose box did not pass keeps no history.
// Testing here, a thread per meshlet, spares the task stage a workgroup per 32 meshlets of
// every draw in view, nearly all of which would draw nothing.
shared uint meshletFound[CULL_GROUP_SIZE / 32u];
shared uint meshletNew[CULL_GROUP_SIZE / 32u];

// Whether the meshlet of `pair` (of draw d) may show: in view and not behind the pyramid.
bool meshletPasses(FrameData frame, uint d, uint pair) {
    DrawCull c = listDrawCull(d);
    uint local = pair - c.meshletBit;
    if (local >= c.meshletCount) return false; // the padding of the draw's last word
    DrawData draw = listDraw(d);
    ObjectData object = ObjectsRef(frame.objectsAddress).objects[draw.objectIndex];
    CullBox box = CullBoxesRef(frame.meshletBoxesAddress).boxes[draw.firstElement + local];
    BoxView view = viewBox(frame, object.world, box.boxMin, box.boxMax);
    return !view.outside && !occluded(frame, view, CULL_MESHLET_SPAN);
}

void meshletsStep(uint lane, uint pair) {
    uint slot = lane >> 5;
    uint bit = 1u << (lane & 31u);
    if ((lane & 31u) == 0u) {
        meshletFound[slot] = 0u;
        meshletNew[slot] = 0u;
    }
    barrier();
    FrameData frame = cullFrame();
    UintsRef history = UintsRef(frame.meshletHistoryAddress);
    bool inList = pair < cull.pairCount;
    uint d = inList ? drawOfPair(pair) : 0u;
    uint bits = inList ? cullState().values[d] : 0u;
    if ((bits & CULL_RETEST) != 0u && meshletPasses(frame, d, pair)) {
        atomicOr(meshletFound[slot], bit);
        bool drawnEarly = (bits & CULL_EARLY) != 0u && (history.values[pair >> 5] & bit) != 0u;
        if (!drawnEarly) atomicOr(meshletNew[slot], bit);
    }
    barrier();
    if (inList && (lane & 31u) == 0u) {
        history.values[pair >> 5] = meshletFound[slot];
        UintsRef(frame.lateMeshletsAddress).values[pair >> 5] = meshletNew[slot];
        if (meshletNew[slot] != 0u) atomicOr(cullState().values[d], CULL_NEW_MESHLETS);
    }
}

// Mesh draws, late: a draw whose box passed is listed only with a meshlet the early pass did
// not draw. Each workgroup's draws are counted again for compact.
void countStep(uint lane, uint i) {
    uint bits = 0u;
    if (i < cull.drawCount) {
        bits = cullState().values[i];
        if ((bits & (CULL_DRAW_NOW | CULL_NEW_MESHLETS)) == CULL_DRAW_NOW) {
            bits &= ~CULL_DRAW_NOW;
            cullState().values[i] = bits;
        }
    }
    uint listed = workgroupSum(lane, (bits & CULL_DRAW_NOW) != 0u ? 1u : 0u);
    if (lane == 0u) UintsRef(cull.groupsAddress).values[gl_WorkGroupID.x] = listed;
}

// The listed draws' commands, in list order, and the counters: triangles (indexed draws:
// indexCount / 3, also per level), draws listed, and late draws the early pass did not list.
void compactStep(uint lane, uint i) {
    uint base = countedBefore(lane);
    uint bits = i < cull.drawCount ? cullState().values[i] : 0u;
    bool listed = (bits & CULL_DRAW_NOW) != 0u;
    inclusivePrefix(lane, listed);
    uint groupTotal = counts[CULL_GROUP_SIZE - 1u];
    if (listed) {
        uint slot = base + counts[lane] - 1u;
        UintsRef source = UintsRef(cull.sourceAddress);
        UintsRef target = UintsRef(cull.targetAddress);
        for (uint w = 0u; w < cull.commandWords; ++w)
            target.values[slot * cull.commandWords + w] = source.values[i * cull.commandWords + w];
    }
    uint drawTriangles =
        listed && !meshDraws() ? UintsRef(cull.sourceAddress).values[i * 5u] / 3u : 0u;
    uint triangles = workgroupSum(lane, drawTriangles);
    countLevels(lane, listed ? listDraw(i).lodLevel : 0u, drawTriangles);
    uint lateNew = workgroupSum(lane, listed && (bits & CULL_EARLY) == 0u ? 1u : 0u);
    if (lane != 0u) return;
    CullStatsRef stats = CullStatsRef(cull.statsAddress);
    if (triangles != 0u) atomicAdd(stats.stats.triangles, triangles);
    if (lateStep() && lateNew != 0u) atomicAdd(stats.stats.lateNew, lateNew);
    if (gl_WorkGroupID.x + 1u == gl_NumWorkGroups.x) {
        if (!lateStep()) stats.stats.listed = base + groupTotal;
        finishList(base + groupTotal);
    }
}

#endif
