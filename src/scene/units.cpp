// units.cpp - lengths, areas and points with their unit (units.h).
#include "scene/units.h"

#include <cstdio>

#include "util/json_writer.h"

namespace scene {

LengthUnit gltfUnit() {
    return {"m", "glTF is in metres (its specification)"};
}

LengthUnit generatedUnit() {
    return {"", "a generated scene: no physical unit"};
}

namespace {

std::string number(double value, int digits = 6) {
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    return text;
}

// A coordinate gets more digits than a length: a point kilometres from the origin (a building
// at its map position) still shows its centimetres, 458002.426 rather than 458002.
constexpr int coordinateDigits = 9;

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

std::string formatVolume(double value, const LengthUnit& unit) {
    return withUnit(number(value), unit, "\u00b3");
}

std::string formatPoint(glm::dvec3 p, const LengthUnit& unit) {
    // Appended piece by piece: GCC 12 warns (-Wrestrict, falsely) on "(" + std::string.
    std::string text = "(";
    text.append(number(p.x, coordinateDigits))
        .append(", ")
        .append(number(p.y, coordinateDigits))
        .append(", ")
        .append(number(p.z, coordinateDigits));
    return withUnit(text + ")", unit, "");
}

void unitMember(util::JsonWriter& json, const LengthUnit& unit) {
    json.member("unit", unit.symbol.empty() ? std::string("none") : unit.symbol);
}

} // namespace scene
