// measure.h - the viewer's measure mode (M): a click on a part places a point where the pick's
// depth says the surface is; two points give their distance and dX/dY/dZ, drawn as a line
// with a label; each point's face is described in the panel, and two planar faces give the
// angle between them (and their distance apart where parallel). A third click starts again.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace app {

struct MeasurePoint {
    glm::dvec3 world;
    uint32_t part;
};

class Measure {
  public:
    bool on() const { return on_; }
    void toggle() {
        on_ = !on_;
        points_.clear();
    }
    void add(const MeasurePoint& point) {
        if (points_.size() == 2) points_.clear();
        points_.push_back(point);
    }
    void forget() { points_.clear(); } // the scene changed: its parts are others
    const std::vector<MeasurePoint>& points() const { return points_; }

  private:
    bool on_ = false;
    std::vector<MeasurePoint> points_;
};

// The panel's lines: the unit's heading, each point's part, face and position, then the
// distance and dX/dY/dZ, then the planes' angle (and distance where parallel); every length
// rounded to the scene's precision, bare under the heading.
std::vector<std::string> measureLines(const scene::Scene& scene,
                                      const std::vector<MeasurePoint>& points);

} // namespace app
