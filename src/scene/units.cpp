// units.cpp - lengths, areas and points with their unit (units.h).
#include "scene/units.h"

#include <cstdio>

namespace scene {

LengthUnit gltfUnit() {
    return {"m", "glTF is in metres (its specification)"};
}

LengthUnit generatedUnit() {
    return {"", "a generated scene: no physical unit"};
}

namespace {

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

std::string withUnit(const std::string& number, const LengthUnit& unit, const char* power) {
    if (unit.symbol.empty()) return number + " (no unit)";
    return number + " " + unit.symbol + power;
}

} // namespace

std::string formatLength(double value, const LengthUnit& unit) {
    return withUnit(number(value), unit, "");
}

std::string formatArea(double value, const LengthUnit& unit) {
    return withUnit(number(value), unit, "\u00b2");
}

std::string formatPoint(glm::dvec3 p, const LengthUnit& unit) {
    // Appended piece by piece: GCC 12 warns (-Wrestrict, falsely) on "(" + std::string.
    std::string text = "(";
    text.append(number(p.x)).append(", ").append(number(p.y)).append(", ").append(number(p.z));
    return withUnit(text + ")", unit, "");
}

std::string unitJsonMember(const LengthUnit& unit) {
    return "\"unit\":\"" + (unit.symbol.empty() ? std::string("none") : unit.symbol) + "\"";
}

} // namespace scene
