// batch_search.glsl - techniques `search-fs` and `search-gs`: a draw covers up to
// IDV_SEARCH_COUNT consecutive parts; the triangle's part is found by walking their triangle
// counts. The loop has a fixed length and is unrolled, its loads independent of the
// comparisons so they can all be in flight at once; the counts buffer is padded so reading
// past the batch's last part stays inside it. An empty part's count of 0 holds no triangle.
uint lookupLocalPart(FrameData frame, DrawData draw, uint primitive) {
    UintsRef counts = UintsRef(frame.idsAddress);
    uint begin = 0u;
    uint found = 0u;
    [[unroll]] for (uint i = 0u; i < IDV_SEARCH_COUNT; ++i) {
        uint count = counts.values[draw.idsOffset + i];
        [[flatten]] if (i < draw.partCount && primitive >= begin && primitive < begin + count) {
            found = i;
        }
        begin += count;
    }
    return draw.firstPart + found;
}
