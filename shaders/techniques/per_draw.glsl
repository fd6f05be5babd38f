// per_draw.glsl - technique `per-draw`: one draw per part, and the draw itself names the
// part, so there is nothing to look up.
uint lookupLocalPart(FrameData frame, DrawData draw, uint primitive) { return draw.firstPart; }
