// shader_variants.h - the shader compile requests each pipeline key needs. The renderer
// compiles exactly these, and a test compiles all of them.
#pragma once

#include <vector>

#include "render/settings.h"
#include "vk/shader_compiler.h"

namespace render {

// The N-ary search parameter sets allShaderVariants() compiles: the default and the corners
// of each range, so the compile test covers what the flags and the panel can ask for.
std::vector<NarySearch> narySearchTestSets();

// For an effective key (PipelineKey::effective): vertex stage first, then geometry (gs
// techniques), fragment last.
std::vector<vk::ShaderRequest> shaderVariants(const PipelineKey& key);

// The effective keys of every pipeline the program can ask for, at one sample count: every
// technique and mode, each search batch in its range for the search techniques,
// narySearchTestSets() for the nsearch techniques, and both geometry shader forms for the gs
// techniques.
std::vector<PipelineKey> allPipelineKeys();
std::vector<vk::ShaderRequest> allShaderVariants();

} // namespace render
