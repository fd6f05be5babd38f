// part_details.cpp - the hovered and selected parts' details, kept (part_details.h).
#include "app/viewer/state/part_details.h"

namespace app {

const PartDetails& PartDetailsCache::get(const scene::Scene& scene, std::optional<uint32_t> part) {
    if (!part) return none_.details;
    for (const Entry& e : entries_)
        if (e.part == part && e.vertices == scene.vertices.data() &&
            e.objects == scene.objects.data() && e.vertexCount == scene.vertices.size() &&
            e.objectCount == scene.objects.size())
            return e.details;
    Entry& e = entries_[next_];
    next_ = (next_ + 1) % entries_.size();
    e = {scene.vertices.data(),
         scene.objects.data(),
         scene.vertices.size(),
         scene.objects.size(),
         part,
         {}};
    e.details.part = scene::describePart(scene, *part);
    if (e.details.part && e.details.part->face) e.details.face = scene::faceReport(scene, *part);
    return e.details;
}

} // namespace app
