// overlays.h - what the viewer draws over the view besides the panel: the help overlay (the
// command table, F1 or ?), a quiet line in the middle of the free area saying why nothing is
// drawn, a short notice (the screenshot's file) and the boxes of solids still loading. The state
// they keep is the Viewer's Shell.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "app/viewer/state/orbit_camera.h"
#include "scene/cad/cad_loader.h"
#include "scene/section.h"

namespace app {

struct Shell {
    bool help = false;      // the help overlay is open
    bool firstModel = true; // the command line's model: its --section stays
    // The frame the hidden parts or planes last changed in (Document::shownVersion): older
    // visible counts are stale.
    uint64_t changedAt = 0, shownVersion = 0;
    std::string empty;             // the reason the event lines last told ("" : something drawn)
    scene::Section countedSection; // the section of the newest fresh visible count
    std::string notice;            // shown until noticeUntil (seconds since the first frame)
    double noticeUntil = 0.0;
};

// Why the view is empty: a word for the event line ("empty: all hidden") and a sentence for
// people. `partCount`: the parts that can show (those with triangles), `hiddenCount` the
// hidden ones of them. `visible`: the visible part count of a frame that shows the current
// hidden parts and section, nullopt when there is none yet or the renderer counts no parts
// (a floor).
struct EmptyReason {
    std::string event, message;
};
std::optional<EmptyReason> whyEmpty(uint32_t partCount, uint32_t hiddenCount, bool sectionOn,
                                    std::optional<uint32_t> visible);

// Each frame, inside the ImGui frame. drawHelp clears `open` when its window is closed.
void drawHelp(bool& open);
void drawCentred(const std::string& text, FreeSpan span, float heightFraction);
// A model shown as it loads: the box of each solid not meshed yet, thin lines under the panel
// (lost ones red), so the assembly's shape shows before its solids; none for an object
// whose parts are all hidden. `viewProj` takes world points to clip space, `size` is the
// window's.
void drawWaitingBoxes(const scene::Scene& scene, const scene::CadPartial& partial,
                      const scene::PartSet& hidden, const glm::dmat4& viewProj, glm::vec2 size);

} // namespace app
