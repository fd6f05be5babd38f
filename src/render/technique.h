// technique.h - the part-ID techniques and per-draw modes as data: the registry. A technique
// is one row of techniques() (technique.cpp) plus its lookup file in shaders/techniques/ (and
// an ID-data builder in draw_list.cpp only if it reads data no technique reads yet). The
// command line, the panel, --list-renderers, the benchmark, the shader variants and the tests
// all iterate the registry; nothing else switches on technique names.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vk {
struct DeviceInfo;
}

namespace render {

// The ID data a technique's shaders read (scene/part_data.h, part_vertices.h and meshlets.h
// build each).
enum class IdBuffer {
    None,                   // the draw names its part
    TrianglePartIds,        // part index per triangle
    PartTriangleCounts,     // triangle count per part, padded for the search loop
    PartTriangleOffsets,    // running triangle offset per part
    VertexPartIds,          // part index per vertex of the part vertices, 1/2/4 bytes
    MeshletTrianglePartIds, // part index per meshlet triangle, 1/2/4 bytes
    MeshletVertexPartIds,   // part index per meshlet vertex (over part vertices), 1/2/4 bytes
};

// What the draws read their triangles from.
enum class Primitives {
    SceneIndices, // the scene's vertex and index buffers, vertex shader
    PartVertices, // the rotated copy whose first vertex names the part (part_vertices.h)
    // Meshlets cut from the part vertices, mesh shader (VK_EXT_mesh_shader): the same
    // meshlets for every mesh technique and their floor, so only the ID work differs.
    Meshlets,
};

enum class DrawSplit { PerPart, PerObject, PerBatch };

// Where the part lookup runs: the fragment shader (from gl_PrimitiveID), a geometry shader
// once per triangle, the vertex shader once per vertex (handed on flat), or the mesh shader
// once per triangle (a per-primitive output). Shade: a compute pass after the scene pass, per
// sample, from the visibility buffer's payload (render/visibility.h), which also shades.
// None: no part ID at all, a benchmark floor.
enum class LookupStage { Fragment, Geometry, Vertex, Mesh, Shade, None };

// Parameters of the N-ary search (nsearch-*), compiled into the shader as IDV_NSEARCH_*
// defines, so each set is its own pipeline (the loop unrolls over n - 1 independent loads).
// Defaults: the fastest set of the H100 sweep in docs/benchmarks.md; ranges in settings.h.
struct NarySearch {
    uint32_t n = 3;           // each step reads n - 1 offsets and narrows n-fold
    bool guess = false;       // start where a uniform part size puts the triangle, then widen
    uint32_t linearBelow = 8; // scan linearly once the range has at most this many parts
    uint32_t maxSteps = 16;   // N-ary steps at most; a linear scan finishes the rest
    bool operator==(const NarySearch&) const = default;
};

struct Technique {
    const char* name;        // as the CLI spells it
    const char* description; // one line for --list-renderers and the panel
    const char* lookupFile;  // defines lookupLocalPart(); included as "technique.glsl" (or null)
    LookupStage stage;
    IdBuffer ids;
    DrawSplit split;
    Primitives primitives = Primitives::SceneIndices;
    bool narySearch = false; // reads PipelineKey::nsearch (the IDV_NSEARCH_* defines)
    // A visibility buffer whose task shader sends meshlets that project small to a compute
    // rasterizer (render/compute_raster.h) instead of the mesh shader.
    bool computeRaster = false;

    // A benchmark floor: no part ID anywhere, nothing in the ID attachment. Each kind of
    // pipeline (vertex or mesh shader) has one, so a technique is measured against the
    // same pipeline without the ID work.
    bool isFloor() const { return stage == LookupStage::None; }
    bool readsSearchBatch() const { return ids == IdBuffer::PartTriangleCounts; }
    bool usesMeshShader() const { return primitives == Primitives::Meshlets; }
    // The scene pass writes a triangle's payload per sample and no colour; a compute pass
    // finds the part and shades (render/visibility.h).
    bool isVisibilityBuffer() const { return stage == LookupStage::Shade; }
    bool usesPartVertices() const { return primitives != Primitives::SceneIndices; }
    // A stage finds the part from gl_PrimitiveID, which counts from the start of a draw
    // command: drawn by cluster runs, it adds the run's offset (PipelineKey::runOffsets).
    bool readsPrimitiveId() const {
        return !usesMeshShader() && ids != IdBuffer::None && stage != LookupStage::Vertex;
    }
    // Culling draws any run of a draw's clusters on its own (shared.h, CULL_CLUSTER_RUNS);
    // the mesh techniques cull meshlets instead.
    bool drawsClusterRuns() const { return !usesMeshShader(); }
};

// How per-draw parameters reach the shaders.
struct DrawMode {
    const char* name;
    const char* description;
    const char* define;      // IDV_MODE_* set to 1 (the others to 0)
    bool indirect;           // one multi-draw-indirect call per pipeline
    bool drawIndexAttribute; // the draw index comes from an instanced vertex attribute
};

// Every technique, the floors last; partIdTechniques() leaves the floors out (they have no
// ID image to compare).
const std::vector<Technique>& techniques();
std::vector<const Technique*> partIdTechniques();
const Technique& floorTechnique(); // no-id: the vertex-shader pipeline's floor
// The floor `technique` is measured against: its own kind of pipeline without the ID work.
const Technique& floorOf(const Technique& technique);
const Technique& defaultTechnique(); // the first row
const std::vector<DrawMode>& drawModes();
const DrawMode& defaultDrawMode(); // the first row

// Why `technique` cannot run on the device ("needs VK_EXT_mesh_shader, which <device> does
// not offer"), or "" when it can.
std::string unavailableReason(const Technique& technique, const vk::DeviceInfo& device);

// nullptr when there is no such name.
const Technique* findTechnique(const std::string& name);
const DrawMode* findDrawMode(const std::string& name);

// "a, b, c": for usage text and error messages.
std::string techniqueNames();
std::string drawModeNames();

} // namespace render
