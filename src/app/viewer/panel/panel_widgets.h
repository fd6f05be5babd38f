// panel_widgets.h - how the panel lays out labels so none is clipped at any width from its
// narrowest (320 px): a combo's or slider's label beside it where both fit, else on a line
// of its own above it; rows of small widgets wrapped; long single-line names elided with the
// whole text in a tooltip. Free functions over ImGui.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace app {

// Before a combo, slider or input labelled `label`: sets the next item's width and returns
// the label to give it ("##label" when the label went on its own line above).
std::string fitLabel(const char* label);

// Before the next of several widgets on one row, `width` wide: on the same row when it fits,
// else on the next.
void sameLineIfFits(float width);

// A checkbox's width with its label.
float checkboxWidth(const char* label);

// `text` in at most `width` pixels: cut with "..." where it is longer.
std::string elided(const std::string& text, float width);

// Prose and paths wrapped a space short of the edge: where a word ends just at the edge ImGui
// 1.86 counts the blank after it in the line's width, past the edge. A word wider than the
// panel (a path) breaks inside; lines of numbers use textWrappedAtSpaces instead.
void wrappedLine(const std::string& text);
// Text wrapped only at its blanks, never inside a word: ImGui's TextWrapped also breaks after
// '.' and ',', which cuts "-49.99" into "-49." and "99". A word wider than the panel keeps its
// line (clipped) whole; the first line keeps its leading blanks (an indent).
void textWrappedAtSpaces(const std::string& text);
// The same, printf-style: lines of numbers ("Render GPU [ms]  0.123").
void textWrappedAtSpacesf(const char* format, ...) __attribute__((format(printf, 1, 2)));
// Its lines for `width`, each word measured by `widthOf` (the text's pixels).
std::vector<std::string_view> wrapAtSpaces(std::string_view text, float width,
                                           const std::function<float(std::string_view)>& widthOf);

// Wrapped text in the disabled colour.
void textDisabledWrapped(const char* text);

} // namespace app
