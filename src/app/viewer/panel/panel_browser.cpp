// panel_browser.cpp - the file browser's rows in the panel (panel_browser.h).
#include "app/viewer/panel/panel_browser.h"

#include <algorithm>
#include <cstring>
#include <string>

#include <imgui.h>

#include "app/viewer/panel/panel_widgets.h"
#include "scene/formats.h"

namespace app {
namespace {

// Rows of entries in view: the list keeps this height whatever the folder holds, so the
// panel's rows below it never move while browsing.
constexpr int listRows = 10;

bool pressed(ImGuiKey key) {
    return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key));
}

// The folder, cut at its start when it is too long (its end is what tells folders apart).
void folderRow(FileBrowser& browser) {
    if (ImGui::Button("Up")) browser.up();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the folder above (Backspace in the filter)");
    ImGui::SameLine();
    const std::string& folder = browser.folder();
    const float room = ImGui::GetContentRegionAvail().x;
    std::string shown = folder;
    while (shown.size() > 4 && ImGui::CalcTextSize(shown.c_str()).x > room)
        shown = "..." + shown.substr(std::min(shown.size(), size_t(4)));
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(shown.c_str());
    if (shown != folder && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", folder.c_str());
}

void recentRow(FileBrowser& browser) {
    const auto& recent = browser.recentFolders();
    ImGui::BeginDisabled(recent.empty());
    ImGui::SetNextItemWidth(-FLT_MIN);
    if (ImGui::BeginCombo("##recent folders", "recent folders")) {
        for (const std::string& folder : recent)
            if (ImGui::Selectable(folder.c_str())) browser.goTo(folder);
        ImGui::EndCombo();
    }
    ImGui::EndDisabled();
}

// The filter takes the keys while the browser is open: typing narrows the entries (or gives
// a path), the arrows move the highlight, Enter opens it, Backspace on nothing goes up, Esc
// closes the browser.
FileBrowser::Outcome filterRow(FileBrowser& browser, bool& focus, bool& close) {
    char text[512] = {};
    std::strncpy(text, browser.filterText().c_str(), sizeof text - 1);
    if (std::exchange(focus, false)) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(-FLT_MIN);
    const bool enter =
        ImGui::InputTextWithHint("##browse", "filter, or type a path; Enter opens", text,
                                 sizeof text, ImGuiInputTextFlags_EnterReturnsTrue);
    const bool active = ImGui::IsItemActive();
    if (browser.filterText() != text) {
        browser.filterText() = text;
        browser.filterChanged();
    }
    FileBrowser::Outcome outcome;
    if (enter) {
        outcome = browser.activate();
        focus = !outcome.open; // entering a folder: the keys stay with the filter
    } else if (active || ImGui::IsItemDeactivated()) {
        if (pressed(ImGuiKey_UpArrow)) browser.move(-1);
        if (pressed(ImGuiKey_DownArrow)) browser.move(1);
        if (pressed(ImGuiKey_Backspace) && browser.filterText().empty() && !text[0]) {
            browser.up();
            focus = true;
        }
        close = pressed(ImGuiKey_Escape);
    }
    return outcome;
}

// The file_browser record of a listing: the folder, how many entries show of how many, the
// first names (folders end in "/") and the highlighted one.
void listing(util::JsonWriter& json, const FileBrowser& browser) {
    const auto& shown = browser.shown();
    json.member("state", "listing").member("folder", browser.folder());
    json.member("shown", shown.size()).member("of", browser.entryCount());
    json.beginArray("entries");
    for (size_t i = 0; i < shown.size() && i < 12; ++i)
        json.value(shown[i].name + (shown[i].folder ? "/" : ""));
    json.endArray().member("highlighted", shown.empty()
                                              ? std::nullopt
                                              : std::optional(shown[browser.highlighted()].name));
}

FileBrowser::Outcome entryList(FileBrowser& browser, bool keysMoved) {
    FileBrowser::Outcome outcome;
    const float height = ImGui::GetTextLineHeightWithSpacing() * float(listRows) +
                         ImGui::GetStyle().FramePadding.y * 2.0f;
    if (!ImGui::BeginListBox("##entries", ImVec2(-FLT_MIN, height))) return outcome;
    const auto shown = browser.shown(); // activating changes the list: iterate a copy
    for (size_t i = 0; i < shown.size(); ++i) {
        const std::string label = shown[i].name + (shown[i].folder ? "/" : "");
        const bool lit = i == browser.highlighted();
        ImGui::PushID(int(i));
        if (ImGui::Selectable(label.c_str(), lit, ImGuiSelectableFlags_AllowDoubleClick)) {
            browser.highlight(i);
            if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) outcome = browser.activate(i);
        }
        if (lit && keysMoved) ImGui::SetScrollHereY();
        ImGui::PopID();
        if (outcome.open || browser.shown() != shown) break;
    }
    ImGui::EndListBox();
    return outcome;
}

} // namespace

void drawFileBrowser(std::optional<FileBrowser>& browser, PanelActions& actions,
                     const Events* events) {
    if (!browser) return;
    ImGui::PushID("file browser");
    ImGui::Separator();
    ImGui::TextUnformatted("Open a model");
    folderRow(*browser);
    recentRow(*browser);
    bool close = false;
    const size_t before = browser->highlighted();
    FileBrowser::Outcome outcome = filterRow(*browser, browser->wantsFocus, close);
    if (!outcome.open) {
        const FileBrowser::Outcome clicked = entryList(*browser, browser->highlighted() != before);
        if (clicked.open) outcome = clicked;
    }
    // One line, always there, for what went wrong: the rows below stay put.
    if (!outcome.problem.empty()) browser->note(outcome.problem);
    const std::string& said = !browser->note().empty() ? browser->note() : browser->problem();
    const std::string line = elided(said, ImGui::GetContentRegionAvail().x);
    ImGui::TextDisabled("%s", line.c_str());
    if (line != said && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", said.c_str());
    if (ImGui::Button("Open")) outcome = browser->activate();
    ImGui::SameLine();
    close = ImGui::Button("Cancel") || close;
    ImGui::SameLine();
    textDisabledWrapped(("shows folders and " + scene::extensionList()).c_str());
    ImGui::PopID();
    if (events)
        if (browser->news())
            events->say("file_browser", [&](util::JsonWriter& j) { listing(j, *browser); });
    if (outcome.open) actions.ask({CommandId::Open, *outcome.open});
    if (outcome.open || close) {
        if (events)
            events->say("file_browser", [&](util::JsonWriter& j) {
                j.member("state", outcome.open ? "chose" : "closed").member("path", outcome.open);
            });
        browser.reset();
    }
}

} // namespace app
