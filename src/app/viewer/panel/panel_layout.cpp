// panel_layout.cpp - the panel's rows held under the pointer, and its clipping check
// (panel_layout.h). ImGui's SetScrollY applies at the next frame's Begin, as does the blank
// room changed here: both take effect together, so the anchor is off for one frame at most.
#include "app/viewer/panel/panel_layout.h"

#include <algorithm>
#include <cmath>

#include <imgui.h>
#include <imgui_internal.h>

namespace app {

PanelLayout::PanelLayout(PanelLayoutState& state) : state_(state) {
    hovered_ = ImGui::IsWindowHovered(ImGuiHoveredFlags_ChildWindows |
                                      ImGuiHoveredFlags_AllowWhenBlockedByPopup |
                                      ImGuiHoveredFlags_AllowWhenBlockedByActiveItem);
    if (!hovered_) { // nobody points at a row: the rows may settle
        state_.anchor.clear();
        state_.roomAbove = state_.roomBelow = 0.0f;
    }
    scroll_ = ImGui::GetScrollY();
    roomAbove_ = state_.roomAbove;
    if (state_.roomAbove > 0.0f) ImGui::SetCursorPosY(ImGui::GetCursorPosY() + state_.roomAbove);
}

// The items since the last check reached past the right edge: the window's content region
// (WorkRect) is where ImGui clips them. CursorMaxPos grows with every item ImGui lays out,
// labels included, so no widget escapes the check.
void PanelLayout::checkOverflow() {
    ImGuiWindow* window = ImGui::GetCurrentWindow();
    const float limit = window->WorkRect.Max.x;
    if (window->DC.CursorMaxPos.x > limit + 0.5f) {
        const std::string name = marks_.empty() ? std::string("top") : marks_.back().name;
        if (std::find(clipped_.begin(), clipped_.end(), name) == clipped_.end())
            clipped_.push_back(name);
        window->DC.CursorMaxPos.x = limit; // the next group is checked afresh
    }
}

void PanelLayout::checkChild() {
    checkOverflow(); // the child window is the current one here
}

void PanelLayout::mark(const char* name) {
    checkOverflow();
    const float y = ImGui::GetCursorPosY() - state_.roomAbove;
    marks_.push_back({name, y});
    if (!state_.anchor.empty() && state_.anchor == name) shift_ = y - state_.anchorY;
}

void PanelLayout::finish(const Events* events) {
    checkOverflow();
    tell(events); // before the anchor moves on
    float scroll = scroll_;
    float below = state_.roomBelow;
    if (hovered_ && std::abs(shift_) > 0.5f) {
        if (shift_ > 0.0f) { // rows came above the anchor: take back room above, then scroll
            const float take = std::min(state_.roomAbove, shift_);
            state_.roomAbove -= take;
            scroll += shift_ - take;
            // Room below so that the scroll can reach, also once the room above has gone: the
            // farthest ImGui scrolls is the content's height less the window's inside.
            ImGuiWindow* window = ImGui::GetCurrentWindow();
            const float content = window->DC.CursorMaxPos.y - window->DC.CursorStartPos.y - take;
            const float reach =
                content + 2.0f * window->WindowPadding.y - window->InnerRect.GetHeight();
            below = std::max(below, scroll - reach);
        } else { // rows went: scroll up, and where the top is reached, room above
            scroll += shift_;
            if (scroll < 0.0f) {
                state_.roomAbove += -scroll;
                scroll = 0.0f;
            }
        }
        ImGui::SetScrollY(scroll);
    }
    state_.roomBelow = hovered_ ? below : 0.0f;
    if (state_.roomBelow > 0.0f) ImGui::Dummy(ImVec2(1.0f, state_.roomBelow));
    // The anchor for the next frame: the last mark at or above the pointer, where it will be
    // once the scroll and room above set here apply.
    state_.anchor.clear();
    if (hovered_) {
        ImGuiWindow* window = ImGui::GetCurrentWindow();
        const float pointer = ImGui::GetIO().MousePos.y - window->Pos.y + scroll - state_.roomAbove;
        for (const Mark& m : marks_)
            if (m.y <= pointer) {
                state_.anchor = m.name;
                state_.anchorY = m.y;
            }
    }
}

void PanelLayout::tell(const Events* events) {
    if (!events) return;
    const float top = ImGui::GetWindowPos().y + roomAbove_ - scroll_; // content y 0, in the window
    auto at = [&](const Mark& m) { return int(std::lround(top + m.y)); };
    // The text compared with the last told one is the record's own fields.
    auto told = [&](std::string& last, const char* event, auto fields) {
        util::JsonWriter json;
        fields(json.beginObject());
        if (json.endObject().text() == last) return;
        last = json.text();
        events->say(event, fields);
    };
    told(state_.toldRows, "panel_rows", [&](util::JsonWriter& j) {
        j.beginArray("rows");
        for (const Mark& m : marks_)
            j.beginObject().member("name", m.name).member("y", at(m)).endObject();
        j.endArray();
    });
    const Mark* pointer = nullptr;
    for (const Mark& m : marks_)
        if (hovered_ && m.name == state_.anchor) pointer = &m;
    told(state_.toldPointer, "panel_pointer", [&](util::JsonWriter& j) {
        j.member("row", pointer ? std::optional(pointer->name) : std::nullopt);
        j.member("y", pointer ? std::optional(at(*pointer)) : std::nullopt);
    });
    told(state_.told, "panel_width", [&](util::JsonWriter& j) {
        j.member("width", int(std::lround(ImGui::GetWindowWidth()))).array("clipped", clipped_);
    });
}

} // namespace app
