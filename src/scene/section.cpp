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

bool SectionPlane::keeps(const glm::dvec3& p, const glm::dvec3& normal, double tolerance) const {
    const glm::dvec4 e = equation();
    const double distance = glm::dot(e, glm::dvec4(p, 1.0));
    const double along = glm::dot(glm::dvec3(e), normal);
    // Strictly above: a plane that is off, or a normal of 0, is never parallel.
    const bool inPlane = std::abs(distance) <= tolerance &&
                         std::abs(along) > gpu::SECTION_PARALLEL_COS * glm::length(normal);
    return inPlane ? along > 0.0 : distance <= 0.0;
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

bool Section::keeps(const glm::dvec3& p, const glm::dvec3& normal, double tolerance) const {
    for (const SectionPlane& plane : planes)
        if (!plane.keeps(p, normal, tolerance)) return false;
    return true;
}

double inPlaneTolerance(double reach) {
    // 64 float roundings (2^-17): a vertex placed and compared with a plane takes a few.
    return std::ldexp(reach, -17);
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

SectionPlane planeAtFace(const SurfaceInfo& face, bool flip) {
    SectionPlane plane;
    plane.on = true;
    plane.normal = face.normal;
    plane.offset = face.d;
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
