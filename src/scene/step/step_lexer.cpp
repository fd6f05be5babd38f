// step_lexer.cpp - the lexer behind step_index.h: one pass over the mapped text that finds the
// DATA section and indexes every record in it (ISO 10303-21: `#id = TYPE(...);` and complex
// `#id = (A(...) B(...));`, strings with '' for a quote, comments anywhere between tokens).
#include "scene/step/step_index.h"

#include <algorithm>
#include <array>
#include <cstring>

namespace scene::step {
namespace {

constexpr uint32_t kDuplicate = 0xfffffffeu;

// The bytes the parameter loop must look at: everything else is skipped in a tight loop.
constexpr std::array<bool, 256> kSpecial = [] {
    std::array<bool, 256> table{};
    for (unsigned char c : std::string_view("'#()/;", 6)) table[c] = true;
    table[0] = true; // the zero byte past the end of the text (util::MappedFile)
    return table;
}();

constexpr std::array<bool, 256> kBlank = [] {
    std::array<bool, 256> table{};
    for (unsigned char c : std::string_view(" \t\r\n\f\v")) table[c] = true;
    return table;
}();

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}
bool isWordChar(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || isDigit(c) || c == '_' || c == '-';
}

class Lexer {
  public:
    Lexer(std::string_view text, StepIndex& out)
        : base_(text.data()), end_(text.data() + text.size()), out_(out) {}

    void run() {
        out_.text = std::string_view(base_, size_t(end_ - base_));
        reserve();
        const char* p = records(header(base_));
        trailer(p);
        resolve();
        fit();
    }

  private:
    [[noreturn]] void refuse(const std::string& reason) const { throw Refused{reason}; }
    std::string where(const char* p) const { return "at byte " + std::to_string(p - base_); }
    // Up to 20 bytes from `p`, on one line.
    std::string sample(const char* p) const {
        const char* stop = p;
        while (stop < end_ && stop - p < 20 && uint8_t(*stop) >= ' ') ++stop;
        return std::string(p, stop);
    }
    std::string inRecord() const {
        return current_ ? " (record #" + std::to_string(current_) + ")" : " (in the header)";
    }

    // Guesses from the size of a typical CAD export (56 bytes a record, 48 a reference in
    // KiCad's), so that the arrays grow rarely; fit() gives back what the guess left over.
    void reserve() {
        const size_t records = size_t(end_ - base_) / 40;
        out_.begin.reserve(records);
        out_.length.reserve(records);
        out_.type.reserve(records);
        out_.refStart.reserve(records + 1);
        ids_.reserve(records);
        refIds_.reserve(size_t(end_ - base_) / 32);
    }
    void fit() {
        out_.begin.shrink_to_fit();
        out_.length.shrink_to_fit();
        out_.type.shrink_to_fit();
        out_.refStart.shrink_to_fit();
    }

    const char* skipComment(const char* p) const { // p just after "/*"
        for (;;) {
            const void* star = std::memchr(p, '*', size_t(end_ - p));
            if (!star) refuse("the file ends inside a comment" + inRecord());
            p = static_cast<const char*>(star) + 1;
            if (*p == '/') return p + 1;
        }
    }

    const char* skipBlank(const char* p) const {
        for (;;) {
            while (kBlank[uint8_t(*p)]) ++p;
            if (p[0] != '/' || p[1] != '*') return p;
            p = skipComment(p + 2);
        }
    }

    const char* skipString(const char* p) const { // p just after the opening quote
        for (;;) {
            const void* quote = std::memchr(p, '\'', size_t(end_ - p));
            if (!quote) refuse("the file ends inside a string" + inRecord());
            p = static_cast<const char*>(quote) + 1;
            if (*p != '\'') return p; // '' stands for one quote inside the string
            ++p;
        }
    }

    const char* word(const char* p, std::string_view& out) const {
        uint64_t hash = 0;
        return word(p, out, hash);
    }
    const char* word(const char* p, std::string_view& out, uint64_t& hash) const {
        const char* start = p;
        hash = kHashStart;
        if (*p == '!') hash = hashStep(hash, *p++); // a user-defined keyword
        for (; isWordChar(*p); ++p) hash = hashStep(hash, *p);
        out = std::string_view(start, size_t(p - start));
        return p;
    }

