// packed_ids.glsl - local part indices stored per element, 1, 2 or 4 bytes wide by the
// geometry's part count (scene/part_data.h PackedPartIndices), read from 32-bit words so no
// 8/16-bit storage feature is needed. The element is a triangle (tri-fs, tri-gs: from
// gl_PrimitiveID), a vertex (vertex-fs: from gl_VertexIndex) or a meshlet triangle (mesh-fs).
uint lookupLocalPart(FrameData frame, DrawData draw, uint element) {
    uint byteAddress = draw.idsOffset + element * draw.idsWidth;
    uint word = UintsRef(frame.idsAddress).values[byteAddress >> 2];
    uint shift = (byteAddress & 3u) * 8u;
    uint mask = draw.idsWidth == 4u ? 0xFFFFFFFFu : (1u << (draw.idsWidth * 8u)) - 1u;
    return (word >> shift) & mask;
}
