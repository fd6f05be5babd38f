// history.cpp - the undo and redo steps of hidden parts and section planes.
#include "app/viewer/state/history.h"

#include <cstdio>

namespace app {

void shownMembers(util::JsonWriter& json, const ShownState& state) {
    uint64_t hash = 1469598103934665603ull; // FNV-1a over the hidden IDs
    for (const uint32_t id : state.hidden.ids())
        for (int byte = 0; byte < 4; ++byte) {
            hash ^= (id >> (8 * byte)) & 0xffu;
            hash *= 1099511628211ull;
        }
    char hex[24];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    json.member("hidden", state.hidden.size()).member("hidden_hash", hex);
    json.member("section", state.section.any());
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

// Undo and redo are one move: the newest state of `from` becomes the current one, which
// goes onto `to`.
std::optional<ShownState> History::step(std::vector<ShownState>& from,
                                        std::vector<ShownState>& to) {
    if (from.empty()) return std::nullopt;
    to.push_back(std::move(current_));
    current_ = std::move(from.back());
    from.pop_back();
    return current_;
}

std::optional<ShownState> History::undo() {
    return step(undo_, redo_);
}

std::optional<ShownState> History::redo() {
    return step(redo_, undo_);
}

} // namespace app
