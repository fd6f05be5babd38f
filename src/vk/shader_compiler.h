// shader_compiler.h - GLSL from shaders/ compiled to SPIR-V at run time with glslang, with
// #include, per-variant #defines and include aliases (how a technique plugs its own code in).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>
#include <vulkan/vulkan.h>

#include "vk/check.h"

namespace vk {

struct ShaderRequest {
    std::string file; // relative to the shader folder, e.g. "scene.frag"
    VkShaderStageFlagBits stage = VK_SHADER_STAGE_VERTEX_BIT;
    std::vector<std::pair<std::string, std::string>> defines;
    // `#include "KEY"` reads the file VALUE instead (both relative to the shader folder).
    std::map<std::string, std::string> includeAliases;

    // "scene.frag [TECHNIQUE_X=1]": for messages and debug names.
    std::string label() const;
};

// A compile error: what() holds "path:line: error: message" lines as glslang reported them.
struct ShaderError : Error {
    using Error::Error;
};

class ShaderCompiler {
  public:
    explicit ShaderCompiler(std::filesystem::path shaderDir);
    ~ShaderCompiler();
    ShaderCompiler(const ShaderCompiler&) = delete;
    ShaderCompiler& operator=(const ShaderCompiler&) = delete;

    const std::filesystem::path& directory() const { return dir_; }
    std::vector<uint32_t> compile(const ShaderRequest& request) const;

    // The folder idview reads shaders from: --shader-dir if given, else shaders/ next to the
    // executable (a bundled copy), else the source tree the binary was built from.
    static std::filesystem::path locate(const std::string& overrideDir);

  private:
    std::filesystem::path dir_;
};

VkShaderModule createShaderModule(VkDevice device, const std::vector<uint32_t>& spirv);

} // namespace vk
