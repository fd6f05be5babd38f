// viewer.h - the interactive window: idview without --headless. The Viewer puts together
// the window and presentation (window.h, presenter.h), the scene and its settings
// (scene_state.h), the user's input (input.h) and the panel (panel.h), and runs the frames:
// each one a short recipe of named steps (frame.cpp), when there is something new to show
// (pacer.h): at rest it sleeps in the window's event wait.
#pragma once

#include <chrono>
#include <deque>
#include <optional>
#include <string>

#include "app/live_settings.h"
#include "app/viewer/pacer.h"
#include "app/viewer/panel/edge_hover.h"
#include "app/viewer/panel/measure_overlay.h"
#include "app/viewer/panel/overlays.h"
#include "app/viewer/panel/panel.h"
#include "app/viewer/state/census_export.h"
#include "app/viewer/state/census_state.h"
#include "app/viewer/state/document.h"
#include "app/viewer/state/events.h"
#include "app/viewer/state/inspect_report.h"
#include "app/viewer/state/orbit_camera.h"
#include "app/viewer/state/part_details.h"
#include "app/viewer/state/picking.h"
#include "app/viewer/state/scene_state.h"
#include "app/viewer/window/file_chooser.h"
#include "app/viewer/window/input.h"
#include "app/viewer/window/presenter.h"
#include "app/viewer/window/window.h"
#include "render/frame_slots.h"
#include "vk/shader_compiler.h"
#include "vk/swapchain.h"

namespace app {

struct Options; // cli.h: the command line

// What the viewer reads once, at start, from the command line and the saved settings; all it
// changes while it runs is the LiveSettings it is handed.
struct ViewerStart {
    WindowPlace window; // --size, --window-pos; Viewer::aspect's until the first frame
    std::string device; // --device
    std::string shaderDir;
    bool validation = false, syncValidation = false;
    std::string script;        // --script (script.h)
    bool printEvents = false;  // --print-events: the event lines on stdout (events.h)
    bool savedSettings = true; // read and write saved_settings.h's file (--no-saved-settings)
};

// Opens the window on the options' scene and runs until it is closed (window close button,
// Ctrl+Q, or a script's quit), then keeps its settings, the window's size
// and place, the panel's layout and the recent files for the next run unless
// --no-saved-settings (saved_settings.h, kept_view.h). Returns the exit code: 0, or 3 when the
// validation layer reported anything. Throws vk::Error and friends with a message for people
// (no display, no device that can present, a model that cannot be loaded at start).
int runViewer(const Options& options);

// The InputTarget and CommandTarget functions (input.h, command_target.h) are what input and
// the command table ask of it.
class Viewer final : public InputTarget {
  public:
    Viewer(const ViewerStart& start, const LiveSettings& settings, Window& window,
           vk::Instance& instance, ScriptPlayer script);
    ~Viewer() override;
    Viewer(const Viewer&) = delete;
    Viewer& operator=(const Viewer&) = delete;

    void run();

    // CommandTarget.
    Document& document() override { return document_; }
    const Document& document() const override { return document_; }
    LiveSettings& settings() override {
        return settings_;
    } // applied at the start of the next frame
    const LiveSettings& settings() const override { return settings_; }
    ViewSettings& view() override { return view_; }
    const ViewSettings& view() const override { return view_; }
    OrbitCamera& camera() override { return camera_; }
    const Events& events() const override { return events_; }
    void selectionChanged() const override;
    void partsChanged() const override;
    void toggleHelp() override; // F1, ?: the help overlay
    bool helpOpen() const override { return shell_.help; }
    void quit() override { window_.close(); }
    void open(const std::string& path) override { input_.onDrop(path); }
    // Ctrl+O and the panel's Open...: the desktop's file chooser (file_chooser.h), its choice
    // opened as a dropped file; without one, the panel's file browser (said once).
    void chooseFile() override;
    // Ctrl+L (a location, as GTK's chooser takes one): the panel's open field, ready to type.
    void focusOpenField() override;
    void screenshot(const std::string& path) override { screenshotPath_ = path; }
    void screenshotToPictures() override; // F12: a PNG in the Pictures folder
    void reloadShaders() override;        // R
    // The panel's Reset to defaults: the settings kept between runs back to the viewer's
    // defaults, in the viewer and in the file (saved_settings.h).
    void resetSettings() override;
    bool cancelBox() override { return input_.cancelBox(); }
    void cancelLoads() override { scene_.cancelOpen(); } // the panel's Cancel
    void stopLoads() override { scene_.stopOpen(); }     // the panel's Stop here
    // A dropped model loading, or a file chooser open (what it chooses loads next).
    bool loading() const override { return scene_.loading().has_value() || chooser_.open(); }
    // The model loading, if one is (Esc stops or cancels it: commands.h).
    std::optional<SceneState::Loading> modelLoading() const override { return scene_.loading(); }
    // F: frames the selected parts when there are some, else those not hidden, else the
    // whole scene, in the area beside the panel.
    void fitView() override;
    // The view command (1, 3, 7, 0): a standard view, at the same distance. The ortho command
    // (O): the projection, a setting (LiveSettings::camera).
    void turnTo(const scene::StandardView& view) override;
    void setOrtho(bool ortho) override;
    void setXray(bool on) override; // X
    // Ctrl+Z, Ctrl+Shift+Z or Ctrl+Y: the hidden parts and section planes of a step before
    // or after.
    void undo() override;
    void redo() override;
    void toggleMeasure() override; // M: clicks place points instead of selecting
    // The parts of every object named `name` join the selection as `mode` says.
    void selectObjects(const std::string& name, SelectMode mode) override;
    // The tree node `node` names: its parts selected (or added), hidden or shown, as the
    // panel's tree row does. False when no node has that path.
    bool actOnNode(const NodeTarget& node) override;
    // The Visibility section's census (viewer_census.cpp), Esc's to cancel while it runs.
    void census(const CensusAsk& ask) override;
    bool censusRunning() const override { return census_.running(); }

