// picking.h - what the GPU's picks answer, a frame or two after they were asked: the part under
// the cursor (the hover), the part a click hit, a released box's parts and the visible part
// count. Input asks (a click, a box); each frame the viewer hands the newest completed
// readings here, and what they answer goes into the document. Frames are numbered as the
// viewer's, so a reading older than what it answers is never taken for it.
#pragma once

#include <cstdint>
#include <optional>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "app/viewer/state/document.h"
#include "render/pick.h"

namespace app {

class Picking {
  public:
    // A click released: the pick of frame `frame` (the next) or later decides what it hit,
    // selected at `level` (ViewSettings::selectLevel); `add` for a Ctrl+click (thing B).
    void click(uint64_t frame, uint32_t level, bool add) {
        pendingClick_ = frame;
        pendingLevel_ = level;
        pendingAdd_ = add;
    }
    // A box released, in scene image pixels: its parts come from the ID image of `frame` or
    // later and join the selection as `mode` says.
    void box(const render::PartSetQuery& pixels, SelectMode mode, uint64_t frame) {
        box_ = Box{pixels, mode, frame};
    }
    // Each frame: the pixel it picks (the cursor's over the scene, else nullopt); frame
    // `frame` starts the run of picks that hover and clicks read.
    std::optional<glm::uvec2> pickPixel(std::optional<glm::uvec2> cursor, uint64_t frame);
    // The released box, until its parts have arrived: each frame asks for it.
    std::optional<render::PartSetQuery> boxQuery() const {
        return box_ ? std::optional(box_->pixels) : std::nullopt;
    }

    // A click whose pick came: what it hit, at what level.
    struct Click {
        render::PickReading pick;
        uint32_t level = 0;
        bool add = false;
    };
    // The newest completed pick: the hover goes into `document`; a click whose pick this is
    // comes back (a Ctrl+click on empty space is dropped).
    std::optional<Click> readPick(const std::optional<render::PickReading>& pick,
                                  Document& document);
    // The newest completed part sets: the visible count (the query of the whole `extent`)
    // and a released box's parts, selected in `document`. True when the selection changed.
    bool readPartSets(const std::optional<render::PartSetReading>& reading, VkExtent2D extent,
                      Document& document);

    // The newest pick that gave the hover: the wheel zooms toward its point while the cursor
    // is still on its pixel.
    const std::optional<render::PickReading>& hoverPick() const { return hoverPick_; }
    float hoveredDepth() const { return hoverPick_ ? hoverPick_->depth : 0.0f; }
    uint32_t visibleParts() const { return visibleParts_; }
    uint64_t partSetsFrame() const { return visibleFrame_; } // the frame visibleParts is of
    // A click or a box waits for its reading: the loop draws frames until it comes.
    bool waiting() const { return pendingClick_ || box_; }
    // A new scene: readings of frames before `frame` name the old one's parts.
    void forget(uint64_t frame);

  private:
    struct Box {
        render::PartSetQuery pixels;
        SelectMode mode;
        uint64_t since; // the first frame that asks for it
    };
    std::optional<uint64_t> pickingSince_; // first frame of the current run of picks
    std::optional<render::PickReading> hoverPick_;
    std::optional<uint64_t> pendingClick_; // the frame whose pick the click selects from
    uint32_t pendingLevel_ = 0;
    bool pendingAdd_ = false;
    std::optional<Box> box_;
    uint64_t partSetsFrom_ = 0; // the first frame whose part sets are still to be read
    uint64_t visibleFrame_ = 0;
    uint32_t visibleParts_ = 0;
};

} // namespace app
