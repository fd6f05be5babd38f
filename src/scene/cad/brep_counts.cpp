// brep_counts.cpp - section counts of BREP text against the bytes left (brep_counts.h).
#include "scene/cad/brep_counts.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <utility>

namespace scene {

std::optional<std::string> implausibleBrepCount(std::istream& in, uint64_t fileBytes) {
    // The sections of Open CASCADE's BREP text (versions 1 to 3) and what their entries are.
    static constexpr std::array<std::pair<std::string_view, std::string_view>, 9> sections{{
        {"Locations", "locations"},
        {"Curve2ds", "2D curves"},
        {"Curves", "curves"},
        {"Polygon3D", "3D polygons"},
        {"PolygonOnTriangulations", "polygons on triangulations"},
        {"Polygon2D", "2D polygons"},
        {"Surfaces", "surfaces"},
        {"Triangulations", "triangulations"},
        {"TShapes", "shapes"},
    }};
    std::string line;
    uint64_t read = 0;
    std::optional<uint64_t> shapes; // the TShapes count, once seen
    uint64_t shapeEnds = 0;         // the '*' after it: each shape's sub-shape list ends in one
    while (std::getline(in, line)) {
        read += line.size() + 1;
        if (shapes) {
            shapeEnds += uint64_t(std::count(line.begin(), line.end(), '*'));
            continue;
        }
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
        const size_t space = line.find(' ');
        if (space == std::string::npos) continue;
        const std::string_view word(line.data(), space);
        for (const auto& [name, what] : sections) {
            if (word != name) continue;
            const char* first = line.data() + space + 1;
            const char* last = line.data() + line.size();
            uint64_t count = 0;
            const auto [end, error] = std::from_chars(first, last, count);
            if (end != last || first == last) break; // not a count line
            const uint64_t left = fileBytes > read ? fileBytes - read : 0;
            if (error == std::errc::result_out_of_range || count > left / 2)
                return "its header announces " + std::string(first, last) + " " +
                       std::string(what) + ", more than the " + std::to_string(left) +
                       " bytes after it can hold (a damaged or truncated file)";
            if (name == "TShapes") shapes = count;
            break;
        }
    }
    // A shorter list leaves Open CASCADE's shape reader looping on the stream's end, adding
    // sub-shapes until memory runs out (seen under AddressSanitizer; which way it goes depends
    // on an uninitialised value in the reader).
    if (shapes && shapeEnds < *shapes)
        return "its header announces " + std::to_string(*shapes) + " shapes, but only " +
               std::to_string(shapeEnds) + " end in the file (a damaged or truncated file)";
    return std::nullopt;
}

} // namespace scene