    // InputTarget.
    void orbit(glm::vec2 delta) override { camera_.orbit(delta); }
    void pan(glm::vec2 delta, float height) override { camera_.pan(delta, height); }
    // The wheel: `steps` toward the surface point under the cursor (the hover's pick, while
    // the cursor is still on its pixel), else toward the orbit target.
    void zoomAtCursor(float steps) override;
    void clicked(bool add, bool twice) override;
    void boxed(glm::dvec2 a, glm::dvec2 b, SelectMode mode) override;
    // The solids a model loading shows so far (the script's `solids N` waits for them).
    uint32_t solidsShown() const override {
        const auto loading = scene_.loading();
        return loading ? loading->solidsShown : 0;
    }
    bool pipelinePending() const override { return scene_.pipelinePending(); }
    // The Inspect panel's answer being worked out (`inspect ready`).
    bool inspecting() const override { return inspect_.computing(); }
    // A census running, a `census here` not counted, an export being written (census-done).
    bool censusBusy() const override { return censusDrawing() || censusExport_.writing(); }
    // The next frame draws everything anew, as after a change: the scene pass, the whole
    // composition and the panel (tests compare what frames at rest show with it).
    void redraw() override { redrawNext_ = true; }
    // The hovered part's blink held at its strong or weak step (tests: a step of the blink
    // they choose), or back on the clock.
    void holdBlink(std::optional<bool> strong) override { blinkHeld_ = strong; }
    // The script's `pipeline hold|release` (Renderer::holdPipelineBuilds) and `inspect`'s.
    void holdPipelineBuilds(bool hold) override { scene_.renderer().holdPipelineBuilds(hold); }
    void holdInspect(bool hold) override { inspect_.hold(hold); }

    float aspect() const;
    void openBrowser(); // the panel's file browser, where the model shown lies

  private:
    using Clock = std::chrono::steady_clock;

    // What asks for frames now, and what the scene pass would draw with `params`.
    FrameWants frameWants() const;
    SceneKey sceneKey(const render::FrameParams& params) const;
    // Before the loop sleeps: one event line with the passes drawn so far.
    void rest();

    // frame.cpp: the steps of one frame.
    void drawFrame(const FrameWants& wants);
    void drawPanel();
    void act(const PanelActions& actions); // the panel's commands and edits; undo steps told
    void applySettings();
    void openDrops();
    void follow(SceneState::Change change);
    void grown();                               // follow: the model loading shows more of itself
    void rebuildTree(bool keepOpen);            // follow: the panel's rows of the scene's tree
    void startClean(SceneState::Change change); // viewer_commands.cpp, from follow
    void drawOverlays();                        // help, empty view, notice; undo steps
    std::optional<EmptyReason> emptyView(uint32_t partCount, uint32_t hidden, bool sectionOn,
                                         std::optional<uint32_t> visible) const;
    void travel(bool forward); // undo (back) or redo, with their event records
    // The parts a click at `level` selects around `part` (scene::partsAround).
    scene::PartSet partsAround(uint32_t part, uint32_t level) const;
    void remember(const std::string& source); // a model that opened: the recent files
    render::FrameParams frameParams(double seconds);
    void explode(); // the CPU's scene and the camera follow the explode setting
    // The camera's reach (OrbitCamera::camera): the camera's bounds hold the scene as the
    // explode slider places it, the animation reaches further (SceneState::explodeReach).
    double reach() { return settings_.animation.animate ? scene_.explodeReach() : 1.0; }
    void showParts();
    void showTint();
    void recordScene(render::FrameSlot& slot, render::FrameParams params, bool scenePass);
    std::optional<VkRect2D> changedTiles() const;
    void saveScreenshot(const std::string& path);
    void updateTitle(double seconds, bool now);
    PanelInfo panelInfo() const;
    double elapsed() const; // seconds since the first frame
    // Seconds of the script's clock: it starts once the model given at start shows (a partial
    // scene of it, or the whole), so that its lines act on a model.
    double scriptSeconds() const;

