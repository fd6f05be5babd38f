// history.cpp - the undo and redo steps of hidden parts and section planes.
#include "app/viewer/history.h"

#include <cstdio>

namespace app {

std::string describe(const ShownState& state) {
    uint64_t hash = 1469598103934665603ull; // FNV-1a over the hidden IDs
    for (const uint32_t id : state.hidden.ids())
        for (int byte = 0; byte < 4; ++byte) {
            hash ^= (id >> (8 * byte)) & 0xffu;
            hash *= 1099511628211ull;
        }
    char text[96];
    std::snprintf(text, sizeof text, "hidden %u parts %016llx, section %s", state.hidden.size(),
                  static_cast<unsigned long long>(hash), state.section.any() ? "on" : "off");
    return text;
}

void History::reset(const ShownState& now) {
    undo_.clear();
    redo_.clear();
    current_ = now;
}

bool History::observe(const ShownState& now, bool settled) {
    if (!settled || now == current_) return false;
    undo_.push_back(std::move(current_));
    if (undo_.size() > limit) undo_.erase(undo_.begin());
    redo_.clear();
    current_ = now;
    return true;
}

std::optional<ShownState> History::undo() {
    if (undo_.empty()) return std::nullopt;
    redo_.push_back(std::move(current_));
    current_ = std::move(undo_.back());
    undo_.pop_back();
    return current_;
}

std::optional<ShownState> History::redo() {
    if (redo_.empty()) return std::nullopt;
    undo_.push_back(std::move(current_));
    current_ = std::move(redo_.back());
    redo_.pop_back();
    return current_;
}

} // namespace app