    // Whether `p` starts the section keyword `name` followed by ';'; if so, `after` is past it.
    bool section(const char* p, std::string_view name, const char*& after) const {
        std::string_view found;
        const char* next = skipBlank(word(p, found));
        if (found != name || *next != ';') return false;
        after = next + 1;
        return true;
    }

    const char* header(const char* p);
    const char* records(const char* p);
    void trailer(const char* p) const;
    const char* record(const char* p);
    const char* complexType(const char* p, uint32_t& type);
    const char* parameters(const char* p);
    const char* reference(const char* p);
    void resolve();
    std::vector<uint32_t> denseTable() const;

    const char* base_;
    const char* end_;
    StepIndex& out_;
    std::vector<uint64_t> ids_;    // each record's id, until resolve
    std::vector<uint64_t> refIds_; // the ids referenced, until resolve
    std::vector<std::string_view> parts_;
    uint64_t current_ = 0; // the record being lexed, for messages
};

// Finds "DATA;" at the top level of the text, past strings and comments; the header sections
// before it are copied verbatim into every output, so an edition 3 section the outputs could
// not stand for is refused here.
const char* Lexer::header(const char* p) {
    for (;;) {
        p = skipBlank(p);
        const char c = *p;
        if (c == '\'') {
            p = skipString(p + 1);
        } else if (isWordChar(c)) {
            const char* after = nullptr;
            if (section(p, "DATA", after)) {
                out_.dataBegin = uint64_t(p - base_);
                return after;
            }
            for (const char* other : {"ANCHOR", "REFERENCE", "SIGNATURE"})
                if (section(p, other, after))
                    refuse(std::string("an ") + other + " section (edition 3) before DATA");
            std::string_view skipped;
            p = word(p, skipped);
            if (skipped == "DATA") refuse("a DATA section with parameters (edition 3)");
        } else if (c == '\0' && p == end_) {
            refuse("no DATA section");
        } else {
            ++p;
        }
    }
}

const char* Lexer::records(const char* p) {
    for (;;) {
        p = skipBlank(p);
        if (*p == '#') {
            p = record(p);
            continue;
        }
        current_ = 0;
        const char* after = nullptr;
        if (section(p, "ENDSEC", after)) return after;
        if (p == end_) refuse("the DATA section does not end (no ENDSEC;)");
        refuse("unexpected text in the DATA section " + where(p) + ": '" + sample(p) + "'");
    }
}

void Lexer::trailer(const char* p) const {
    p = skipBlank(p);
    const char* after = nullptr;
    if (section(p, "END-ISO-10303-21", after)) return;
    std::string_view next;
    word(p, next);
    if (next == "DATA") refuse("a second DATA section");
    if (p == end_) refuse("the file ends without END-ISO-10303-21;");
    refuse("unexpected text after the DATA section " + where(p));
}

const char* Lexer::record(const char* p) {
    const char* start = p++;
    const char* digits = p;
    uint64_t id = 0;
    while (isDigit(*p)) id = id * 10 + uint64_t(*p++ - '0');
    if (p == digits || p - digits > 18) refuse("a bad entity number " + where(start));
    current_ = id;
    p = skipBlank(p);
    if (*p != '=') refuse("'=' expected after #" + std::to_string(id));
    p = skipBlank(p + 1);
    const auto firstRef = refIds_.size();
    uint32_t type = 0;
    if (*p == '(') {
        p = complexType(p + 1, type);
    } else {
        std::string_view name;
        uint64_t hash = 0;
        p = skipBlank(word(p, name, hash));
        if (name.empty() || *p != '(')
            refuse(entityName(id) + " is not TYPE(...) nor a complex record");
        p = parameters(p + 1);
        type = out_.types.simple(name, hash);
    }
    p = skipBlank(p);
    if (*p != ';') refuse("record #" + std::to_string(id) + " does not end with ';'");
    ++p;
    if (uint64_t(p - start) > UINT32_MAX) refuse("record #" + std::to_string(id) + " too long");
    out_.begin.push_back(uint64_t(start - base_));
    out_.length.push_back(uint32_t(p - start));
    out_.type.push_back(type);
    out_.refStart.push_back(uint32_t(firstRef));
    ids_.push_back(id);
    out_.maxId = std::max(out_.maxId, id);
    return p;
}

const char* Lexer::complexType(const char* p, uint32_t& type) {
    parts_.clear();
    for (;;) {
        p = skipBlank(p);
        if (*p == ')') break;
        std::string_view name;
        p = skipBlank(word(p, name));
        if (name.empty() || *p != '(')
            refuse("complex record #" + std::to_string(current_) + ": TYPE(...) expected " +
                   where(p));
        p = parameters(p + 1);
        parts_.push_back(name);
    }
    if (parts_.empty()) refuse("complex record #" + std::to_string(current_) + " is empty");
    type = out_.types.complex(parts_);
    return p + 1;
}

// From just after an opening parenthesis to just after the one that closes it.
const char* Lexer::parameters(const char* p) {
    uint32_t depth = 1;
    for (;;) {
        while (!kSpecial[uint8_t(*p)]) ++p;
        switch (*p) {
        case '\'':
            p = skipString(p + 1);
            break;
        case '#':
            p = reference(p + 1);
            break;
        case '(':
            ++depth;
            ++p;
            break;
        case ')':
            ++p;
            if (--depth == 0) return p;
            break;
        case '/':
            p = p[1] == '*' ? skipComment(p + 2) : p + 1;
            break;
        case ';':
            refuse("record #" + std::to_string(current_) + " does not end (';' " + where(p) +
                   " inside its parentheses)");
        default:
            if (p == end_) refuse("the file ends inside record #" + std::to_string(current_));
            refuse("a zero byte " + where(p));
        }
    }
}

const char* Lexer::reference(const char* p) {
    const char* digits = p;
    uint64_t id = 0;
    while (isDigit(*p)) id = id * 10 + uint64_t(*p++ - '0');
    if (p == digits || p - digits > 18)
        refuse("record #" + std::to_string(current_) + ": a bad reference " + where(digits - 1));
    refIds_.push_back(id);
    return p;
}

// id -> record for ids up to maxId, where they are dense enough for a table.
std::vector<uint32_t> Lexer::denseTable() const {
    std::vector<uint32_t> table(out_.maxId + 1, kNoRecord);
    for (uint32_t r = 0; r < ids_.size(); ++r) {
        uint32_t& slot = table[ids_[r]];
        slot = slot == kNoRecord ? r : kDuplicate;
    }
    return table;
}

// Turns the ids referenced into record numbers, through a table where ids are dense and a
// sorted list where they are sparse.
void Lexer::resolve() {
    const auto n = uint64_t(ids_.size());
    if (n >= kDuplicate || refIds_.size() >= UINT32_MAX) refuse("too many records to split");
    out_.refStart.push_back(uint32_t(refIds_.size()));
    const bool dense = out_.maxId <= 4 * n + 1024;
    std::vector<uint32_t> table;
    std::vector<std::pair<uint64_t, uint32_t>> sorted;
    if (dense) {
        table = denseTable();
    } else {
        sorted.reserve(n);
        for (uint32_t r = 0; r < n; ++r) sorted.emplace_back(ids_[r], r);
        std::sort(sorted.begin(), sorted.end());
        for (size_t i = 1; i < sorted.size(); ++i)
            if (sorted[i].first == sorted[i - 1].first)
                sorted[i].second = sorted[i - 1].second = kDuplicate;
    }
    auto lookup = [&](uint64_t id) {
        if (!dense) {
            const auto at = std::lower_bound(sorted.begin(), sorted.end(),
                                             std::pair<uint64_t, uint32_t>(id, 0));
            return at != sorted.end() && at->first == id ? at->second : kNoRecord;
        }
        return id < table.size() ? table[id] : kNoRecord;
    };
    out_.refs.resize(refIds_.size());
    for (size_t i = 0; i < refIds_.size(); ++i) {
        const uint32_t r = lookup(refIds_[i]);
        if (r == kDuplicate) refuse(entityName(refIds_[i]) + " is defined twice and referenced");
        out_.missingRefs += r == kNoRecord;
        out_.refs[i] = r;
    }
    std::vector<uint64_t>().swap(refIds_);
    std::vector<uint64_t>().swap(ids_);
}

} // namespace

std::optional<std::string> lexStep(std::string_view text, StepIndex& index) {
    return refusalOf(index, [&] { Lexer(text, index).run(); });
}

} // namespace scene::step
