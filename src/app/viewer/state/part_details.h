// part_details.h - what the panel and the event lines say of the hovered and selected parts:
// the part (its object's name and path), and for a CAD part its B-rep face (surface type,
// exact area, radius or normal). A face report walks the part's triangles, so each is worked
// out once when the part under the cursor or the selection changes, not every frame.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "scene/face_info.h"
#include "scene/scene.h"

namespace app {

struct PartDetails {
    std::optional<scene::PartInfo> part;
    std::optional<scene::FaceReport> face; // CAD parts: their B-rep face
};

class PartDetailsCache {
  public:
    // The details of `part` in `scene` (none for nullopt or an ID the scene lacks).
    const PartDetails& get(const scene::Scene& scene, std::optional<uint32_t> part);

  private:
    // A scene is told apart by where its arrays lie and how long they are: a new scene is
    // built while the one before still exists, so it never starts at the same addresses; the
    // lengths tell apart copies made after earlier ones were freed.
    struct Entry {
        const void* vertices = nullptr;
        const void* objects = nullptr;
        size_t vertexCount = 0, objectCount = 0;
        std::optional<uint32_t> part;
        PartDetails details;
    };
    std::array<Entry, 2> entries_; // the hovered part and the selected one
    size_t next_ = 0;
    Entry none_;
};

} // namespace app
