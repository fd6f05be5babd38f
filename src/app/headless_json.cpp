// headless_json.cpp - the JSON lines a headless run prints (--pick, --edge-info, --measure,
// --select-rect, --visible-parts, --distance, --properties), all through util::JsonWriter.
#include <stdexcept>

#include "app/headless.h"
#include "app/measure_json.h"
#include "scene/edge_info.h"
#include "scene/face_info.h"
#include "scene/inspect.h"
#include "util/json_writer.h"

namespace app {

namespace {

// {"x":X,"y":Y, with the rest of the line to follow.
void openAtPixel(util::JsonWriter& json, const render::PickReading& pick) {
    json.beginObject().member("x", pick.pixel.x).member("y", pick.pixel.y);
}

} // namespace

std::string pickJson(const scene::Scene& scene, const render::PickReading& pick) {
    util::JsonWriter json;
    openAtPixel(json, pick);
    const auto info = pick.part ? scene::describePart(scene, *pick.part) : std::nullopt;
    if (!info) {
        for (const char* name : {"part", "object", "local_part", "name", "path", "depth"})
            json.key(name).null();
        return json.endObject().text();
    }
    json.member("part", info->uniquePartId)
        .member("object", info->object)
        .member("local_part", info->localPart);
    // CAD files: the B-rep face (face numbers skip faces that did not triangulate).
    if (info->face) json.member("face", *info->face);
    // A float's nine significant digits: the depth reads back as the GPU wrote it.
    json.member("name", info->name)
        .member("path", info->path)
        .member("depth", util::Significant{pick.depth, 9});
    return json.endObject().text();
}

std::string faceInfoJson(const scene::Scene& scene, const render::PickReading& pick) {
    if (const auto report = pick.part ? scene::faceReport(scene, *pick.part) : std::nullopt)
        return scene::faceReportJson(*report);
    util::JsonWriter json;
    return json.beginObject().key("part").null().endObject().text();
}

std::string edgeInfoJson(const scene::Scene& scene, const render::PickReading& pick,
                         const std::optional<scene::EdgeRef>& edge) {
    util::JsonWriter json;
    openAtPixel(json, pick);
    if (const auto report = edge ? scene::edgeReport(scene, *edge) : std::nullopt)
        scene::edgeReportMembers(json, *report);
    else
        json.member("part", pick.part).key("edge").null();
    return json.endObject().text();
}

std::string measureJson(const HeadlessResult& result, const scene::LengthUnit& unit) {
    std::array<std::optional<uint32_t>, 2> parts;
    for (size_t i = 0; i < 2 && i < result.measured.size(); ++i) parts[i] = result.measured[i].part;
    return measureJson(result.measuredPoints, parts, unit);
}

std::string partSetJson(const scene::PartSet& parts, uint32_t count,
                        const std::optional<render::PartSetQuery>& rect) {
    util::JsonWriter json;
    json.beginObject();
    // --select-rect names the rectangle and its parts first, --visible-parts the count.
    if (rect)
        json.array("rect",
                   std::vector<uint32_t>{rect->min.x, rect->min.y, rect->max.x, rect->max.y})
            .array("parts", parts.ids())
            .member("count", count);
    else
        json.member("count", count).array("parts", parts.ids());
    return json.endObject().text();
}

std::vector<std::string> inspectionJson(const Options& options, const scene::Scene& scene) {
    std::vector<std::string> lines;
    auto range = [](uint32_t count) {
        return count == 0 ? std::string("it has none") : "0 to " + std::to_string(count - 1);
    };
    if (options.distance) {
        const uint32_t count = scene.uniquePartCount();
        scene::Thing sides[2];
        for (size_t i = 0; i < 2; ++i) {
            const uint32_t id = (*options.distance)[i];
            if (id >= count)
                throw std::invalid_argument("--distance: part " + std::to_string(id) +
                                            " is not in the scene (its parts are " + range(count) +
                                            ")");
            sides[i].parts = {id};
        }
        const auto report = scene::measureDistance(scene, sides[0], sides[1]);
        // In range but without a B-rep face: a face that did not come through the load whole.
        if (!report)
            throw std::invalid_argument("--distance: parts " + std::to_string(sides[0].parts[0]) +
                                        " and " + std::to_string(sides[1].parts[0]) +
                                        " give no distance");
        lines.push_back(scene::distanceJson(*report));
    }
    const uint32_t objects = uint32_t(scene.objects.size());
    if (options.propertiesObject && *options.propertiesObject >= objects)
        throw std::invalid_argument(
            "--properties: object " + std::to_string(*options.propertiesObject) +
            " is not in the scene (its objects are " + range(objects) + ")");
    std::vector<scene::SolidProperties> each;
    for (uint32_t o = 0; o < objects; ++o)
        if (options.propertiesAll || options.propertiesObject == o) {
            each.push_back(*scene::objectProperties(scene, o));
            lines.push_back(scene::propertiesJson(each.back()));
        }
    if (options.propertiesAll)
        lines.push_back(scene::totalPropertiesJson(scene::sumProperties(each)));
    return lines;
}

} // namespace app
