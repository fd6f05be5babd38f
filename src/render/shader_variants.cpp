// shader_variants.cpp - technique and mode defines combined into compile requests.
#include "render/shader_variants.h"

namespace render {

std::vector<vk::ShaderRequest> shaderVariants(const Technique& technique, const DrawMode& mode) {
    auto defines = technique.defines;
    defines.insert(defines.end(), mode.defines.begin(), mode.defines.end());
    vk::ShaderRequest vertex{"scene.vert", VK_SHADER_STAGE_VERTEX_BIT, defines, {}};
    vk::ShaderRequest fragment{"scene.frag",
                               VK_SHADER_STAGE_FRAGMENT_BIT,
                               defines,
                               {{"technique.glsl", technique.shaderFile}}};
    return {vertex, fragment};
}

std::vector<vk::ShaderRequest> allShaderVariants() {
    std::vector<vk::ShaderRequest> all;
    for (const auto& technique : techniques())
        for (const auto& mode : drawModes()) {
            auto variants = shaderVariants(technique, mode);
            all.insert(all.end(), variants.begin(), variants.end());
        }
    return all;
}

} // namespace render
