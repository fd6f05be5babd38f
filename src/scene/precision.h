// precision.h - how finely a scene's lengths are known, and the numbers people read rounded
// to it: Open CASCADE's tolerance for CAD models, a float's resolution at the model's size for
// every model (the viewer's vertices, boxes and picked points are floats). Values below half
// a step read 0, and -0 reads 0. The headless JSON keeps every digit and never comes here.
// Plain C++.
#pragma once

#include <string>

#include <glm/glm.hpp>

namespace scene {

struct Precision {
    // The step lengths and coordinates are rounded to: a power of ten. 0 (a scene no loader
    // set) rounds nothing and shows six significant digits.
    double length = 0.0;
};

// A float's resolution, times the few roundings a length or a box corner goes through.
inline constexpr double floatSteps = 4.0;

// The step for a model whose coordinates reach `size` (the largest magnitude) and whose
// B-rep tolerance is `tolerance` (0 for meshes): the power of ten at or above the larger of
// the tolerance and floatSteps floats at that size.
Precision modelPrecision(double size, double tolerance);

// Bare numbers, rounded: "12.3457", "-50", "0".
std::string lengthText(double value, const Precision& precision);
// An area's and a volume's steps follow from the length's: a square of side L known to s is
// known to 2 L s, a cube to 3 L² s.
std::string areaText(double value, const Precision& precision);
std::string volumeText(double value, const Precision& precision);
// "(1, 2.5, -3)": a coordinate or an offset, each component a length.
std::string pointText(glm::dvec3 p, const Precision& precision);
// A unit vector: components to a millionth, "(0, 0, 1)".
std::string directionText(glm::dvec3 d);
// Degrees, to a ten-thousandth (a millionth of a radian is 6e-5 degrees): "90", "0.0573".
std::string angleText(double degrees);

// `value` rounded to `step` as text, with no trailing zeros and no "-0"; a step of 0 gives six
// significant digits.
std::string rounded(double value, double step);

} // namespace scene
