// step_record.cpp - parameters of one record (step_record.h), read from its text with the
// lexer's rules: strings with '' inside, comments, nested parentheses.
#include "scene/step/step_record.h"

#include <charconv>

namespace scene::step {
namespace {

bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f';
}

std::string_view trimmed(std::string_view text) {
    while (!text.empty() && isBlank(text.front())) text.remove_prefix(1);
    while (!text.empty() && isBlank(text.back())) text.remove_suffix(1);
    return text;
}

// Past blanks and comments from `at`.
size_t skipBlank(std::string_view text, size_t at) {
    for (;;) {
        while (at < text.size() && isBlank(text[at])) ++at;
        if (text.substr(at, 2) != "/*") return at;
        const size_t close = text.find("*/", at + 2);
        at = close == std::string_view::npos ? text.size() : close + 2;
    }
}

// Splits `text`, which starts just after an opening parenthesis, at its top-level commas
// until the parenthesis that closes it; `part` gets each piece (trimmed) with the number of
// references before it and in it. Nothing where the list is empty.
template <typename Part>
void splitList(std::string_view text, Part&& part) {
    size_t start = 0;
    uint32_t depth = 0, refsBefore = 0, refs = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\'') { // to the closing quote: '' inside stands for one quote
            for (++i; i < text.size(); ++i) {
                if (text[i] != '\'') continue;
                if (i + 1 < text.size() && text[i + 1] == '\'') {
                    ++i;
                    continue;
                }
                break;
            }
        } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
            const size_t close = text.find("*/", i + 2);
            i = close == std::string_view::npos ? text.size() : close + 1;
        } else if (c == '#') {
            ++refs;
        } else if (c == '(') {
            ++depth;
        } else if ((c == ')' && depth == 0) || (c == ',' && depth == 0)) {
            const std::string_view piece = trimmed(text.substr(start, i - start));
            if (c == ',' || !piece.empty() || start > 0) part(piece, refsBefore, refs);
            if (c == ')') return;
            refsBefore += refs;
            refs = 0;
            start = i + 1;
        } else if (c == ')') {
            --depth;
        }
    }
}

} // namespace

std::vector<Parameter> parametersOf(const StepIndex& index, uint32_t record) {
    std::vector<Parameter> parameters;
    if (index.types.isComplex(index.type[record])) return parameters;
    // The record was lexed: "#id = KEYWORD(" with blanks and comments between the tokens.
    const std::string_view text = index.textOf(record);
    size_t at = 1;
    while (at < text.size() && text[at] >= '0' && text[at] <= '9') ++at;
    at = skipBlank(text, skipBlank(text, at) + 1); // past '='
    while (at < text.size() && text[at] != '(' && !isBlank(text[at]) && text[at] != '/') ++at;
    at = skipBlank(text, at);
    if (at >= text.size() || text[at] != '(') return parameters;
    splitList(text.substr(at + 1), [&](std::string_view piece, uint32_t before, uint32_t refs) {
        parameters.push_back({piece, before, refs});
    });
    return parameters;
}

std::optional<std::vector<std::string_view>> listElements(std::string_view text) {
    text = trimmed(text);
    if (text.size() < 2 || text.front() != '(' || text.back() != ')') return std::nullopt;
    std::vector<std::string_view> elements;
    splitList(text.substr(1),
              [&](std::string_view piece, uint32_t, uint32_t) { elements.push_back(piece); });
    return elements;
}

uint32_t referenceIn(const StepIndex& index, uint32_t record, const Parameter& parameter) {
    if (parameter.refCount != 1 || parameter.text.empty() || parameter.text.front() != '#')
        return kNoRecord;
    return index.refsOf(record)[parameter.firstRef];
}

std::optional<double> realOf(std::string_view text) {
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

} // namespace scene::step
