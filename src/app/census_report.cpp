// census_report.cpp - what `idview --census` prints and writes: a JSON line per part, the
// CSV of the same, the summary line (see census.h).
#include <cstdio>
#include <stdexcept>

#include "app/census.h"
#include "util/json_writer.h"

namespace app {

std::string censusPartJson(const scene::Scene& scene, const scene::Census& census, uint32_t part) {
    const auto info = scene::describePart(scene, part);
    const scene::CensusPart& counted = census.parts[part];
    util::JsonWriter json;
    json.beginObject()
        .member("part", part)
        .member("object", info->object)
        .member("name", info->name)
        .member("path", info->path)
        .member("pixels", counted.pixels)
        .member("views", counted.views)
        .member("largest_share", util::Significant{census.largestShare(part), 6});
    return json.endObject().text();
}

namespace {

// A CSV field: quoted, with its quotes doubled (RFC 4180), wherever it holds a comma, a
// quote or a line break.
std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) {
        if (c == '"') quoted += '"';
        quoted += c;
    }
    return quoted + '"';
}

} // namespace

void writeCensusCsv(const std::string& path, const scene::Scene& scene,
                    const scene::Census& census) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) throw std::runtime_error(path + ": cannot write the census CSV");
    std::fprintf(file, "part,object,name,path,pixels,views,largest_share\n");
    for (uint32_t part = 0; part < census.parts.size(); ++part) {
        const auto info = scene::describePart(scene, part);
        const scene::CensusPart& counted = census.parts[part];
        std::fprintf(file, "%u,%u,%s,%s,%llu,%u,%.6g\n", part, info->object,
                     csvField(info->name).c_str(), csvField(info->path).c_str(),
                     static_cast<unsigned long long>(counted.pixels), counted.views,
                     census.largestShare(part));
    }
    if (std::fclose(file) != 0) throw std::runtime_error(path + ": cannot write the census CSV");
}

std::string censusSummaryJson(const scene::Census& census, const scene::CensusSummary& sum) {
    const auto share = [&](uint64_t triangles) {
        return util::Significant{sum.triangles ? double(triangles) / double(sum.triangles) : 0.0,
                                 6};
    };
    util::JsonWriter json;
    json.beginObject()
        .beginObject("census")
        .member("views", census.views)
        .member("width", census.width)
        .member("height", census.height)
        .member("ms", util::Fixed{census.ms, 3})
        .endObject()
        .member("parts", sum.parts)
        .member("parts_seen", sum.partsSeen)
        .member("parts_never_seen", sum.partsNeverSeen)
        .member("parts_hidden", sum.partsHidden)
        .member("parts_empty", sum.partsEmpty)
        .member("objects", sum.objects)
        .member("objects_seen", sum.objectsSeen)
        .member("objects_never_seen", sum.objectsNeverSeen)
        .member("triangles", sum.triangles)
        .member("triangles_never_seen", sum.trianglesNeverSeen)
        .member("triangle_share_never_seen", share(sum.trianglesNeverSeen))
        .member("object_triangles_never_seen", sum.objectTrianglesNeverSeen)
        .member("object_triangle_share_never_seen", share(sum.objectTrianglesNeverSeen));
    return json.endObject().text();
}

} // namespace app
