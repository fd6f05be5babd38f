// edge_info.h - a CAD part's B-rep edges: what --edge-info and the viewer's edge hover say of
// one (its curve type, exact length from GCPnts_AbscissaPoint, radius, centre and axis of a
// circle or arc, direction of a line), its points for drawing, and which edge lies nearest a
// pixel near the face's boundary. World coordinates, the scene's unit. Free of Open CASCADE
// types.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/inspect.h"
#include "scene/scene.h"

namespace util {
class JsonWriter;
}

namespace scene {

enum class CurveKind : uint8_t { Line, Circle, Ellipse, BSpline, Other };
const char* curveName(CurveKind kind); // "line", "circle", "ellipse", "bspline", "other"

struct EdgeReport {
    EdgeRef ref;
    uint32_t object = 0;
    CurveKind kind = CurveKind::Other;
    double length = 0.0;
    bool closed = false;             // a full circle, a closed spline
    glm::dvec3 start{0.0}, end{0.0}; // its vertices
    glm::dvec3 direction{0.0};       // lines
    double radius = 0.0;             // circles and arcs (diameter = 2 radius)
    glm::dvec3 center{0.0}, axis{0.0};
    std::vector<glm::dvec3> points; // along the edge, for drawing and screen distance
    LengthUnit unit;
    Precision precision; // the scene's, for describeEdge
};

// The edges bounding the part's face (EdgeRefs of that part); empty without a B-rep.
std::vector<EdgeRef> faceEdges(const Scene& scene, uint32_t part);
std::optional<EdgeReport> edgeReport(const Scene& scene, EdgeRef ref);

// How near (pixels) the cursor must come to an edge for --edge-info and the viewer's hover to
// take it: the ID image's face boundary lies within about a pixel of the drawn edge (the
// tessellation's chords and the rasterizer's sample position), so a cursor on the face a couple
// of pixels inside it finds the edge, while a band of 4 still leaves most of a face on screen
// for picking the face itself.
inline constexpr double edgePickPixels = 4.0;

// The edge of `part`'s face (or of a neighbouring face sharing it) drawn nearest the pixel
// `cursor` under `viewProj` (world to clip, double) in a window of `size` pixels, if within
// `maxPixels`; nullopt otherwise.
std::optional<EdgeRef> nearestEdge(const Scene& scene, uint32_t part, const glm::dmat4& viewProj,
                                   glm::dvec2 size, glm::dvec2 cursor, double maxPixels);

// {"part":P,"object":O,"edge":E,"curve":"circle","length":L,"radius":R,"diameter":D,
// "center":[..],"axis":[..],"start":[..],"end":[..],"closed":false,"unit":"mm"} (radius,
// diameter, centre and axis for circles; "direction" for lines).
std::string edgeReportJson(const EdgeReport& report);
// The same members, written into the object `json` has open (--edge-info puts the pixel
// first).
void edgeReportMembers(util::JsonWriter& json, const EdgeReport& report);
// Rounded to the scene's precision, the unit once: "circle Ø 10 mm (r 5), length 31.4159",
// "line, length 20 mm, direction (1, 0, 0)".
std::string describeEdge(const EdgeReport& report);

} // namespace scene
