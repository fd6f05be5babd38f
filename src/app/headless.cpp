// headless.cpp - the frame loop without a window, and image readback.
#include "app/headless.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <optional>
#include <stdexcept>

#include "app/image_io.h"
#include "app/json.h"
#include "app/offscreen.h"
#include "app/scene_source.h"
#include "render/frame_slots.h"
#include "render/renderer.h"
#include "render/targets.h"
#include "render/xray.h"
#include "scene/camera_path.h"
#include "scene/edge_info.h"
#include "scene/explode.h"
#include "scene/face_info.h"
#include "scene/inspect.h"
#include "util/cache_file.h"
#include "util/json_number.h"
#include "vk/check.h"
#include "vk/context.h"
#include "vk/shader_compiler.h"

namespace app {

std::string pickJson(const scene::Scene& scene, const render::PickReading& pick) {
    char head[64];
    std::snprintf(head, sizeof head, "{\"x\":%u,\"y\":%u,", pick.pixel.x, pick.pixel.y);
    const auto info = pick.part ? scene::describePart(scene, *pick.part) : std::nullopt;
    if (!info)
        return std::string(head) + "\"part\":null,\"object\":null,\"local_part\":null,"
                                   "\"name\":null,\"path\":null,\"depth\":null}";
    char ids[128], depth[48];
    std::snprintf(ids, sizeof ids, "\"part\":%u,\"object\":%u,\"local_part\":%u,",
                  info->uniquePartId, info->object, info->localPart);
    // CAD files: the B-rep face (face numbers skip faces that did not triangulate).
    if (info->face)
        std::snprintf(ids + std::strlen(ids), sizeof ids - std::strlen(ids), "\"face\":%u,",
                      *info->face);
    std::snprintf(depth, sizeof depth, ",\"depth\":%.9g}", double(pick.depth));
    return std::string(head) + ids + "\"name\":" + jsonString(info->name) +
           ",\"path\":" + jsonString(info->path) + depth;
}

std::string edgeInfoJson(const scene::Scene& scene, const render::PickReading& pick,
                         const std::optional<scene::EdgeRef>& edge) {
    const std::string head =
        "{\"x\":" + std::to_string(pick.pixel.x) + ",\"y\":" + std::to_string(pick.pixel.y) + ",";
    const auto report = edge ? scene::edgeReport(scene, *edge) : std::nullopt;
    if (report) return head + scene::edgeReportJson(*report).substr(1);
    return head + "\"part\":" + (pick.part ? std::to_string(*pick.part) : std::string("null")) +
           ",\"edge\":null}";
}

std::string measureJson(const std::array<std::optional<glm::dvec3>, 2>& points,
                        const std::array<std::optional<uint32_t>, 2>& parts,
                        const scene::LengthUnit& unit) {
    // Every digit of a double: points far from the origin read back exactly.
    auto point = [](const std::optional<glm::dvec3>& p) {
        return p ? util::jsonVector(*p) : std::string("null");
    };
    const auto& [p0, p1] = points;
    std::string distance = "null";
    std::optional<glm::dvec3> delta;
    if (p0 && p1) {
        delta = *p1 - *p0;
        distance = util::jsonNumber(glm::length(*delta));
    }
    auto part = [&](size_t i) {
        return parts[i] ? std::to_string(*parts[i]) : std::string("null");
    };
    return "{\"p0\":" + point(p0) + ",\"p1\":" + point(p1) + ",\"distance\":" + distance +
           ",\"delta\":" + point(delta) + ",\"parts\":[" + part(0) + "," + part(1) + "]," +
           scene::unitJsonMember(unit) + "}";
}

std::string measureJson(const HeadlessResult& result, const scene::LengthUnit& unit) {
    std::array<std::optional<uint32_t>, 2> parts;
    for (size_t i = 0; i < 2 && i < result.measured.size(); ++i) parts[i] = result.measured[i].part;
    return measureJson(result.measuredPoints, parts, unit);
}

namespace {

// What one frame found in a rectangle: the parts, and their count as the GPU counted it.
struct RectResult {
    scene::PartSet parts;
    uint32_t count;
};

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

} // namespace

std::filesystem::path pipelineCacheFolder(const Options& options) {
    return options.scene.cadCache ? util::cacheFolder() : std::filesystem::path{};
}

void savePipelineCache(const render::Renderer& renderer) {
    if (const std::string error = renderer.driverCache().save(); !error.empty())
        std::fprintf(stderr, "idview: warning: pipeline cache not saved: %s\n", error.c_str());
}

render::FrameParams cameraFrame(const scene::Camera& camera, VkExtent2D extent) {
    render::FrameParams params;
    const double aspect = double(extent.width) / double(extent.height);
    // The GPU works relative to the eye: the view from there has no translation, so the
    // float matrix it gets is as exact wherever the model sits (docs/models.md).
    params.origin = camera.eye;
    params.worldViewProj = camera.viewProjection(aspect);
    params.viewProj = glm::mat4(camera.projection(aspect) * camera.viewFromEye());
    params.eye = glm::vec3(0.0f);
    if (camera.ortho) params.orthoToViewer = glm::normalize(camera.eye - camera.target);
    return params;
}

float explodeAt(const Animation& animation, uint64_t frame) {
    return animation.animate ? scene::explodeLoop(animation.time.value_or(float(frame) / 60))
                             : animation.explode;
}

std::vector<HeadlessResult>
renderHeadlessSequence(const Options& options, const scene::Scene& scene,
                       const scene::Camera& camera,
                       const std::vector<render::RenderSettings>& settings) {
    std::vector<HeadlessResult> results(settings.size());
    vk::Instance instance({options.validation, {}, options.syncValidation});
    {
        Offscreen rig(instance, options);
        vk::Device& device = rig.device;
        render::FrameSlots& slots = rig.slots;
        render::Renderer& renderer = rig.renderer;
        Readback readback(device, rig.extent);
        // The camera of frame `frame` (of the timed frames) along the path, if any.
        const scene::Bounds bounds =
            options.cameraPath == scene::CameraPath::None ? scene::Bounds{} : scene.bounds();
        auto frameCamera = [&](uint32_t frame) {
            return cameraFrame(
                scene::cameraOnPath(options.cameraPath, camera, bounds, frame, options.frames),
                rig.extent);
        };
        // Picks and selections see the last frame's view, which the images hold.
        render::FrameParams params = frameCamera(options.frames - 1);
        uint64_t frameNumber = 0;
        // Waits for the run's first frame, whichever kind it is, to time it.
        std::optional<double> firstFrameMs;
        auto firstFrameDone = [&] {
            if (firstFrameMs) return;
            slots.finish();
            firstFrameMs = msSince(rig.start);
        };
        // One frame with `frameParams`, waited for: headless has nothing else to overlap.
        auto waitedFrame = [&](render::FrameParams frameParams) {
            frameParams.explode = explodeAt(options.animation, frameNumber);
            render::FrameSlot& slot = slots.begin(frameNumber++);
            renderer.record(slot, rig.targets, frameParams);
            slots.submit(slot);
            slots.finish();
            firstFrameDone();
        };
        // One frame that picks `pixel`.
        auto pickFrame = [&](const Options::Pixel& pixel) {
            render::FrameParams pickParams = params;
            pickParams.pickPixel = glm::uvec2(pixel.x, pixel.y);
            waitedFrame(pickParams);
            return *slots.latestPick();
        };
        // One frame that collects the parts in `rect`.
        auto rectFrame = [&](const render::PartSetQuery& rect) {
            render::FrameParams rectParams = params;
            rectParams.partSets = {rect};
            waitedFrame(rectParams);
            const render::PartSetReading& reading = *slots.latestPartSets();
            return RectResult{reading.sets.front(), reading.counts.front()};
        };
        const render::PartSetQuery whole{{0, 0}, {rig.extent.width - 1, rig.extent.height - 1}};
        const scene::PartSet hidden = hiddenParts(options, scene);
        for (size_t c = 0; c < settings.size(); ++c) {
            HeadlessResult& result = results[c];
            result.width = rig.extent.width;
            result.height = rig.extent.height;
            result.deviceName = device.info().name;
            // The same renderer, switched.
            if (c == 0)
                renderer.setScene(scene, settings[c]);
            else
                renderer.configure(scene, settings[c]);
            rig.useMsaa(settings[c].pipeline.msaa);
            result.stats = renderer.stats();
            // X-ray of the configuration before is off until this one's selection is made.
            if (c == 0 || options.xray) renderer.setHidden(hidden);
            scene::PartSet selection(scene.uniquePartCount());
            renderer.setSelection(selection);
            if (options.xray) renderer.setTranslucent(scene, selection);
            params.pickPixel.reset();
            params.partSets.clear();
            for (const auto& pixel : options.selects) {
                result.selected = pickFrame(pixel).part;
                selection.clear();
                if (result.selected) selection.insert(*result.selected);
                renderer.setSelection(selection);
            }
            if (options.selectRect) {
                RectResult rect = rectFrame(*options.selectRect);
                renderer.setSelection(rect.parts);
                selection = rect.parts;
                result.rectParts = std::move(rect.parts);
                result.rectCount = rect.count;
            }
            // The picks and the timed frames see the selection through X-ray.
            if (options.xray) {
                const render::XrayParts xray = render::xrayParts(true, selection, hidden);
                renderer.setHidden(xray.hidden);
                renderer.setTranslucent(scene, xray.translucent);
            }
            for (const auto& pixel : options.picks) {
                result.picks.push_back(pickFrame(pixel));
                result.hovers.push_back(*slots.latestHover());
                params.pickPixel = result.picks.back().pixel;
            }
            // The pick's depth is taken where sample 0 lies (the pixel centre without MSAA).
            if (options.measure)
                for (size_t i = 0; i < 2; ++i) {
                    const render::PickReading pick = pickFrame((*options.measure)[i]);
                    result.measured.push_back(pick);
                    if (pick.part)
                        result.measuredPoints[i] = scene::unprojectPixel(
                            params.worldViewProj, glm::dvec2(rig.extent.width, rig.extent.height),
                            glm::dvec2(pick.pixel) + glm::dvec2(rig.targets->pass().sampleZero()),
                            pick.depth);
                }
            for (const auto& pixel : options.faceInfos)
                result.faceInfoPicks.push_back(pickFrame(pixel));
            for (const auto& pixel : options.edgeInfos) {
                const render::PickReading pick = pickFrame(pixel);
                result.edgeInfoPicks.push_back(pick);
                // The cursor at the pixel's centre, as the viewer's mouse position is.
                result.edgeInfoEdges.push_back(
                    pick.part
                        ? scene::nearestEdge(scene, *pick.part, params.worldViewProj,
                                             glm::dvec2(rig.extent.width, rig.extent.height),
                                             glm::dvec2(pick.pixel) + 0.5, scene::edgePickPixels)
                        : std::nullopt);
            }
            const uint64_t timedBefore = slots.timedFrames();
            for (uint32_t frame = 0; frame < options.frames; ++frame, ++frameNumber) {
                render::FrameSlot& slot = slots.begin(frameNumber);
                params.explode = explodeAt(options.animation, frameNumber);
                const bool lastFrame = frame + 1 == options.frames;
                render::FrameParams frameParams = params;
                if (options.cameraPath != scene::CameraPath::None) {
                    frameParams.setView(frameCamera(frame));
                }
                if (lastFrame && options.visibleParts) frameParams.partSets = {whole};
                renderer.record(slot, rig.targets, frameParams);
                if (lastFrame || options.keepEveryFrame) readback.record(slot.cmd, *rig.targets);
                slots.submit(slot);
                firstFrameDone();
                if (options.keepEveryFrame) {
                    slots.finish();
                    result.frames.push_back({readback.idValues(), readback.colorBytes()});
                }
            }
            slots.finish();
            if (options.visibleParts) {
                const render::PartSetReading& reading = *slots.latestPartSets();
                result.visibleParts = reading.sets.front();
                result.visibleCount = reading.counts.front();
            }
            const auto& gpuMs = slots.gpuMilliseconds(); // the last historyLimit at most
            const size_t timed = std::min<size_t>(slots.timedFrames() - timedBefore, gpuMs.size());
            result.gpuMs.assign(gpuMs.end() - long(timed), gpuMs.end());
            const auto& idPassMs = slots.idPassMilliseconds();
            result.idPassMs.assign(idPassMs.end() - long(timed), idPassMs.end());
            result.frameTimes.assign(slots.frameTimes().end() - long(timed),
                                     slots.frameTimes().end());
            result.cullStats.assign(slots.cullStats().end() - long(timed), slots.cullStats().end());
            result.cullTotals = renderer.cullTotals();
            result.color = readback.colorBytes();
            result.ids = readback.idValues();
            result.pipelineCache = renderer.driverCache().status();
        }
        for (HeadlessResult& result : results) result.firstFrameMs = firstFrameMs.value_or(0.0);
        savePipelineCache(renderer);
    }
    for (HeadlessResult& result : results)
        result.validationMessages = instance.validationMessages();
    return results;
}

HeadlessResult renderHeadless(const Options& options, const scene::Scene& scene,
                              const scene::Camera& camera) {
    return renderHeadlessSequence(options, scene, camera, {options.render}).front();
}

int runHeadless(const Options& options) {
    const LoadedScene loaded = loadScene(options.scene);
    for (const auto& warning : loaded.warnings)
        std::fprintf(stderr, "idview: warning: %s: %s\n", loaded.source.c_str(), warning.c_str());
    // --explode: the GPU draws it from the scene at rest (render/animator.h); what the CPU
    // answers (face reports, measurements, inspection) and the opening view take the objects
    // where they are drawn, bit for bit (scene::explodedScene).
    std::optional<scene::Scene> exploded;
    if (!options.animation.animate && options.animation.explode > 0.0f)
        exploded = scene::explodedScene(loaded.scene, options.animation.explode);
    const scene::Scene& scene = exploded ? *exploded : loaded.scene;
    // Before rendering: a part or object not in the scene ends the run at once.
    const std::vector<std::string> inspection = inspectionJson(options, scene);
    const float aspect = float(options.width) / float(options.height);
    HeadlessResult result = renderHeadless(
        options, loaded.scene, initialCamera(loaded, aspect, options.camera, scene.bounds()));
    const render::PipelineKey& key = options.render.pipeline;

    if (!options.screenshot.empty())
        writePng(options.screenshot, result.width, result.height, result.color);
    if (!options.idImage.empty()) writeIdImage(options.idImage, result.ids);
    if (result.rectParts)
        std::printf("%s\n",
                    partSetJson(*result.rectParts, result.rectCount, options.selectRect).c_str());
    for (const auto& pick : result.picks) std::printf("%s\n", pickJson(scene, pick).c_str());
    if (options.measure) std::printf("%s\n", measureJson(result, scene.unit).c_str());
    for (const auto& pick : result.faceInfoPicks) {
        const auto report = pick.part ? scene::faceReport(scene, *pick.part) : std::nullopt;
        std::printf("%s\n", report ? scene::faceReportJson(*report).c_str() : "{\"part\":null}");
    }
    for (size_t i = 0; i < result.edgeInfoPicks.size(); ++i)
        std::printf("%s\n",
                    edgeInfoJson(scene, result.edgeInfoPicks[i], result.edgeInfoEdges[i]).c_str());
    if (result.visibleParts)
        std::printf("%s\n",
                    partSetJson(*result.visibleParts, result.visibleCount, std::nullopt).c_str());
    for (const std::string& line : inspection) std::printf("%s\n", line.c_str());
    if (options.stats)
        std::printf("%s\n", statsJson(loaded, options.render,
                                      FirstFrame{result.firstFrameMs, result.pipelineCache})
                                .c_str());

    // With JSON lines, stdout carries only them; the summary goes to stderr.
    const bool json = !options.picks.empty() || options.measure || !options.faceInfos.empty() ||
                      !options.edgeInfos.empty() || result.rectParts || result.visibleParts ||
                      options.stats || !inspection.empty();
    // What the last frame drew, culling's counters against their totals.
    const render::CullCounts drawn =
        result.cullStats.empty()
            ? render::CullCounts{}
            : render::countsOf(result.cullStats.back(), key.technique->usesMeshShader());
    std::string meshlets;
    if (result.cullTotals.meshlets)
        meshlets = std::to_string(drawn.meshlets) + " of " +
                   std::to_string(result.cullTotals.meshlets) + " meshlets, ";
    // With levels of detail chosen, the triangles of each level.
    std::string levels;
    if (options.render.lod.errorPixels > 0.0f) {
        levels = " (by level of detail:";
        for (uint64_t t : drawn.levelTriangles) levels.append(" ").append(std::to_string(t));
        levels += ")";
    }
    std::fprintf(json ? stderr : stdout,
                 "idview: %u frames of %ux%u on %s, %s%s + %s, culling %s: %zu draws, %llu "
                 "triangles, %u parts; the last frame drew %llu draws, %s%llu triangles%s; "
                 "scene pass GPU median %.3f ms\n",
                 options.frames, result.width, result.height, result.deviceName.c_str(),
                 key.technique->name, result.stats.gsPassthrough ? " (passthrough)" : "",
                 key.mode->name, render::cullModeName(options.render.culling.mode),
                 result.stats.draws, static_cast<unsigned long long>(scene.drawnTriangleCount()),
                 scene.uniquePartCount(), static_cast<unsigned long long>(drawn.draws),
                 meshlets.c_str(), static_cast<unsigned long long>(drawn.triangles), levels.c_str(),
                 median(result.gpuMs));
    return exitCode(result.validationMessages);
}

scene::PartSet hiddenParts(const Options& options, const scene::Scene& scene) {
    const uint32_t count = scene.uniquePartCount();
    scene::PartSet hidden(count);
    const bool isolate = !options.isolate.empty();
    for (uint32_t id : isolate ? options.isolate : options.hide) {
        if (id >= count)
            throw std::invalid_argument(
                std::string(isolate ? "--isolate" : "--hide") + ": part " + std::to_string(id) +
                " is not in the scene (its parts are 0 to " + std::to_string(count - 1) + ")");
        hidden.insert(id);
    }
    if (isolate) hidden.invert();
    return hidden;
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

std::string partSetJson(const scene::PartSet& parts, uint32_t count,
                        const std::optional<render::PartSetQuery>& rect) {
    std::string json = "{";
    if (rect)
        json += "\"rect\":[" + std::to_string(rect->min.x) + "," + std::to_string(rect->min.y) +
                "," + std::to_string(rect->max.x) + "," + std::to_string(rect->max.y) + "],";
    std::string list;
    // Appended piece by piece: GCC 12 warns (-Wrestrict) on "literal" + to_string() here.
    for (uint32_t id : parts.ids()) {
        if (!list.empty()) list += ',';
        list += std::to_string(id);
    }
    const std::string counted = "\"count\":" + std::to_string(count);
    // --select-rect names the parts first, --visible-parts the count.
    if (rect) return json + "\"parts\":[" + list + "]," + counted + "}";
    return json + counted + ",\"parts\":[" + list + "]}";
}

int exitCode(uint32_t validationMessages) {
    if (validationMessages == 0) return 0;
    std::fprintf(stderr, "idview: the validation layer reported %u messages (see above)\n",
                 validationMessages);
    return 3;
}

} // namespace app
