// section.cpp - section planes: their equations and the flag's text form.
#include "scene/section.h"

#include <cmath>
#include <stdexcept>

namespace scene {

glm::dvec4 SectionPlane::equation(const glm::dvec3& origin) const {
    if (!on) return {0.0, 0.0, 0.0, -1.0};
    const double side = flip ? -1.0 : 1.0;
    return side * glm::dvec4(normal, glm::dot(normal, origin) - offset);
}

bool Section::any() const {
    for (const SectionPlane& p : planes)
        if (p.on) return true;
    return false;
}

bool Section::keeps(const glm::dvec3& p) const {
    for (const SectionPlane& plane : planes)
        if (!plane.keeps(p)) return false;
    return true;
}

bool Section::add(const SectionPlane& plane) {
    for (SectionPlane& slot : planes)
        if (!slot.on) {
            slot = plane;
            return true;
        }
    return false;
}

SectionPlane axisPlane(int axis, double value, bool flip) {
    SectionPlane plane;
    plane.on = true;
    plane.normal = glm::dvec3(0.0);
    plane.normal[axis] = 1.0;
    plane.offset = value;
    plane.flip = flip;
    return plane;
}

SectionPlane parseSectionPlane(const std::string& text) {
    const std::string form = "expects AXIS,VALUE[,flip] with AXIS x, y or z, not '" + text + "'";
    const size_t comma = text.find(',');
    if (comma != 1 || text[0] < 'x' || text[0] > 'z') throw std::invalid_argument(form);
    std::string value = text.substr(2);
    bool flip = false;
    if (const size_t second = value.find(','); second != std::string::npos) {
        if (value.substr(second + 1) != "flip") throw std::invalid_argument(form);
        flip = true;
        value.resize(second);
    }
    double number = 0.0;
    try {
        size_t used = 0;
        number = std::stod(value, &used);
        if (used != value.size() || !std::isfinite(number)) throw std::invalid_argument(form);
    } catch (const std::logic_error&) { // not a number, or out of double's range
        throw std::invalid_argument(form);
    }
    return axisPlane(text[0] - 'x', number, flip);
}

} // namespace scene
