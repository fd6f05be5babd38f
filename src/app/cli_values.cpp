// cli_values.cpp - the values flags take: whole numbers, fractions, pixels, rectangles,
// colours, section planes; each refused in one line that names the flag and the form.
#include "app/cli_values.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace app {

// "a,b,,c" -> {"a", "b", "", "c"}: every item, empty ones included (they are refused later).
std::vector<std::string> commaList(const std::string& text) {
    std::vector<std::string> items;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t comma = std::min(text.find(',', start), text.size());
        items.push_back(text.substr(start, comma - start));
        start = comma + 1;
    }
    return items;
}

uint32_t parseCount(const std::string& flag, const std::string& text, uint32_t min, uint32_t max) {
    uint32_t value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || value < min || value > max)
        throw UsageError(flag + " expects a whole number from " + std::to_string(min) + " to " +
                         std::to_string(max) + ", not '" + text + "'");
    return value;
}

// A number from 0 to `max`; `what` names it in the refusal ("a number", "seconds").
float parseNumber(const std::string& flag, const std::string& text, float max, const char* what) {
    try {
        size_t used = 0;
        float value = std::stof(text, &used);
        if (used == text.size() && value >= 0.0f && value <= max) return value;
    } catch (const std::exception&) { // not a number at all: the same refusal
    }
    char range[48];
    std::snprintf(range, sizeof range, " from 0 to %.10g", double(max));
    throw UsageError(flag + " expects " + what + range + ", not '" + text + "'");
}

float parseFraction(const std::string& flag, const std::string& text) {
    return parseNumber(flag, text, 1.0f, "a number");
}

void parseSize(const std::string& text, Options& o) {
    auto x = text.find('x');
    if (x == std::string::npos) throw UsageError("--size expects WIDTHxHEIGHT, not '" + text + "'");
    o.width = parseCount("--size width", text.substr(0, x), 1, 16384);
    o.height = parseCount("--size height", text.substr(x + 1), 1, 16384);
}

scene::CensusSpec parseCensus(const std::string& text) {
    const auto x = text.find('x');
    if (x == std::string::npos)
        throw UsageError("--census expects VIEWSxSIZE (e.g. 162x1024), not '" + text + "'");
    return {parseCount("--census views", text.substr(0, x), 1, 100000),
            parseCount("--census size", text.substr(x + 1), 16, 8192)};
}

std::array<int, 2> parseWindowPos(const std::string& text) {
    const std::vector<std::string> items = commaList(text);
    std::array<int, 2> pos{};
    bool good = items.size() == 2;
    for (size_t i = 0; good && i < 2; ++i) {
        const char* end = items[i].data() + items[i].size();
        const auto [stop, error] = std::from_chars(items[i].data(), end, pos[i]);
        // Monitors left of or above the primary one have negative coordinates.
        good =
            error == std::errc() && stop == end && !items[i].empty() && std::abs(pos[i]) < 100000;
    }
    if (!good) throw UsageError("--window-pos expects X,Y in screen pixels, not '" + text + "'");
    return pos;
}

uint32_t parseRange(const std::string& flag, const std::string& text, render::Range range) {
    return parseCount(flag, text, range.min, range.max);
}

bool parseOnOff(const std::string& flag, const std::string& text) {
    if (text != "on" && text != "off")
        throw UsageError(flag + " expects on or off, not '" + text + "'");
    return text == "on";
}

Options::Pixel parsePixel(const std::string& flag, const std::string& text) {
    auto comma = text.find(',');
    if (comma == std::string::npos) throw UsageError(flag + " expects X,Y, not '" + text + "'");
    return {parseCount(flag + " x", text.substr(0, comma), 0, 16383),
            parseCount(flag + " y", text.substr(comma + 1), 0, 16383)};
}

// "4,7,12": whole numbers from 0 to `max`.
std::vector<uint32_t> parseCounts(const std::string& flag, const std::string& text, uint32_t max) {
    std::vector<uint32_t> values;
    for (const std::string& item : commaList(text))
        values.push_back(parseCount(flag, item, 0, max));
    return values;
}

// "4,7,12": unique part IDs.
std::vector<uint32_t> parseIds(const std::string& flag, const std::string& text) {
    return parseCounts(flag, text, 0xFFFFFFFEu);
}

render::PartSetQuery parseRect(const std::string& flag, const std::string& text) {
    const std::vector<uint32_t> corners = parseCounts(flag, text, 16383);
    if (corners.size() != 4) throw UsageError(flag + " expects X0,Y0,X1,Y1, not '" + text + "'");
    return render::spanning({corners[0], corners[1]}, {corners[2], corners[3]});
}

// "X0,Y0,X1,Y1": two pixels, in the order given.
std::array<Options::Pixel, 2> parseMeasure(const std::string& text) {
    const std::vector<uint32_t> v = parseCounts("--measure", text, 16383);
    if (v.size() != 4) throw UsageError("--measure expects X0,Y0,X1,Y1, not '" + text + "'");
    return {Options::Pixel{v[0], v[1]}, Options::Pixel{v[2], v[3]}};
}

std::array<uint32_t, 2> parseDistance(const std::string& text) {
    const std::vector<uint32_t> ids = parseIds("--distance", text);
    if (ids.size() != 2)
        throw UsageError("--distance expects A,B (two unique part IDs), not '" + text + "'");
    return {ids[0], ids[1]};
}

void addSectionPlane(scene::Section& section, const std::string& text) {
    scene::SectionPlane plane;
    try {
        plane = scene::parseSectionPlane(text);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--section ") + e.what());
    }
    if (!section.add(plane))
        throw UsageError("--section is given more than " + std::to_string(scene::maxSectionPlanes) +
                         " times");
}

// "RRGGBB" in hex, as displayed.
glm::vec3 parseColor(const std::string& flag, const std::string& text) {
    uint32_t value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value, 16);
    if (text.size() != 6 || error != std::errc() || end != text.data() + text.size())
        throw UsageError(flag + " expects a colour as RRGGBB in hex, not '" + text + "'");
    return glm::vec3((value >> 16) & 0xFF, (value >> 8) & 0xFF, value & 0xFF) / 255.0f;
}

std::string hexColor(glm::vec3 color) {
    char text[8];
    const glm::uvec3 c = glm::uvec3(glm::round(glm::clamp(color, 0.0f, 1.0f) * 255.0f));
    std::snprintf(text, sizeof text, "%02x%02x%02x", c.r, c.g, c.b);
    return text;
}

std::string modelPath(const std::string& argument) {
    const std::string scheme = "file://";
    if (argument.rfind(scheme, 0) != 0) return argument;
    std::string rest = argument.substr(scheme.size());
    // file://HOST/path: only the local host's files can be opened.
    if (rest.rfind("localhost/", 0) == 0) rest.erase(0, std::string("localhost").size());
    if (rest.empty() || rest[0] != '/')
        throw UsageError("'" + argument + "' is not a local file URI (file:///path)");
    auto hex = [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; };
    std::string path;
    for (size_t i = 0; i < rest.size(); ++i) {
        if (rest[i] == '%' && i + 2 < rest.size() && hex(rest[i + 1]) && hex(rest[i + 2])) {
            path += static_cast<char>(std::stoi(rest.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            path += rest[i];
        }
    }
    return path;
}

} // namespace app
