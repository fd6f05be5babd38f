// command_target.h - what a command may change or ask (commands.h): the document (what the
// person did to the model), the live settings, the window's settings and camera, and the
// viewer's few actions of its own (files, the window, loads, undo's event lines). The viewer
// implements it, so the command table knows nothing of the viewer above it.
#pragma once

#include <optional>
#include <string>

#include "app/live_settings.h"
#include "app/viewer/state/document.h"
#include "app/viewer/state/events.h"
#include "app/viewer/state/orbit_camera.h"
#include "app/viewer/state/scene_state.h"
#include "app/viewer/state/view_settings.h"

namespace app {

struct NodeTarget;
struct CensusAsk;

class CommandTarget {
  public:
    virtual ~CommandTarget() = default;

    virtual Document& document() = 0;
    virtual const Document& document() const = 0;
    virtual LiveSettings& settings() = 0; // applied at the start of the next frame
    virtual const LiveSettings& settings() const = 0;
    virtual ViewSettings& view() = 0;
    virtual const ViewSettings& view() const = 0;
    virtual OrbitCamera& camera() = 0;

    virtual const Events& events() const = 0;  // for the commands' event records
    virtual void selectionChanged() const = 0; // tells the event lines
    virtual void partsChanged() const = 0;     // the hidden parts: the same

    // The window and files.
    virtual void toggleHelp() = 0;
    virtual bool helpOpen() const = 0;
    virtual void quit() = 0;
    virtual void open(const std::string& path) = 0; // as a dropped file
    virtual void chooseFile() = 0;
    virtual void focusOpenField() = 0;
    virtual void screenshot(const std::string& path) = 0;
    virtual void screenshotToPictures() = 0;
    virtual void reloadShaders() = 0;
    virtual void resetSettings() = 0;
    virtual bool cancelBox() = 0; // Esc's: a box being dragged; false when none was
    // Loads.
    virtual void cancelLoads() = 0;
    virtual void stopLoads() = 0;
    virtual bool loading() const = 0;
    virtual std::optional<SceneState::Loading> modelLoading() const = 0;
    // The camera.
    virtual void fitView() = 0;
    virtual void turnTo(const scene::StandardView& view) = 0;
    virtual void setOrtho(bool ortho) = 0;
    // The parts.
    virtual void setXray(bool on) = 0;
    virtual void undo() = 0;
    virtual void redo() = 0;
    virtual void toggleMeasure() = 0;
    virtual void selectObjects(const std::string& name, SelectMode mode) = 0;
    virtual bool actOnNode(const NodeTarget& node) = 0;
    // The Visibility section's census (CensusAsk); whether one is running (Esc cancels it).
    virtual void census(const CensusAsk& ask) = 0;
    virtual bool censusRunning() const = 0;
};

} // namespace app
