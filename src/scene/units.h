// units.h - the length unit of a scene's coordinates, said once per scene (Scene::unit, set
// where the scene is loaded), and every length, area and point the viewer or the JSON shows
// written through these helpers, so no number leaves without its unit. Plain C++.
#pragma once

#include <string>

#include <glm/glm.hpp>

namespace util {
class JsonWriter;
}

namespace scene {

struct LengthUnit {
    // "mm", "m", "in", ...; "" where the source has no physical unit (BREP files, the
    // procedural and built-in scenes).
    std::string symbol;
    std::string source; // where the unit comes from, for a tooltip and the docs
    bool operator==(const LengthUnit&) const = default;
};

// glTF's specification: metres.
LengthUnit gltfUnit();
// Generated scenes: sizes chosen for the eye, no physical unit.
LengthUnit generatedUnit();

// "12.5 mm", "0.001 m"; six significant digits (what a B-rep's tolerances mean); without a
// unit "12.5 (no unit)".
std::string formatLength(double value, const LengthUnit& unit);
// "628.319 mm²".
std::string formatArea(double value, const LengthUnit& unit);
// "1570.8 mm³".
std::string formatVolume(double value, const LengthUnit& unit);
// "(1, 2.5, -3) mm": a coordinate or an offset vector.
std::string formatPoint(glm::dvec3 p, const LengthUnit& unit);

// The JSON member every object holding lengths carries: "unit":"mm", or "unit":"none".
// Areas in such an object are in the unit squared.
void unitMember(util::JsonWriter& json, const LengthUnit& unit);

} // namespace scene
