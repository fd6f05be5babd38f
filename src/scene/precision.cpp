// precision.cpp - numbers rounded to what the model knows (precision.h).
#include "scene/precision.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace scene {
namespace {

// The power of ten at or above `x`; never below 1e-15 (a double's digits end there).
double decadeAtOrAbove(double x) {
    return std::pow(10.0, std::ceil(std::log10(std::max(x, 1e-15))));
}

// A step for a quantity of magnitude `value` known to `spread`, never finer than `floor`.
double stepFor(double spread, double floor) {
    return decadeAtOrAbove(std::max(spread, floor));
}

} // namespace

Precision modelPrecision(double size, double tolerance) {
    const float at = float(std::abs(size));
    const double ulp = double(std::nextafter(at, std::numeric_limits<float>::infinity()) - at);
    return {decadeAtOrAbove(std::max(tolerance, floatSteps * ulp))};
}

std::string rounded(double value, double step) {
    char text[64];
    if (!(step > 0.0) || !std::isfinite(value)) {
        std::snprintf(text, sizeof text, "%.6g", value);
    } else {
        const int decimals = std::max(0, int(std::lround(-std::log10(step))));
        double r = std::round(value / step) * step;
        if (r == 0.0) r = 0.0; // -0 reads 0
        std::snprintf(text, sizeof text, "%.*f", decimals, r);
    }
    std::string s = text;
    if (s.find('.') != std::string::npos && s.find('e') == std::string::npos) {
        s.erase(s.find_last_not_of('0') + 1);
        if (s.back() == '.') s.pop_back();
    }
    return s == "-0" ? "0" : s;
}

std::string lengthText(double value, const Precision& p) {
    return rounded(value, p.length);
}

std::string areaText(double value, const Precision& p) {
    const double s = p.length;
    return rounded(value, s > 0.0 ? stepFor(2.0 * std::sqrt(std::abs(value)) * s, s * s) : 0.0);
}

std::string volumeText(double value, const Precision& p) {
    const double s = p.length;
    const double side = std::cbrt(std::abs(value));
    return rounded(value, s > 0.0 ? stepFor(3.0 * side * side * s, s * s * s) : 0.0);
}

std::string pointText(glm::dvec3 p, const Precision& precision) {
    // Appended piece by piece: GCC 12 warns (-Wrestrict, falsely) on "(" + std::string.
    std::string text = "(";
    text.append(lengthText(p.x, precision))
        .append(", ")
        .append(lengthText(p.y, precision))
        .append(", ")
        .append(lengthText(p.z, precision));
    return text + ")";
}

std::string directionText(glm::dvec3 d) {
    std::string text = "(";
    text.append(rounded(d.x, 1e-6)).append(", ").append(rounded(d.y, 1e-6)).append(", ");
    return text.append(rounded(d.z, 1e-6)) + ")";
}

std::string angleText(double degrees) {
    return rounded(degrees, 1e-4);
}

} // namespace scene
