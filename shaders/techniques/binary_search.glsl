// binary_search.glsl - technique `bsearch-fs`: one draw per object; the triangle's part is
// found by a binary search over the geometry's running triangle offsets (partCount + 1
// entries, offsets[p] is part p's first triangle), about log2(parts) dependent loads. It finds
// the last part that starts at or before the triangle: an empty part starts where the next
// one does, so it is never the answer.
uint lookupLocalPart(FrameData frame, DrawData draw, uint primitive) {
    UintsRef offsets = UintsRef(frame.idsAddress);
    uint low = 0u;                // offsets[low] <= primitive
    uint high = draw.partCount;   // primitive < offsets[high]
    while (high - low > 1u) {
        uint middle = (low + high) >> 1;
        if (offsets.values[draw.idsOffset + middle] <= primitive) low = middle;
        else high = middle;
    }
    return draw.firstPart + low;
}
