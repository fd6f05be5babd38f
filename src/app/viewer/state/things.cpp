// things.cpp - the Inspect panel's things A and B: their parts and their names (things.h).
#include "app/viewer/state/things.h"

namespace app {
namespace {

// The object's place in the assembly: its path, else its name, else its number.
std::string objectName(const scene::Scene& scene, uint32_t object) {
    if (object >= scene.objects.size()) return "object " + std::to_string(object);
    const scene::Object& o = scene.objects[object];
    if (!o.path.empty()) return o.path;
    if (!o.name.empty()) return o.name;
    return "object " + std::to_string(object);
}

} // namespace

scene::PartSet Things::parts(uint32_t partCount) const {
    scene::PartSet set(partCount);
    for (const auto* thing : {&a_, &b_}) {
        if (!*thing) continue;
        for (uint32_t part : (*thing)->parts) set.insert(part);
        if ((*thing)->edge) set.insert((*thing)->edge->part);
    }
    return set;
}

scene::Thing makeThing(const scene::Scene& scene, const std::vector<scene::TreeRow>& tree,
                       const scene::PartSet& parts, uint32_t part,
                       std::optional<scene::EdgeRef> edge) {
    scene::Thing thing;
    if (edge) {
        const auto info = scene::describePart(scene, edge->part);
        thing.edge = edge;
        thing.label = (info ? objectName(scene, info->object) : "part " + std::to_string(part)) +
                      " \u00b7 edge " + std::to_string(edge->edge);
        return thing;
    }
    thing.parts = parts.ids();
    const auto info = scene::describePart(scene, part);
    const std::string object =
        info ? objectName(scene, info->object) : "part " + std::to_string(part);
    if (thing.parts.size() <= 1) { // a face of a CAD solid, a part of a mesh
        thing.label = object;
        if (info && info->face)
            thing.label += " \u00b7 face " + std::to_string(*info->face);
        else if (info)
            thing.label += " \u00b7 part " + std::to_string(info->localPart);
        return thing;
    }
    // A solid whose node holds others too (a plate and the bolts under it): its path.
    if (info) {
        const scene::Object& o = scene.objects[info->object];
        const uint32_t count = scene.geometries[o.geometry].partCount;
        if (thing.parts.size() == count && parts.countIn(o.uniquePartOffset, count) == count) {
            thing.label = object;
            return thing;
        }
    }
    if (const auto row = scene::rowOfParts(tree, parts)) {
        const scene::TreeRow& r = tree[*row];
        thing.label = r.path.empty() ? r.label : r.path; // the root's path is ""
        return thing;
    }
    thing.label = object + " (" + std::to_string(thing.parts.size()) + " parts)";
    return thing;
}

std::string thingsLine(const Things& things) {
    auto name = [](const std::optional<scene::Thing>& t) { return t ? t->label : "none"; };
    return name(things.a()) + "|" + name(things.b());
}

} // namespace app
