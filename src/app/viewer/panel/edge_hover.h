// edge_hover.h - the B-rep edge under the cursor and the selected one: near a face's boundary
// the nearest edge of the hovered part's face is hovered (scene/edge_info.h), a click while one
// is hovered selects it (Selection keeps both), both are drawn over the scene, and the event
// lines say each change ("edge hovered: part 3 edge 7"). The reports behind them are worked out
// once per change, not every frame.
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "app/viewer/state/document.h"
#include "app/viewer/state/events.h"
#include "scene/edge_info.h"

namespace app {

class EdgeHover {
  public:
    // After the frame's pick: the edge of the hovered part nearest `cursor` (scene image
    // pixels, nullopt off the scene), under the newest frame's `viewProj` (world to clip).
    void update(const scene::Scene& scene, Document& document, std::optional<glm::dvec2> cursor,
                const glm::dmat4& viewProj, glm::dvec2 size);
    // Tells the event lines what changed (hover and selection) and keeps their reports.
    void tell(const scene::Scene& scene, const Selection& selection, const Events& events);
    // The hovered and selected edges over the scene, in window coordinates of `size`.
    void draw(const glm::dmat4& viewProj, glm::vec2 size) const;
    // A new scene: its edges are other edges, even under the same numbers.
    void forget() { *this = EdgeHover(); }

    // What the panel says of each: "edge 7: circle Ø 10 mm (r 5 mm), length 31.4159 mm".
    std::string hoveredLine() const { return line(hovered_); }
    std::string selectedLine() const { return line(selected_); }

  private:
    static std::string line(const std::optional<scene::EdgeReport>& report);
    std::optional<scene::EdgeRef> saidHovered_, saidSelected_;
    std::optional<scene::EdgeReport> hovered_, selected_;
};

} // namespace app
