// nary_search.glsl - techniques `nsearch-fs` and `nsearch-gs`: one draw per object; the
// triangle's part is found in the geometry's running triangle offsets (partCount + 1 entries,
// offsets[p] is part p's first triangle) by an N-ary search. Each step reads N - 1 offsets
// whose addresses do not depend on each other, so they can all be in flight at once, and
// narrows the range N-fold: about log_N(parts) rounds of loads instead of binary search's
// log_2(parts) dependent ones. Compiled per parameter set (src/render/shader_variants.cpp):
//   IDV_NSEARCH_N       3..16, the fan-out of a step
//   IDV_NSEARCH_GUESS   1: start at the part a uniform part size predicts, then widen
//   IDV_NSEARCH_LINEAR  scan linearly once the range has at most this many parts
//   IDV_NSEARCH_STEPS   N-ary steps at most; the linear scan finishes whatever is left, so
//                       the answer is exact for any cap and the loops always end.
// Invariant throughout: offsets[low] <= primitive < offsets[high], so the part is in
// [low, high), and the answer is the last part that starts at or before the triangle: an empty
// part starts where the next one does, so it is never the answer.

// Gallops away from a guessed part until the range brackets the primitive. Each probe
// doubles the distance, so a guess k parts off costs about 2 log2(k) loads.
void narrowByGuess(UintsRef offsets, uint base, uint primitive, inout uint low, inout uint high) {
    uint total = offsets.values[base + high]; // > primitive, so not 0
    uint guess = uint(uint64_t(primitive) * uint64_t(high) / uint64_t(total));
    guess = min(guess, high - 1u);
    if (offsets.values[base + guess] <= primitive) {
        low = guess;
        for (uint width = 1u; width != 0u && high - low > 1u; width <<= 1) {
            uint probe = low + min(width, high - low - 1u);
            if (offsets.values[base + probe] > primitive) {
                high = probe;
                break;
            }
            low = probe;
        }
    } else {
        high = guess;
        for (uint width = 1u; width != 0u && high - low > 1u; width <<= 1) {
            uint probe = high - min(width, high - low - 1u);
            if (offsets.values[base + probe] <= primitive) {
                low = probe;
                break;
            }
            high = probe;
        }
    }
}

uint lookupLocalPart(FrameData frame, DrawData draw, uint primitive) {
    UintsRef offsets = UintsRef(frame.idsAddress);
    uint base = draw.idsOffset;
    uint low = 0u;
    uint high = draw.partCount;
#if IDV_NSEARCH_GUESS
    if (high > 1u) narrowByGuess(offsets, base, primitive, low, high);
#endif
    // The N - 1 pivots split [low, high) into N pieces of at most ceil(size / N) parts; for
    // size < N they are every part of the range, so each step shrinks it until one is left.
    for (uint step = 0u; step < IDV_NSEARCH_STEPS && high - low > max(IDV_NSEARCH_LINEAR, 1u);
         ++step) {
        uint size = high - low;
        uint whole = size / IDV_NSEARCH_N;
        uint rest = size % IDV_NSEARCH_N;
        uint newLow = low;
        uint newHigh = high;
        [[unroll]] for (uint k = 1u; k < IDV_NSEARCH_N; ++k) {
            // low + size * k / N without overflowing 32 bits.
            uint pivot = low + whole * k + rest * k / IDV_NSEARCH_N;
            uint value = offsets.values[base + pivot];
            if (value <= primitive) newLow = max(newLow, pivot);
            else newHigh = min(newHigh, pivot);
        }
        low = newLow;
        high = newHigh;
    }
    // The last parts (or everything the step cap left) one by one.
    uint part = low;
    for (uint p = low + 1u; p < high && offsets.values[base + p] <= primitive; ++p) part = p;
    return draw.firstPart + part;
}
