// camera_path.cpp - orbit and dolly.
#include "scene/camera_path.h"

#include <array>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace scene {
namespace {

struct Named {
    CameraPath path;
    const char* name;
};
constexpr std::array<Named, 3> paths = {
    {{CameraPath::None, "none"}, {CameraPath::Orbit, "orbit"}, {CameraPath::Dolly, "dolly"}}};

} // namespace

const char* cameraPathName(CameraPath path) {
    for (const Named& n : paths)
        if (n.path == path) return n.name;
    return "none";
}

std::optional<CameraPath> findCameraPath(const std::string& name) {
    for (const Named& n : paths)
        if (name == n.name) return n.path;
    return std::nullopt;
}

std::string cameraPathNames() {
    return "orbit, dolly";
}

Camera cameraOnPath(CameraPath path, const Camera& start, const Bounds& bounds, uint32_t frame,
                    uint32_t frames) {
    Camera camera = start;
    const double t = frames ? double(frame % frames) / double(frames) : 0.0;
    if (path == CameraPath::Orbit) {
        // About the up axis through the target: the eye keeps its height and distance.
        const glm::dmat4 turn =
            glm::rotate(glm::dmat4(1.0), 2.0 * glm::pi<double>() * t, glm::normalize(start.up));
        camera.eye = start.target + glm::dvec3(turn * glm::dvec4(start.eye - start.target, 0.0));
    } else if (path == CameraPath::Dolly) {
        // In to the middle of the bounds at half way, then back out, the view direction kept
        // (the target moves along). The distance to the centre shrinks by the same factor
        // every frame, as the wheel zooms, down to a fiftieth of the bounding radius: equal
        // steps as the eye sees them, so the path spends as long among the parts as on its
        // way to them.
        const double depth = 1.0 - std::abs(1.0 - 2.0 * t);
        const glm::dvec3 centre = bounds.center();
        const double from = glm::length(start.eye - centre);
        const double to = 0.02 * std::max(bounds.radius(), 1e-6);
        const double scale = from > to ? std::pow(to / from, depth) : 1.0;
        camera.eye = centre + (start.eye - centre) * scale;
        camera.target = camera.eye + (start.target - start.eye);
    }
    if (path != CameraPath::None) fitPlanes(camera, bounds);
    return camera;
}

} // namespace scene
