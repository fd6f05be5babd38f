// cull_decide.glsl - cull.comp's per-draw steps for every kind of list (shared_cull.h): the
// levels step, which keeps each object's level of detail, and decide, which gives each draw
// its state bits for the pass and counts per workgroup the draws it lists.
#ifndef IDVIEW_CULL_DECIDE_GLSL
#define IDVIEW_CULL_DECIDE_GLSL

#include "cull_list.glsl"

// Levels: a draw of another level than the one its object draws this frame is listed by no
// pass. All of an object's draws hold the same box and errors (DrawCull), so they agree.
void levelsStep(uint i) {
    if (i >= cull.drawCount) return;
    FrameData frame = cullFrame();
    mat4 world = ObjectsRef(frame.objectsAddress).objects[listDraw(i).objectIndex].world;
    cullState().values[i] = lodChosen(frame, world, listDrawCull(i)) ? 0u : CULL_OTHER_LEVEL;
}

// Whether the early pass draws draw `i` (in view): runs where its object's history end lies
// past its first cluster, so that an object's early clusters are its first ones; mesh draws
// where one of its meshlets has history.
bool hasHistory(FrameData frame, DrawData draw, DrawCull c) {
    if (clusterRuns()) return c.firstPair < historyEnds().values[draw.objectIndex];
    if (meshDraws())
        return anyBitInRange(frame.meshletHistoryAddress, c.meshletBit, c.meshletCount);
    return false; // whole vertex draws are listed only with culling off
}

// The first pass of a frame (NONE, FRUSTUM or EARLY): the draw's place in the view.
uint decideFirst(FrameData frame, uint i, uint before) {
    if (frame.lodErrorPixels > 0.0 && (before & CULL_OTHER_LEVEL) != 0u) return CULL_OTHER_LEVEL;
    if ((passBits() & CULL_PASS_TESTS) == 0u) return CULL_DRAW_NOW;
    DrawData draw = listDraw(i);
    ObjectData object = ObjectsRef(frame.objectsAddress).objects[draw.objectIndex];
    bool hidden = (frame.flags & FRAME_HIDING) != 0u &&
                  allBitsInRange(frame.hiddenAddress, object.uniquePartOffset + draw.firstPart,
                                 draw.partCount);
    if (hidden) return 0u;
    DrawCull c = listDrawCull(i);
    BoxView view = viewBox(frame, object.world, c.boxMin, c.boxMax);
    if (view.outside) return 0u;
    uint bits = CULL_IN_FRUSTUM | (view.inside ? CULL_INSIDE_FRUSTUM : 0u);
    if (!earlyStep() || hasHistory(frame, draw, c))
        bits |= (earlyStep() ? CULL_EARLY : 0u) | CULL_DRAW_NOW;
    return bits;
}

// The late pass: every draw in view is tested against the pyramid again, those drawn early
// too, so that the history follows the view; a draw that passes has its pairs tested. Mesh
// draws are listed when a meshlet the early pass did not draw passed (the count step), whole
// vertex draws when they were not drawn early; runs list their clusters' runs.
uint decideLate(FrameData frame, uint i, uint before) {
    const uint kept =
        CULL_OTHER_LEVEL | CULL_IN_FRUSTUM | CULL_INSIDE_FRUSTUM | CULL_EARLY | CULL_LISTED_EARLY;
    uint bits = before & kept;
    if ((bits & CULL_IN_FRUSTUM) == 0u) return bits;
    ObjectData object = ObjectsRef(frame.objectsAddress).objects[listDraw(i).objectIndex];
    DrawCull c = listDrawCull(i);
    if (occluded(frame, viewBox(frame, object.world, c.boxMin, c.boxMax), CULL_DRAW_SPAN))
        return bits;
    bits |= CULL_RETEST;
    if (meshDraws() || (!clusterRuns() && (bits & CULL_EARLY) == 0u)) bits |= CULL_DRAW_NOW;
    return bits;
}

void decideStep(uint lane, uint i) {
    uint bits = 0u;
    if (i < cull.drawCount) {
        FrameData frame = cullFrame();
        uint before = cullState().values[i];
        bits = lateStep() ? decideLate(frame, i, before) : decideFirst(frame, i, before);
        cullState().values[i] = bits;
    }
    uint listed = workgroupSum(lane, (bits & CULL_DRAW_NOW) != 0u ? 1u : 0u);
    if (lane == 0u) UintsRef(cull.groupsAddress).values[gl_WorkGroupID.x] = listed;
}

#endif
