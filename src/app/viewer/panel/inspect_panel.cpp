// inspect_panel.cpp - the Inspect section and the closest points' overlay (inspect_panel.h).
#include "app/viewer/panel/inspect_panel.h"

#include <imgui.h>

#include "app/viewer/panel/measure_overlay.h"
#include "app/viewer/panel/panel_widgets.h"

namespace app {

void inspectSection(const InspectReport& report) {
    if (report.rows.empty()) {
        ImGui::TextWrapped("Click a part for its size (a solid's volume, area and centre of "
                           "mass at the solid level); Ctrl+click a second for their distance.");
        return;
    }
    // Each component's name once, above its rows: the rows name it through it.
    const std::string* component = nullptr;
    for (const InspectRow& row : report.rows) {
        if (row.component.empty()) { // the unit's heading (inspectRows)
            textDisabledWrapped(row.text.c_str());
            continue;
        }
        if (!component || *component != row.component) {
            component = &row.component;
            textDisabledWrapped(row.component.c_str());
        }
        ImGui::Indent();
        textWrappedAtSpaces(row.text);
        ImGui::Unindent();
    }
    if (report.a && !report.b)
        textDisabledWrapped("Ctrl+click a second thing (B) for the distance from A.");
}

void drawInspect(const InspectReport& report, const glm::dmat4& viewProj, glm::vec2 size,
                 const scene::LengthUnit& unit, const scene::Precision& precision) {
    if (!report.distance) return;
    const scene::DistanceReport& d = *report.distance;
    // The parts are not drawn from: a MeasurePoint's part names nothing here.
    drawMeasure({{d.p0, 0}, {d.p1, 0}}, viewProj, size, unit, precision, inspectColour);
}

} // namespace app
