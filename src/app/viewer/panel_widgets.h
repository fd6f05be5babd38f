// panel_widgets.h - how the panel lays out labels so none is clipped at any width from its
// narrowest (320 px): a combo's or slider's label beside it where both fit, else on a line
// of its own above it; rows of small widgets wrapped; long single-line names elided with the
// whole text in a tooltip. Free functions over ImGui.
#pragma once

#include <string>

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

// A line wrapped a space short of the edge: where a word ends just at the edge ImGui 1.86
// counts the blank after it in the line's width, past the edge (seen at the narrowest panel
// with "cylinder Ø 10 mm (r 5 mm), axis (0, 0, -1)").
void wrappedLine(const std::string& text);

// Wrapped text in the disabled colour.
void textDisabledWrapped(const char* text);

} // namespace app
