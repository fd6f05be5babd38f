// step_index.cpp - the type table and the record accessors of step_index.h.
#include "scene/step/step_index.h"

#include <algorithm>

namespace scene::step {

// Written without `"#" + std::to_string(id)`, on which GCC 12 warns falsely (-Wrestrict).
std::string entityName(uint64_t id) {
    std::string name = std::to_string(id);
    name.insert(name.begin(), '#');
    return name;
}

uint64_t hashOf(std::string_view keyword) {
    uint64_t hash = kHashStart;
    for (char c : keyword) hash = hashStep(hash, c);
    return hash;
}

// Linear probing; the table doubles past half full.
template <typename Same>
uint32_t TypeTable::find(uint64_t hash, Same&& same, const std::vector<std::string_view>& parts,
                         bool complex) {
    size_t mask = slots_.size() - 1;
    size_t at = size_t(hash) & mask;
    for (; slots_[at].type != UINT32_MAX; at = (at + 1) & mask)
        if (slots_[at].hash == hash && complex_[slots_[at].type] == complex &&
            same(parts_[slots_[at].type]))
            return slots_[at].type;
    const auto type = uint32_t(parts_.size());
    parts_.push_back(parts);
    complex_.push_back(complex);
    slots_[at] = {hash, type};
    if (2 * parts_.size() > slots_.size()) {
        std::vector<Slot> old(slots_.size() * 2);
        old.swap(slots_);
        mask = slots_.size() - 1;
        for (const Slot& slot : old) {
            if (slot.type == UINT32_MAX) continue;
            size_t to = size_t(slot.hash) & mask;
            while (slots_[to].type != UINT32_MAX) to = (to + 1) & mask;
            slots_[to] = slot;
        }
    }
    return type;
}

uint32_t TypeTable::simple(std::string_view name, uint64_t hash) {
    scratch_.assign(1, name);
    return find(
        hash, [&](const std::vector<std::string_view>& parts) { return parts[0] == name; },
        scratch_, false);
}

uint32_t TypeTable::complex(const std::vector<std::string_view>& parts) {
    uint64_t hash = kHashStart;
    for (std::string_view part : parts) hash = hashStep(hashOf(part) ^ hash, ' ');
    return find(
        hash, [&](const std::vector<std::string_view>& known) { return known == parts; }, parts,
        true);
}

std::string TypeTable::name(uint32_t type) const {
    if (!complex_[type]) return std::string(parts_[type][0]);
    std::string joined = "(";
    for (size_t i = 0; i < parts_[type].size(); ++i)
        joined.append(i > 0 ? " " : "").append(parts_[type][i]);
    return joined + ")";
}

uint64_t TypeTable::memoryBytes() const {
    uint64_t bytes = slots_.capacity() * sizeof(Slot) + parts_.capacity() * sizeof(parts_[0]);
    for (const auto& parts : parts_) bytes += parts.capacity() * sizeof(std::string_view);
    return bytes;
}

uint64_t StepIndex::idOf(uint32_t record) const {
    uint64_t id = 0;
    for (size_t i = begin[record] + 1; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i)
        id = id * 10 + uint64_t(text[i] - '0');
    return id;
}

std::string StepIndex::describe(uint32_t record) const {
    return entityName(idOf(record)) + " (" + types.name(type[record]) + ")";
}

uint64_t StepIndex::memoryBytes() const {
    return begin.capacity() * sizeof(uint64_t) + length.capacity() * sizeof(uint32_t) +
           type.capacity() * sizeof(uint32_t) + refStart.capacity() * sizeof(uint32_t) +
           refs.capacity() * sizeof(uint32_t) + types.memoryBytes();
}

} // namespace scene::step
