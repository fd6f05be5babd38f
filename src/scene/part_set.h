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
