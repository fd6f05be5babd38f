// pacer.h - when the viewer draws, and what. With vsync on it draws on change: a frame after
// each window event (and a few more, for the panel to settle and the GPU's readbacks to
// arrive), while a script or a load is under way, and when the hovered part's blink steps;
// otherwise it sleeps in the window's event wait. A frame runs the scene pass only when what
// the scene pass draws changed (SceneKey); hover, blink, selection and edges are composed
// over the images the last scene pass left (render/id_passes.h). With vsync off it draws
// continuously, every frame a scene pass, so GPU timings read as the reference sample's do.
#pragma once

#include <cstdint>
#include <optional>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "render/settings.h"

namespace app {

// Everything the scene pass's picture depends on. Equal keys draw equal images.
struct SceneKey {
    glm::dvec3 origin{0.0}; // what viewProj and the objects' matrices are relative to
    glm::mat4 viewProj{1.0f};
    glm::vec4 eye{0.0f}; // position, or the direction to the viewer (w 0) in orthographic
    float explode = 0.0f;
    const void* targets = nullptr; // the images rendered into (size, MSAA)
    uint64_t renderer = 0;         // render::Renderer::changes(): scene, hidden parts, shaders
    VkPipeline pipeline = VK_NULL_HANDLE;
    render::RenderSettings settings; // but for edges, which are composed
    bool operator==(const SceneKey&) const = default;
};

// What asks for frames at the moment `now` (seconds since the viewer started).
struct FrameWants {
    double now = 0.0;
    uint64_t events = 0;              // Window::events()
    bool continuous = false;          // vsync off
    bool busy = false;                // script steps, a click or a box waiting for its frame
    bool loading = false;             // a model opening or a pipeline being built: progress shows
    bool hovering = false;            // a part under the cursor: its blink steps
    std::optional<double> scriptWake; // seconds until the script's next command
    std::optional<double> changeAt;   // when the picture changes by itself (a notice goes)
};

class FramePacer {
  public:
    // Frames drawn after each event: ImGui settles a hover or a click over two frames, and
    // what the GPU reads back (hovered part, visible parts) arrives two frames later.
    static constexpr int settleFrames = 3;
    // A load's or a build's progress line is drawn this often, in seconds.
    static constexpr double progressInterval = 0.25;

    // Whether a frame is due now.
    bool due(const FrameWants& wants);
    // How long the loop may sleep when no frame is due: nullopt until an event comes.
    std::optional<double> rest(const FrameWants& wants) const;
    // Once a frame is due: whether it needs the scene pass, for a picture keyed `key`.
    bool needsScene(const SceneKey& key, bool continuous) const;
    // The frame was drawn, with the scene pass or composed only.
    void drew(const FrameWants& wants, bool scene, const SceneKey& key);

    uint64_t scenePasses() const { return scenePasses_; }
    uint64_t compositions() const { return compositions_; }

  private:
    std::optional<SceneKey> drawn_; // what the last scene pass drew
    uint64_t seenEvents_ = 0;
    int owed_ = settleFrames; // the first frames draw
    std::optional<double> lastFrame_;
    uint64_t scenePasses_ = 0, compositions_ = 0;
};

} // namespace app
