// per_draw.glsl - technique `per-draw`: one draw per part, and the draw itself carries the
// part's local index, so the fragment shader does no lookup at all.
uint techniqueLocalPartIndex() { return push.partIndex; }
