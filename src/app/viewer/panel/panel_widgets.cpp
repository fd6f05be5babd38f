// panel_widgets.cpp - labels that fit the panel (panel_widgets.h).
#include "app/viewer/panel/panel_widgets.h"

#include <algorithm>
#include <cfloat>
#include <cstdarg>
#include <cstdio>

#include <imgui.h>
#include <imgui_internal.h>

namespace app {
namespace {

// A label column as wide as the common labels, so widgets line up where the panel is wide;
// and the narrowest a slider or combo is still worth using beside its label.
constexpr float labelColumn = 130.0f, narrowestWidget = 150.0f;

} // namespace

std::string fitLabel(const char* label) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float avail = ImGui::GetContentRegionAvail().x;
    const float text = ImGui::CalcTextSize(label, nullptr, true).x + style.ItemInnerSpacing.x;
    const float column = std::max(text, labelColumn);
    if (avail - column >= narrowestWidget) {
        ImGui::SetNextItemWidth(avail - column);
        return label;
    }
    const std::string shown(label, ImGui::FindRenderedTextEnd(label));
    ImGui::TextWrapped("%s", shown.c_str());
    ImGui::SetNextItemWidth(-FLT_MIN);
    return "##" + std::string(label);
}

void sameLineIfFits(float width) {
    ImGui::SameLine();
    if (ImGui::GetContentRegionAvail().x < width) ImGui::NewLine();
}

float checkboxWidth(const char* label) {
    const ImGuiStyle& style = ImGui::GetStyle();
    return ImGui::GetFrameHeight() + style.ItemInnerSpacing.x +
           ImGui::CalcTextSize(label, nullptr, true).x;
}

std::string elided(const std::string& text, float width) {
    if (ImGui::CalcTextSize(text.c_str()).x <= width) return text;
    const float dots = ImGui::CalcTextSize("...").x;
    size_t keep = text.size();
    // Whole UTF-8 characters only: never cut between a lead byte and its continuations.
    while (keep > 0) {
        do --keep;
        while (keep > 0 && (static_cast<unsigned char>(text[keep]) & 0xC0) == 0x80);
        if (ImGui::CalcTextSize(text.c_str(), text.c_str() + keep).x + dots <= width) break;
    }
    return text.substr(0, keep) + "...";
}

std::vector<std::string_view> wrapAtSpaces(std::string_view text, float width,
                                           const std::function<float(std::string_view)>& widthOf) {
    std::vector<std::string_view> lines;
    size_t line = 0;
    do {
        size_t fits = std::string_view::npos; // the end of the last word that fits
        size_t scan = text.find_first_not_of(' ', line);
        while (scan != std::string_view::npos) {
            const size_t wordEnd = std::min(text.find(' ', scan), text.size());
            if (fits != std::string_view::npos &&
                widthOf(text.substr(line, wordEnd - line)) > width)
                break;
            fits = wordEnd;
            scan = text.find_first_not_of(' ', wordEnd);
        }
        const size_t end = fits == std::string_view::npos ? text.size() : fits;
        lines.push_back(text.substr(line, end - line));
        line = std::min(text.find_first_not_of(' ', end), text.size());
    } while (line < text.size());
    return lines;
}

void textWrappedAtSpaces(const std::string& text) {
    const auto widthOf = [](std::string_view s) {
        return ImGui::CalcTextSize(s.data(), s.data() + s.size()).x;
    };
    for (std::string_view line : wrapAtSpaces(text, ImGui::GetContentRegionAvail().x, widthOf))
        ImGui::TextUnformatted(line.data(), line.data() + line.size());
}

void textWrappedAtSpacesf(const char* format, ...) {
    char text[512];
    va_list args;
    va_start(args, format);
    std::vsnprintf(text, sizeof text, format, args);
    va_end(args);
    textWrappedAtSpaces(text);
}

void textDisabledWrapped(const char* text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    wrappedLine(text);
    ImGui::PopStyleColor();
}

void wrappedLine(const std::string& text) {
    ImGui::PushTextWrapPos(ImGui::GetContentRegionMax().x - ImGui::CalcTextSize(" ").x);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
}

} // namespace app