    const ViewerStart startup_;
    LiveSettings settings_; // the scene, render and animation settings, edited in place
    ViewSettings view_;
    Window& window_;
    Events events_;
    vk::Surface surface_;
    vk::Device device_;
    vk::ShaderCompiler compiler_;
    Presenter presenter_;
    SceneState scene_;
    CensusState census_;       // its pass is used by the frames' `census here` counts
    render::FrameSlots slots_; // after what the frames use: destroyed (and waited for) first
    Document document_;        // what the person has done to the model (document.h)
    Picking picking_;          // the GPU's answers to the hover, clicks and boxes
    Input input_;
    OrbitCamera camera_;
    EdgeHover edgeHover_; // the B-rep edges hovered and selected
    // The Inspect section's report, worked out on its worker when the selection changes; an
    // answer wakes the loop (glfwPostEmptyEvent may be called from any thread).
    Inspector inspect_{&Window::wake};
    FileChooser chooser_;    // Open...: its answer is taken between frames (openDrops)
    bool noChooser_ = false; // neither the portal nor zenity answered: the panel's browser
    void chosen(const ChooserResult& result);
    std::vector<scene::TreeRow> tree_; // the scene's assembly tree, for the panel
    scene::PartSet namedSelection_;    // the selection selectedRow_ was found for
    std::optional<size_t> selectedRow_;
    glm::dmat4 viewProj_{1.0}; // of the newest frame (world): where measure points come from
    mutable PartDetailsCache partDetails_; // the hovered and selected parts, worked out once
    // The view-projections of the last few frames, by frame number: a pick arrives frames
    // after it was taken, and its depth is unprojected with the view it was taken in.
    std::deque<std::pair<uint64_t, glm::dmat4>> drawnViewProj_;
    void keepViewProj(uint64_t frame, const glm::dmat4& viewProj);
    std::optional<glm::dvec3> pointUnderCursor() const; // zoomAtCursor's point
    bool hoverIsCurrent() const; // the hover reading is of the cursor's pixel
    void zoomWhenReady();        // each frame: wheel steps waiting for the hover reading
    void zoomNow(float steps);
    float pendingZoom_ = 0.0f;      // wheel steps waiting
    uint64_t pendingZoomFrame_ = 0; // the frame they started waiting at
    // The part of the window's width beside the panel, where F and a new model fit.
    FreeSpan panelSpan() const;
    void sayFitted() const; // a new model's fit, as an event line

    // Frame timing and the title.
    FramePacer pacer_;
    bool rested_ = false;           // the loop slept since the last frame
    uint64_t tileCompositions_ = 0; // compositions of the hovered part's tiles alone
    bool redrawNext_ = false;
    std::optional<bool> blinkHeld_; // strong (true) or weak
    uint64_t frameNumber_ = 0;
    std::optional<Clock::time_point> start_, scriptStart_;
    std::deque<double> cpuRecordMs_;
    double titleTime_ = 0.0, fps_ = 0.0;
    uint64_t titleFrame_ = 0;
    std::string title_, screenshotPath_;
    // The document's version (Document::version) the renderer last drew from; nullopt: a
    // new scene, which has nothing selected or hidden yet.
    std::optional<uint64_t> drawnVersion_;
    uint64_t drawnSelection_ = 0; // Document::selectionVersion, as the renderer highlights it
    float selectedDepth_ = 0.0f;  // the depth of the click that selected (reversed)
    // A click's pick came: measure mode places a point, else its thing goes into the document.
    void clickAnswered(const Picking::Click& click);
    void measured(const render::PickReading& pick);
    uint32_t saidVisible_ = UINT32_MAX;   // the visible part count last told
    std::optional<uint32_t> saidHovered_; // the hovered part last told
    Shell shell_;                         // the help, undo history and overlays (overlays.h)
    // What a model's first partial scene replaced, for Cancel to bring back with the model
    // drawn before (SceneState::Change::Restored).
    struct Before {
        OrbitCamera camera;
        Selection selection;
        scene::Section section;
    };
    std::optional<Before> before_;
    // The census (viewer_census.cpp).
    uint64_t drawnTint_ = 0; // the census's tintVersion() the renderer draws
    bool tintShown_ = false; // the renderer draws a tint
    bool hereAsked_ = false; // `census here`: the next scene pass's ID image is counted
    // Export seen...: written on its worker (its answer wakes the loop), told when taken.
    CensusExport censusExport_{&Window::wake};
    bool censusDrawing() const { return census_.running() || census_.hereWaiting() || hereAsked_; }
    void exportCensus(const std::string& path);
    void sayExported(const ExportOutcome& outcome);
    void startCensus(scene::CensusSpec spec);
    void cancelCensus();
    void stepCensus();
    void countHere(render::FrameSlot& slot, bool scenePass);
};

} // namespace app
