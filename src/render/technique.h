// technique.h - the part-ID techniques and per-draw modes as data. Adding a technique means
// one entry in techniques() (technique.cpp), its lookup file in shaders/techniques/ if it
// needs a new one, and its name in the test lists; nothing else switches on technique names.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "scene/part_data.h"

namespace render {

// One draw call: a range of parts of one object's geometry (scene/part_data.h).
using DrawItem = scene::DrawRange;

// The ID data a technique's shaders read (scene/part_data.h builds each).
enum class IdBuffer {
    None,                // the draw names its part
    TrianglePartIds,     // part index per triangle
    PartTriangleCounts,  // triangle count per part, padded for the search loop
    PartTriangleOffsets, // running triangle offset per part
};

enum class DrawSplit { PerPart, PerObject, PerBatch };

// Where the part lookup runs: the fragment shader, or a geometry shader once per triangle.
// None: no part ID at all, the benchmark's reference floor (no-id).
enum class LookupStage { Fragment, Geometry, None };

// Parameters of the N-ary search (nsearch-*), compiled into the shader as IDV_NSEARCH_*
// defines, so each set is its own pipeline (the loop unrolls over n - 1 independent loads).
// Defaults: the fastest set of the H100 sweep in docs/benchmarks.md (3, off, 8, 16).
struct NarySearch {
    uint32_t n = 3;           // 3..16: each step reads n - 1 offsets and narrows n-fold
    bool guess = false;       // start where a uniform part size puts the triangle, then widen
    uint32_t linearBelow = 8; // 0..64: scan linearly once the range has at most this many parts
    uint32_t maxSteps = 16;   // 1..64: N-ary steps at most; a linear scan finishes the rest
    bool operator==(const NarySearch&) const = default;
};

struct Technique {
    const char* name;        // as the CLI spells it
    const char* description; // one line for --list-renderers and the panel
    const char* lookupFile;  // defines lookupLocalPart(); included as "technique.glsl" (or null)
    LookupStage stage;
    IdBuffer ids;
    DrawSplit split;
    bool narySearch = false; // reads RenderConfig::nsearch (the IDV_NSEARCH_* defines)
};

// How per-draw parameters reach the shaders.
struct DrawMode {
    const char* name;
    const char* description;
    const char* define;      // IDV_MODE_* set to 1 (the others to 0)
    bool indirect;           // one multi-draw-indirect call per pipeline
    bool drawIndexAttribute; // the draw index comes from an instanced vertex attribute
};

// The part-ID techniques. The no-id reference is not among them (it has no ID image to
// compare); findTechnique() knows it by name.
const std::vector<Technique>& techniques();
const Technique& noIdTechnique();
const std::vector<DrawMode>& drawModes();

// nullptr when there is no such name.
const Technique* findTechnique(const std::string& name);
const DrawMode* findDrawMode(const std::string& name);

// "a, b, c": for usage text and error messages.
std::string techniqueNames();
std::string drawModeNames();

} // namespace render
