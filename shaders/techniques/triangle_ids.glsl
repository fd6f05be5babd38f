// triangle_ids.glsl - techniques `tri-fs` and `tri-gs`: one draw per object; the part of each
// triangle is stored per triangle, 1, 2 or 4 bytes wide by the geometry's part count, read
// here from 32-bit words so no 8/16-bit storage feature is needed.
uint lookupLocalPart(FrameData frame, DrawData draw, uint primitive) {
    uint byteAddress = draw.idsOffset + primitive * draw.idsWidth;
    uint word = UintsRef(frame.idsAddress).values[byteAddress >> 2];
    uint shift = (byteAddress & 3u) * 8u;
    uint mask = draw.idsWidth == 4u ? 0xFFFFFFFFu : (1u << (draw.idsWidth * 8u)) - 1u;
    return (word >> shift) & mask;
}
