// cli_values.h - reading the values of flags (cli_values.cpp). Each throws UsageError with
// one line that names the flag and the form it expects.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "app/cli.h"
#include "render/pick.h"
#include "render/settings.h"
#include "scene/section.h"

namespace app {

// "a,b,,c" -> {"a", "b", "", "c"}: every item, empty ones included (they are refused later).
std::vector<std::string> commaList(const std::string& text);

uint32_t parseCount(const std::string& flag, const std::string& text, uint32_t min, uint32_t max);
// A number from 0 to `max`; `what` names it in the refusal ("a number", "seconds").
float parseNumber(const std::string& flag, const std::string& text, float max, const char* what);
float parseFraction(const std::string& flag, const std::string& text); // 0 to 1
void parseSize(const std::string& text, Options& o);                   // WIDTHxHEIGHT
scene::CensusSpec parseCensus(const std::string& text);                // VIEWSxSIZE
std::array<int, 2> parseWindowPos(const std::string& text);            // X,Y (may be < 0)
uint32_t parseRange(const std::string& flag, const std::string& text, render::Range range);
bool parseOnOff(const std::string& flag, const std::string& text);
Options::Pixel parsePixel(const std::string& flag, const std::string& text); // X,Y
// "4,7,12": whole numbers from 0 to `max`; unique part IDs.
std::vector<uint32_t> parseCounts(const std::string& flag, const std::string& text, uint32_t max);
std::vector<uint32_t> parseIds(const std::string& flag, const std::string& text);
render::PartSetQuery parseRect(const std::string& flag, const std::string& text); // X0,Y0,X1,Y1
std::array<Options::Pixel, 2> parseMeasure(const std::string& text);
std::array<uint32_t, 2> parseDistance(const std::string& text); // A,B: two unique part IDs
// --section AXIS,VALUE[,flip]: into the first free plane; more than the planes are refused.
void addSectionPlane(scene::Section& section, const std::string& text);
// A model argument as a path: a file:// URI (a file manager's or launcher's %u, a
// thumbnailer's %i) decoded, anything else as given.
std::string modelPath(const std::string& argument);
// "RRGGBB" in hex, as displayed, and back.
glm::vec3 parseColor(const std::string& flag, const std::string& text);
std::string hexColor(glm::vec3 color);

} // namespace app
