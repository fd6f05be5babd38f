// standard_view.h - the standard views CAD users know: front, back, left, right, top,
// bottom and isometric, as FreeCAD defines them for its Z-up world, carried over to a
// model of any up axis (glTF's Y-up included). Plain maths, unit-tested.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "scene/camera.h"

namespace scene {

struct StandardView {
    const char* name;
    // In FreeCAD's Z-up frame: from the target to the eye, and the screen's up direction.
    glm::vec3 toEye;
    glm::vec3 screenUp;
};

// Every standard view, in the order help and errors list them.
std::span<const StandardView> standardViews();
const StandardView* findStandardView(std::string_view name); // nullptr for no such view
std::string standardViewNames();                             // "front, back, ...": help, errors

// The model's axes for a model whose up axis is `modelUp`: the columns are the model's
// directions that FreeCAD's X, Y and Z stand for (Z-up: the identity; Y-up: X, -Z, Y).
glm::dmat3 modelFrame(glm::dvec3 modelUp);

// `camera` turned to `view` around its target, at the same distance (so a fitted view stays
// fitted), in a model whose up axis is `modelUp`. Its up vector stays the model's, except
// for top and bottom, which look along it and take the screen's up.
Camera turnedTo(const Camera& camera, const StandardView& view, glm::dvec3 modelUp);

} // namespace scene
