// standard_view.cpp - the views' table and turning a camera to one.
#include "scene/standard_view.h"

#include <array>
#include <cmath>

namespace scene {
namespace {

// FreeCAD's definitions (Gui/Camera.cpp: each view is a rotation of a camera looking down
// its -Z with +Y up; its documentation: front "in the direction of the positive Y axis", top
// "of the negative Z axis", right "of the negative X axis"). Read as the direction from the
// target to the eye and the screen's up: front looks along +Y with Z up, back along -Y,
// right along -X (Y to the right), left along +X, top down -Z with Y up, bottom along +Z
// with -Y up (X to the right in both), and isometric along (-1, 1, -1), from (1, -1, 1): X
// and Y run down to the right and left, Z up.
constexpr std::array<StandardView, 7> views = {{
    {"front", {0, -1, 0}, {0, 0, 1}},
    {"back", {0, 1, 0}, {0, 0, 1}},
    {"left", {-1, 0, 0}, {0, 0, 1}},
    {"right", {1, 0, 0}, {0, 0, 1}},
    {"top", {0, 0, 1}, {0, 1, 0}},
    {"bottom", {0, 0, -1}, {0, -1, 0}},
    {"isometric", {1, -1, 1}, {-1, 1, 2}}, // up: Z less its part along the view
}};

} // namespace

std::span<const StandardView> standardViews() {
    return views;
}

const StandardView* findStandardView(std::string_view name) {
    for (const StandardView& view : views)
        if (name == view.name) return &view;
    return nullptr;
}

std::string standardViewNames() {
    std::string names;
    for (const StandardView& view : views)
        names += (names.empty() ? "" : ", ") + std::string(view.name);
    return names;
}

glm::dmat3 modelFrame(glm::dvec3 modelUp) {
    const glm::dvec3 z = glm::normalize(modelUp);
    // X stays X unless it is the up axis itself; Y completes a right-handed frame.
    const glm::dvec3 helper = std::abs(z.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 x = glm::normalize(helper - glm::dot(helper, z) * z);
    return glm::dmat3(x, glm::cross(z, x), z);
}

Camera turnedTo(const Camera& camera, const StandardView& view, glm::dvec3 modelUp) {
    const glm::dmat3 frame = modelFrame(modelUp);
    Camera turned = camera;
    const double distance = glm::length(camera.eye - camera.target);
    const glm::dvec3 toEye = glm::normalize(frame * glm::dvec3(view.toEye));
    turned.eye = camera.target + toEye * distance;
    // lookAt turns the model's up into the screen's up everywhere but along it, and keeping it
    // keeps what turns about the up axis (--camera-path orbit) doing so; top and bottom look
    // along it and take the screen's up.
    const bool alongUp = std::abs(glm::dot(toEye, frame[2])) > 0.999;
    turned.up = alongUp ? glm::normalize(frame * glm::dvec3(view.screenUp)) : frame[2];
    return turned;
}

} // namespace scene
