// buffers.glsl - what every idview shader includes first: the extensions the shared code
// needs (all here, so that no include adds one after code), the shared.h family, and every
// buffer-reference type the shaders read or write memory through, each declared here once. A shader
// names a buffer by the address a struct of shared.h holds (FrameData::objectsAddress...) cast to
// one of these. None is declared readonly or writeonly, so that one type serves the shaders that
// read it and the one that writes it.
#ifndef IDVIEW_BUFFERS_GLSL
#define IDVIEW_BUFFERS_GLSL

#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_control_flow_attributes : require
#extension GL_EXT_shader_atomic_int64 : require

#include "shared.h"

// The scene and the frame.
layout(buffer_reference, std430, buffer_reference_align = 16) buffer FrameRef {
    FrameData frame;
};
layout(buffer_reference, std430, buffer_reference_align = 16) buffer ObjectsRef {
    ObjectData objects[];
};
layout(buffer_reference, std430, buffer_reference_align = 16) buffer MaterialsRef {
    Material materials[];
};
// animate.comp's inputs: the objects' placements in double, and their exploded offsets.
layout(buffer_reference, std430, buffer_reference_align = 32) buffer DMat4sRef {
    dmat4 matrices[];
};
layout(buffer_reference, std430, buffer_reference_align = 16) buffer Vec4sRef {
    vec4 values[];
};

// Plain arrays: bitsets, ID data, indices, state words; the meshlets' vertices as floats
// (Vertex is two tightly packed vec3s, which std430 would pad to 16 bytes each).
layout(buffer_reference, std430, buffer_reference_align = 4) buffer UintsRef {
    uint values[];
};
layout(buffer_reference, std430, buffer_reference_align = 4) buffer FloatsRef {
    float values[];
};
layout(buffer_reference, std430, buffer_reference_align = 8) buffer Uint64Ref {
    uint64_t value;
};

// Draws.
layout(buffer_reference, std430, buffer_reference_align = 4) buffer DrawsRef {
    DrawData draws[];
};
layout(buffer_reference, std430, buffer_reference_align = 16) buffer MeshletsRef {
    Meshlet meshlets[];
};
layout(buffer_reference, std430, buffer_reference_align = 4) buffer RunCommandsRef {
    RunCommand commands[];
};
layout(buffer_reference, std430, buffer_reference_align = 16) buffer MeshTaskCommandsRef {
    MeshTaskCommand commands[];
};

// The visibility buffer.
layout(buffer_reference, std430, buffer_reference_align = 16) buffer VisibilityDrawsRef {
    VisibilityDraw draws[];
};
// The compute rasterizer's lists (a VkDispatchIndirectCommand and a count per pass, then the
// entries) and its 64-bit samples.
layout(buffer_reference, std430, buffer_reference_align = 16) buffer RasterListRef {
    uint dispatch[8]; // per pass: x, y, z, and a word to spare
    RasterEntry entries[];
};
layout(buffer_reference, std430, buffer_reference_align = 8) buffer RasterSamplesRef {
    uint64_t values[];
};

// Culling.
layout(buffer_reference, std430, buffer_reference_align = 16) buffer DrawCullsRef {
    DrawCull draws[];
};
layout(buffer_reference, std430, buffer_reference_align = 16) buffer CullBoxesRef {
    CullBox boxes[];
};
layout(buffer_reference, std430, buffer_reference_align = 4) buffer CullStatsRef {
    CullStats stats;
};
layout(buffer_reference, std430, buffer_reference_align = 16) buffer PyramidRef {
    PyramidHeader header;
    float depth[];
};

// The pick and the passes over the ID image.
layout(buffer_reference, std430, buffer_reference_align = 8) buffer PickRef {
    PickData pick;
};
layout(buffer_reference, std430, buffer_reference_align = 8) buffer HoverBoxRef {
    HoverBox box;
};
layout(buffer_reference, std430, buffer_reference_align = 16) buffer PartSetRef {
    PartSetResult head;
    uint words[];
};
// The visibility census's totals (census.comp); its per-view counters are UintsRef.
layout(buffer_reference, std430, buffer_reference_align = 16) buffer CensusTotalsRef {
    CensusTotals parts[];
};

#endif
