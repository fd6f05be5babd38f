// step_index.h - a STEP file's DATA section lexed into an index: each record's bytes, type
// and references, in file order, as compact arrays (step_lexer.cpp makes it; the splitter,
// step_split.cpp, reads it). The text itself stays where it is (a mapped file).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace scene::step {

// A reference to an id no record defines (kept in the text; Open CASCADE warns of it itself).
constexpr uint32_t kNoRecord = 0xffffffffu;

// "#id", the way a STEP file names an entity.
std::string entityName(uint64_t id);

// Thrown where a file leaves what the lexer or the planner takes.
struct Refused {
    std::string reason;
};

// Runs `run`, which fills `out`: nothing where it finishes, else the reason it was refused,
// `out` left empty.
template <typename Out, typename Run>
std::optional<std::string> refusalOf(Out& out, Run&& run) {
    try {
        run();
        return std::nullopt;
    } catch (const Refused& refused) {
        out = Out();
        return refused.reason;
    }
}

// The hash of a keyword, one character at a time (FNV-1a), so that the lexer works it out
// while it reads the keyword.
constexpr uint64_t kHashStart = 14695981039346656037ull;
inline uint64_t hashStep(uint64_t hash, char c) {
    return (hash ^ uint8_t(c)) * 1099511628211ull;
}
uint64_t hashOf(std::string_view keyword);

// Type names, interned: a simple record's keyword, or a complex record's list of partial
// types. A small open-addressing table: every record asks it once, so std::unordered_map's
// hashing and node chasing showed in the lexer's time.
class TypeTable {
  public:
    // `name` must outlive the table (it points into the mapped text); `hash` is hashOf(name).
    uint32_t simple(std::string_view name, uint64_t hash);
    uint32_t complex(const std::vector<std::string_view>& parts);

    size_t size() const { return parts_.size(); }
    bool isComplex(uint32_t type) const { return complex_[type]; }
    // A simple type's keyword, or a complex type's partial types in the order of the text.
    const std::vector<std::string_view>& parts(uint32_t type) const { return parts_[type]; }
    std::string name(uint32_t type) const; // "KEYWORD" or "(A B C)", for messages
    uint64_t memoryBytes() const;

  private:
    struct Slot {
        uint64_t hash = 0;
        uint32_t type = UINT32_MAX; // empty
    };
    template <typename Same>
    uint32_t find(uint64_t hash, Same&& same, const std::vector<std::string_view>& parts,
                  bool complex);

    std::vector<Slot> slots_ = std::vector<Slot>(256);
    std::vector<std::vector<std::string_view>> parts_;
    std::vector<bool> complex_;
    std::vector<std::string_view> scratch_;
};

struct StepIndex {
    std::string_view text;  // the whole file
    uint64_t dataBegin = 0; // where "DATA;" starts: the header is every byte before it
    uint64_t maxId = 0;     // the largest entity number, new records are numbered above it

    // Per record, in file order.
    std::vector<uint64_t> begin;  // its '#'
    std::vector<uint32_t> length; // through its ';'
    std::vector<uint32_t> type;
    std::vector<uint32_t> refStart; // size() + 1 entries into refs
    // The records each one references, one entry per '#' of its text outside strings and
    // comments, in text order; kNoRecord for an id nothing defines.
    std::vector<uint32_t> refs;
    TypeTable types;
    uint64_t missingRefs = 0;

    uint32_t size() const { return uint32_t(begin.size()); }
    std::span<const uint32_t> refsOf(uint32_t record) const {
        return {refs.data() + refStart[record], refs.data() + refStart[record + 1]};
    }
    std::string_view textOf(uint32_t record) const {
        return text.substr(begin[record], length[record]);
    }
    uint64_t idOf(uint32_t record) const;        // read again from its text
    std::string describe(uint32_t record) const; // "#12 (CLOSED_SHELL)", for messages
    uint64_t memoryBytes() const;                // what the arrays hold
};

// Lexes `text` (a whole STEP file whose byte past the end reads as zero: util::MappedFile)
// into `index`. Returns why not, in one line, where the text is not a STEP file this lexer
// takes (the file is then read whole, as before).
std::optional<std::string> lexStep(std::string_view text, StepIndex& index);

} // namespace scene::step
