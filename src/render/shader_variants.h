// shader_variants.h - the shader compile requests each technique x mode pipeline needs. The
// renderer compiles exactly these, and a test compiles all of them.
#pragma once

#include <vector>

#include "render/technique.h"
#include "vk/shader_compiler.h"

namespace render {

// Vertex stage first, fragment stage last.
std::vector<vk::ShaderRequest> shaderVariants(const Technique& technique, const DrawMode& mode);

// Every request the program can make, over all techniques and modes.
std::vector<vk::ShaderRequest> allShaderVariants();

} // namespace render
