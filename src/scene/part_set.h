// part_set.h - a set of unique part IDs as a bitset: bit (id & 31) of word id / 32, the
// layout the GPU reads and writes (gpu::FrameData::selectedAddress, PartSetResult). The
// selection, the hidden parts and what a box or the whole image covers are all PartSets.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

namespace scene {

class PartSet {
  public:
    PartSet() = default;
    // Room for IDs 0 to partCount - 1; empty.
    explicit PartSet(uint32_t partCount) : count_(partCount), words_((partCount + 31) / 32) {}
    // From GPU words; bits at or above partCount are ignored.
    PartSet(uint32_t partCount, const uint32_t* words) : PartSet(partCount) {
        for (size_t i = 0; i < words_.size(); ++i) words_[i] = words[i];
        if (count_ % 32) words_.back() &= (1u << (count_ % 32)) - 1u;
    }

    uint32_t partCount() const { return count_; }
    // IDs outside 0..partCount-1 are never members; inserting them does nothing.
    bool contains(uint32_t id) const { return id < count_ && (words_[id >> 5] >> (id & 31)) & 1u; }
    void insert(uint32_t id) {
        if (id < count_) words_[id >> 5] |= 1u << (id & 31);
    }
    void erase(uint32_t id) {
        if (id < count_) words_[id >> 5] &= ~(1u << (id & 31));
    }
    void clear() { std::fill(words_.begin(), words_.end(), 0u); }
    // Every ID not in the set is in it afterwards and the other way round.
    void invert() {
        for (uint32_t& w : words_) w = ~w;
        if (count_ % 32) words_.back() &= (1u << (count_ % 32)) - 1u;
    }
    void insertAll(const PartSet& other) {
        for (size_t i = 0; i < words_.size() && i < other.words_.size(); ++i)
            words_[i] |= other.words_[i];
    }
    void eraseAll(const PartSet& other) {
        for (size_t i = 0; i < words_.size() && i < other.words_.size(); ++i)
            words_[i] &= ~other.words_[i];
    }

    bool empty() const {
        for (uint32_t w : words_)
            if (w) return false;
        return true;
    }
    uint32_t size() const {
        uint32_t n = 0;
        for (uint32_t w : words_) n += uint32_t(std::popcount(w));
        return n;
    }
    // Whether any of, or all of, the parts [first, first + count) are members: a word at a
    // time, so a tree row over a whole scene costs little per frame.
    bool anyIn(uint32_t first, uint32_t count) const { return countIn(first, count) > 0; }
    bool allIn(uint32_t first, uint32_t count) const { return countIn(first, count) == count; }
    uint32_t countIn(uint32_t first, uint32_t count) const {
        uint32_t n = 0;
        const uint64_t end = std::min<uint64_t>(uint64_t(first) + count, count_);
        for (uint64_t id = first; id < end;) {
            const uint32_t bit = uint32_t(id & 31),
                           take = uint32_t(std::min<uint64_t>(32 - bit, end - id));
            const uint32_t mask = take == 32 ? ~0u : ((1u << take) - 1u) << bit;
            n += uint32_t(std::popcount(words_[id >> 5] & mask));
            id += take;
        }
        return n;
    }
    // The members in increasing order.
    std::vector<uint32_t> ids() const {
        std::vector<uint32_t> out;
        for (size_t i = 0; i < words_.size(); ++i)
            for (uint32_t w = words_[i]; w; w &= w - 1)
                out.push_back(uint32_t(i * 32) + uint32_t(std::countr_zero(w)));
        return out;
    }
    const std::vector<uint32_t>& words() const { return words_; }
    bool operator==(const PartSet&) const = default;

  private:
    uint32_t count_ = 0;
    std::vector<uint32_t> words_;
};

} // namespace scene
