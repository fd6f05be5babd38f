// shader_compiler.h - GLSL from shaders/ compiled to SPIR-V at run time with glslang, with
// #include, per-variant #defines and include aliases (how a technique plugs its own code in).
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>
#include <vulkan/vulkan.h>

#include "vk/check.h"
#include "vk/handle.h"

namespace vk {

struct ShaderRequest {
    std::string file; // relative to the shader folder, e.g. "scene.frag"
    VkShaderStageFlagBits stage = VK_SHADER_STAGE_VERTEX_BIT;
    std::vector<std::pair<std::string, std::string>> defines;
    // `#include "KEY"` reads the file VALUE instead (both relative to the shader folder).
    std::map<std::string, std::string> includeAliases;

    // "scene.frag [TECHNIQUE_X=1]": for messages and debug names.
    std::string label() const;
    // Everything that makes the SPIR-V differ: file, stage, defines and aliases.
    std::string key() const;
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
    // SPIR-V for the request. Each distinct request is compiled once and remembered, so
    // switching back to a technique costs no glslang run; forget() drops what was kept
    // (shaders edited on disk, the viewer's R). Safe from several threads at once (the
    // renderer builds pipelines on workers).
    std::vector<uint32_t> compile(const ShaderRequest& request) const;
    void forget() const;
    // glslang runs so far, and requests answered from memory (for the panel and the tests).
    uint64_t compilations() const { return compilations_; }
    uint64_t remembered() const { return remembered_; }

    // The folder idview reads shaders from: --shader-dir if given, else shaders/ beside the
    // executable, else installed (../share/idview/shaders), else the source's (util::dataPath).
    static std::filesystem::path locate(const std::string& overrideDir);

  private:
    std::vector<uint32_t> compileNow(const ShaderRequest& request) const;

    std::filesystem::path dir_;
    // One compile at a time, memo and glslang run alike. glslang's authors call parses on
    // several threads safe once InitializeProcess has run (it has, in the constructor), but
    // others met unguarded globals on first use; builds rarely overlap, so nothing is lost.
    mutable std::mutex mutex_;
    mutable std::map<std::string, std::vector<uint32_t>> memo_; // by ShaderRequest::key()
    mutable std::atomic<uint64_t> compilations_ = 0, remembered_ = 0;
};

class Device;
Handle<VkShaderModule> createShaderModule(const Device& device, const std::vector<uint32_t>& spirv,
                                          const std::string& name);

} // namespace vk
