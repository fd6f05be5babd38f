// picking.cpp - the hover, clicks, boxes and visible count from the GPU's readings.
#include "app/viewer/state/picking.h"

namespace app {

std::optional<glm::uvec2> Picking::pickPixel(std::optional<glm::uvec2> cursor, uint64_t frame) {
    if (!cursor)
        pickingSince_.reset();
    else if (!pickingSince_)
        pickingSince_ = frame;
    return cursor;
}

std::optional<Picking::Click> Picking::readPick(const std::optional<render::PickReading>& pick,
                                                Document& document) {
    // Picks arrive a frame or two late; only those since the cursor came over the scene
    // count, so an old pick never shows as the hover after leaving the panel.
    if (!pickingSince_) {
        document.hover(std::nullopt);
        hoverPick_.reset();
        pendingClick_.reset();
        return std::nullopt;
    }
    if (pick && pick->frame >= *pickingSince_) {
        document.hover(pick->part);
        hoverPick_ = pick;
    }
    // A click selects what was under the cursor in the frame after the click.
    if (!pendingClick_ || !pick || pick->frame < *pendingClick_) return std::nullopt;
    pendingClick_.reset();
    if (pendingAdd_ && !pick->part) return std::nullopt; // Ctrl+click on empty space
    return Click{*pick, pendingLevel_, pendingAdd_};
}

bool Picking::readPartSets(const std::optional<render::PartSetReading>& reading, VkExtent2D extent,
                           Document& document) {
    if (!reading || reading->frame < partSetsFrom_) return false;
    partSetsFrom_ = reading->frame + 1;
    const render::PartSetQuery whole{{0, 0}, {extent.width - 1, extent.height - 1}};
    bool changed = false;
    for (size_t i = 0; i < reading->queries.size(); ++i) {
        if (reading->queries[i] == whole) {
            visibleParts_ = reading->counts[i];
            visibleFrame_ = reading->frame;
        }
        if (box_ && reading->frame >= box_->since && reading->queries[i] == box_->pixels) {
            document.select(reading->sets[i], box_->mode);
            box_.reset();
            changed = true;
        }
    }
    return changed;
}

void Picking::forget(uint64_t frame) {
    pendingClick_.reset();
    pickingSince_.reset();
    hoverPick_.reset();
    box_.reset();
    partSetsFrom_ = frame; // earlier frames counted the old scene's parts
    visibleParts_ = 0;
    visibleFrame_ = 0;
}

} // namespace app
