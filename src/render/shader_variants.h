// shader_variants.h - the shader compile requests each technique x mode pipeline needs. The
// renderer compiles exactly these, and a test compiles all of them.
#pragma once

#include <vector>

#include "render/technique.h"
#include "vk/shader_compiler.h"

namespace render {

struct VariantOptions {
    uint32_t searchCount = 16;  // the unrolled loop length of the search techniques
    bool gsPassthrough = false; // VK_NV_geometry_shader_passthrough for the gs techniques
    NarySearch nsearch{};       // the nsearch techniques' parameters
};

// The N-ary search parameter sets allShaderVariants() compiles: the default and the corners
// of each range, so the compile test covers what the flags and the panel can ask for.
std::vector<NarySearch> narySearchTestSets();

// Vertex stage first, then geometry (gs techniques), fragment last.
std::vector<vk::ShaderRequest> shaderVariants(const Technique& technique, const DrawMode& mode,
                                              const VariantOptions& options);

// Every request the program can make: all techniques and modes, every search batch size for
// the search techniques, narySearchTestSets() for the nsearch techniques, and both geometry
// shader forms for the gs techniques.
std::vector<vk::ShaderRequest> allShaderVariants();

} // namespace render
