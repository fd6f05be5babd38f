// shading.glsl - colour from an ID and the headlight model shared by all techniques.

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
// have inconsistent winding. `toViewer`: from the point toward the viewer (prelude.glsl's
// toViewer), so an orthographic view lights every point from its one direction.
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
