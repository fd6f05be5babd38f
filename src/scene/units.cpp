// units.cpp - lengths, areas and points with their unit (units.h).
#include "scene/units.h"

#include "util/json_writer.h"

namespace scene {

LengthUnit gltfUnit() {
    return {"m", "glTF is in metres (its specification)"};
}

LengthUnit generatedUnit() {
    return {"", "a generated scene: no physical unit"};
}

namespace {

std::string withUnit(const std::string& number, const LengthUnit& unit, const char* power) {
    if (unit.symbol.empty()) return number;
    return number + " " + unit.symbol + power;
}

} // namespace

std::string unitHeading(const LengthUnit& unit) {
    return unit.symbol.empty() ? "lengths: no unit" : "lengths in " + unit.symbol;
}

std::string formatLength(double value, const LengthUnit& unit, const Precision& precision) {
    return withUnit(lengthText(value, precision), unit, "");
}

std::string formatArea(double value, const LengthUnit& unit, const Precision& precision) {
    return withUnit(areaText(value, precision), unit, "\u00b2");
}

std::string formatVolume(double value, const LengthUnit& unit, const Precision& precision) {
    return withUnit(volumeText(value, precision), unit, "\u00b3");
}

std::string formatPoint(glm::dvec3 p, const LengthUnit& unit, const Precision& precision) {
    return withUnit(pointText(p, precision), unit, "");
}

void unitMember(util::JsonWriter& json, const LengthUnit& unit) {
    json.member("unit", unit.symbol.empty() ? std::string("none") : unit.symbol);
}

} // namespace scene
