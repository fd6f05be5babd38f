// shading.glsl - colour from an ID and the headlight model shared by all techniques: the
// scene pass's fragment shader and the visibility buffer's shading pass (include buffers.glsl
// first).

// From the surface point `worldPos` toward the viewer, not normalised: to the eye in
// perspective (FrameData::eyePosition.w 1), the one direction of the view in ortho (w 0).
vec3 toViewer(FrameData frame, vec3 worldPos) {
    return frame.eyePosition.w != 0.0 ? frame.eyePosition.xyz - worldPos : frame.eyePosition.xyz;
}

// A well-mixed integer hash (PCG output permutation) so neighbouring IDs get unrelated colours.
uint hashId(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// A distinct, saturated colour per ID, in linear RGB: hue from the hash, saturation and value
// kept in a band where neighbouring parts still read apart under the lighting.
vec3 hashColor(uint id) {
    uint h = hashId(id);
    float hue = float(h & 0xFFFFu) / 65536.0;
    float saturation = 0.45 + 0.35 * float((h >> 16) & 0xFFu) / 255.0;
    float value = 0.70 + 0.30 * float(h >> 24) / 255.0;
    vec3 rgb = clamp(abs(mod(hue * 6.0 + vec3(0, 4, 2), 6.0) - 3.0) - 1.0, 0.0, 1.0);
    vec3 srgb = value * mix(vec3(1.0), rgb, saturation);
    return srgb * srgb; // roughly sRGB to linear, to match material colours
}

// Light placed at the eye: faces turned to the viewer are bright whatever the orientation,
// which is what CAD users expect from an inspection view. Two-sided, since CAD exports often
// have inconsistent winding. `toViewer`: from the point toward the viewer (toViewer above), so an orthographic view lights every point from its one direction.
vec3 headlight(vec3 base, vec3 worldNormal, vec3 toViewer) {
    vec3 n = normalize(worldNormal);
    vec3 v = normalize(toViewer);
    float diffuse = abs(dot(n, v));
    vec3 linear = base * (0.2 + 0.8 * diffuse);
    return pow(linear, vec3(1.0 / 2.2)); // the colour attachment is UNORM: encode for display
}

// Where a section plane opens a solid (scene.frag): the part's colour, darker, under
// diagonal hatching 2 of every 8 pixels wide, unlit, so a cap never reads as a surface.
vec3 capColor(vec3 base, vec2 fragCoord) {
    bool line = (uint(fragCoord.x) + uint(fragCoord.y)) % 8u < 2u;
    vec3 linear = base * (line ? 0.12 : 0.45);
    return pow(linear, vec3(1.0 / 2.2));
}

// FRAME_TINT_LEVELS: a colour per level of detail, full detail first (the panel's legend
// shows the same ones), far apart in hue so that neighbouring objects read apart.
vec3 levelTint(uint level) {
    return LEVEL_TINTS[min(level, LOD_MAX_LEVELS - 1u)];
}

// The colour a draw's surface starts from: its object's material, or what the frame's flags
// put in its place (one neutral grey, a colour per draw, a colour per level of detail).
vec3 drawBase(FrameData frame, ObjectData object, uint drawIndex, uint lodLevel) {
    vec3 base = MaterialsRef(frame.materialsAddress).materials[object.materialIndex].color.rgb;
    if ((frame.flags & FRAME_IGNORE_MATERIALS) != 0u) base = vec3(NEUTRAL_MATERIAL);
    if ((frame.flags & FRAME_COLORIZE_DRAWS) != 0u) base = hashColor(drawIndex ^ 0x9e3779b9u);
    if ((frame.flags & FRAME_TINT_LEVELS) != 0u) base = levelTint(lodLevel);
    return base;
}

// The colour a part is shaded in: a face with a colour of its own (CAD files) shows it instead
// of its object's where materials show, then the part's hash colour is blended over.
vec3 partBase(FrameData frame, ObjectData object, uint localPart, uint uniquePartId, vec3 base) {
    if (frame.partMaterialsAddress != 0ul && (frame.flags & FRAME_IGNORE_MATERIALS) == 0u &&
        (frame.flags & (FRAME_COLORIZE_DRAWS | FRAME_TINT_LEVELS)) == 0u) {
        uint own = UintsRef(frame.partMaterialsAddress).values[object.firstPart + localPart];
        if (own != OBJECT_MATERIAL) base = MaterialsRef(frame.materialsAddress).materials[own].color.rgb;
    }
    return mix(base, hashColor(uniquePartId), frame.partColorWeight);
}
