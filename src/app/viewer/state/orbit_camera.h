// orbit_camera.h - the viewer's camera: it orbits, pans and zooms around a target point and
// turns that into a scene::Camera whose near and far planes hug the scene's bounding sphere
// as seen from the current eye, so depth precision follows the model whatever its size. It
// turns to the standard views (scene/standard_view.h), straight down and up included, and
// gives either projection. Plain maths (no window, no Vulkan), so it is unit-tested.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "scene/camera.h"
#include "scene/scene.h"
#include "scene/standard_view.h"

namespace app {

// The horizontal span of a window that a panel over [panelLeft, panelRight) (window x
// coordinates) leaves free, as fractions of the width: the wider side of the panel; the whole
// window when there is no panel, or too little is left beside it.
struct FreeSpan {
    float left = 0.0f, right = 1.0f;
};
FreeSpan freeSpan(float windowWidth, float panelLeft, float panelRight);

class OrbitCamera {
  public:
    // Radians of orbit per pixel dragged, and the zoom factor per wheel step.
    static constexpr double radiansPerPixel = 0.005;
    static constexpr double zoomPerStep = 0.85;

    OrbitCamera() = default;
    // Starts from `initial` (its eye, target, up axis and field of view; its up is the
    // model's) around a scene with `bounds`, turned to `opening` if given; Home (resetView)
    // comes back to exactly this view.
    OrbitCamera(const scene::Camera& initial, const scene::Bounds& bounds,
                const scene::StandardView* opening = nullptr);

    // The scene changed size (copies) but the user keeps the view.
    void setBounds(const scene::Bounds& bounds);

    // Turns around the target: x about the up axis, y up and down (never over the pole).
    void orbit(glm::vec2 pixels);
    // Moves eye and target in the view plane so the point under the cursor follows it.
    void pan(glm::vec2 pixels, double viewportHeight);
    // Wheel steps (positive: closer). Scales the distance to the target, so the eye never
    // reaches or crosses it.
    void zoom(double steps);
    // Wheel steps toward `point` (the surface under the cursor): eye and target move along
    // their lines to the point by the distance's factor, a scaling about the point that keeps
    // the view direction, so the point projects to the same pixel in either projection (an
    // orthographic view's height follows the distance). The target comes closer to the point
    // on each step, so the next orbit turns around the region the user zoomed into.
    void zoomToward(glm::dvec3 point, double steps);
    // Keeps the view direction and frames the whole scene, or `what` (F: the selection), in
    // either projection (scene::fitCamera's distance), inside `span` of the window's width
    // (the area beside the panel): the distance fits that narrower view, and the projection
    // shifts sideways so the target shows in the middle of the span (shift()).
    void fit(double aspect, FreeSpan span = {});
    void fit(const scene::Bounds& what, double aspect, FreeSpan span = {});
    // Turns to a standard view around the target, at the same distance (1, 3, 7, 0).
    void turnTo(const scene::StandardView& view);
    // Back to the initial view (Home), or to the view setHome() kept.
    void resetView();
    // The current view, lens shift included, becomes the one Home comes back to (a model
    // opened fitted beside the panel).
    void setHome();

    glm::dvec3 eye() const;
    glm::dvec3 target() const { return target_; }
    double distance() const { return distance_; }
    const scene::Bounds& bounds() const { return bounds_; }
    // How far right the picture moves, in normalised device coordinates (2 is the window's
    // width): a lens shift set by fit and kept by orbit, pan, zoom and the standard views, so
    // they turn around the target where it shows. Home (resetView) takes it back to 0, or to
    // the one setHome() kept.
    double shift() const { return shift_; }
    // The projection's lens shift as a matrix to apply after the view-projection.
    glm::dmat4 shiftMatrix() const;
    // The camera for this frame, near and far planes fitted to the bounds. `reach` is how
    // far from the centre the scene may extend, in bounding radii (the exploded view's
    // animation: SceneState::explodeReach).
    scene::Camera camera(double reach = 1.0, bool ortho = false) const;

  private:
    glm::dvec3 direction() const;          // unit vector from target to eye
    double zoomFactor(double steps) const; // what `steps` multiply the distance by, clamped
    // The screen's up: the direction's derivative by pitch, defined at the poles too, where
    // the model's up axis is the view direction itself.
    glm::dvec3 viewUp() const;
    void setFrom(const scene::Camera& camera);

    // Orthonormal frame: up_, and a_ x b_ = up_ spanning the horizontal plane.
    glm::dvec3 up_{0, 0, 1}, a_{1, 0, 0}, b_{0, 1, 0};
    glm::dvec3 target_{0.0};
    double distance_ = 10.0;
    double yaw_ = 0.0, pitch_ = 0.0; // radians, pitch in (-pi/2, pi/2)
    double fovY_ = glm::radians(40.0);
    double shift_ = 0.0;
    scene::Bounds bounds_;
    scene::Camera initial_;
    const scene::StandardView* opening_ = nullptr;
    // setHome's view, kept as the orbit's own state: a camera rebuilt from eye and target
    // could not say which way is up on the poles (a top view).
    struct Home {
        glm::dvec3 target;
        double distance, yaw, pitch, shift;
    };
    std::optional<Home> home_;
};

} // namespace app
