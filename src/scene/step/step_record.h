// step_record.h - one record's parameters read again from its text, for the few records the
// splitter looks into (representations, styled items, points): the index only keeps where
// each record is and what it references.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "scene/step/step_index.h"

namespace scene::step {

// One top-level parameter: its text (trimmed) and its references, as positions in the
// record's refsOf() (one per '#', in text order).
struct Parameter {
    std::string_view text;
    uint32_t firstRef = 0;
    uint32_t refCount = 0;
};

// The top-level parameters of a simple record, in order; empty for a complex record.
std::vector<Parameter> parametersOf(const StepIndex& index, uint32_t record);

// The elements of a list parameter "(a, b, c)", trimmed; nullopt where `text` is not a list.
std::optional<std::vector<std::string_view>> listElements(std::string_view text);

// The record that a parameter made of a single reference names (kNoRecord where it is not
// one, or names no record).
uint32_t referenceIn(const StepIndex& index, uint32_t record, const Parameter& parameter);

// A real number as STEP writes it ("-1.5", "2.E-07", "+3."); nullopt where it is not one.
std::optional<double> realOf(std::string_view text);

} // namespace scene::step
