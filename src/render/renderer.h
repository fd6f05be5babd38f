// renderer.h - draws a scene into the scene pass with one part-ID technique and per-draw
// mode. Pipelines, draw lists, ID, per-draw and indirect buffers are built when the scene,
// technique, mode or search batch changes, never per frame; record() only writes commands.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "render/animator.h"
#include "render/draw_list.h"
#include "render/frame_slots.h"
#include "render/scene_gpu.h"
#include "render/targets.h"
#include "render/technique.h"
#include "vk/shader_compiler.h"

namespace render {

struct FrameParams {
    glm::mat4 viewProj{1.0f};
    glm::vec3 eye{0.0f};
    float partColorWeight = 0.5f;
    bool colorizeDraws = false;
    bool ignoreMaterials = false; // one neutral grey for every object: only part colours show
    float time = 0.0f;            // seconds; drives the blink of the hovered part
    // The pixel (top-left origin) whose nearest part this frame picks; the result reaches
    // FrameSlots::latestPick() and, on the GPU, the next frame's hover highlight.
    std::optional<glm::uvec2> pickPixel;
    uint32_t selectedPart = gpu::BACKGROUND_ID; // drawn with the steady highlight
    float explode = 0.0f; // exploded view, 0 (at rest) to 1; see render/animator.h
};

struct RenderConfig {
    const Technique* technique = nullptr;
    const DrawMode* mode = nullptr;
    uint32_t searchBatch = 16;
    bool sortDraws = true;
    bool gsPassthrough = true; // used where the device offers VK_NV_geometry_shader_passthrough
    NarySearch nsearch{};      // nsearch techniques: compiled in, so a change rebuilds the pipeline
    float visible = 1.0f;      // draw the first ceil(visible * objects) objects (DrawOptions)
};

class Renderer {
  public:
    Renderer(vk::Device& device, const vk::ShaderCompiler& compiler, const ScenePass& pass);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Uploads the scene's geometry, objects and materials; configure() must follow.
    void setScene(const scene::Scene& scene);
    // Builds what `config` needs for `scene`. The pipeline is rebuilt only when its shader
    // variant changes; a compile error throws and leaves the previous configuration working.
    void configure(const scene::Scene& scene, const RenderConfig& config);

    // Compiles the current pipeline again from the shader files (edited while running). A
    // compile error throws vk::ShaderError and the previous pipeline keeps drawing.
    void reloadShaders();

    // Records the scene pass with timestamps around it into the slot's command buffer.
    void record(FrameSlot& slot, const SceneTargets& targets, const FrameParams& params) const;

    const RenderStats& stats() const { return stats_; }

  private:
    struct Variant {
        const Technique* technique = nullptr;
        const DrawMode* mode = nullptr;
        uint32_t searchCount = 0;
        bool passthrough = false;
        NarySearch nsearch{}; // the default for the techniques that do not read it
        bool operator==(const Variant&) const = default;
    };
    struct DrawBuffers {
        vk::Buffer ids, draws, indirect, drawIndices;
    };

    VkPipeline buildPipeline(const Variant& variant) const;
    DrawBuffers uploadDraws(const DrawList& list, const DrawMode& mode) const;
    void destroyDraws(DrawBuffers& buffers) const;
    void recordPushDraws(VkCommandBuffer cmd) const;
    void recordIndirectDraws(VkCommandBuffer cmd) const;
    void recordPickReset(VkCommandBuffer cmd) const;
    void recordPickCopies(VkCommandBuffer cmd, const FrameSlot& slot) const;

    vk::Device& device_;
    const vk::ShaderCompiler& compiler_;
    const ScenePass& pass_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    Variant variant_;
    std::unique_ptr<SceneGpu> sceneGpu_;
    std::unique_ptr<Animator> animator_; // writes sceneGpu_'s world matrices each frame
    DrawList drawList_;
    DrawBuffers drawBuffers_;
    RenderStats stats_;
    vk::Buffer pick_; // gpu::PickData, shared by all frames in flight (ordered by barriers)
};

} // namespace render
