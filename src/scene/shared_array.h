// shared_array.h - the scene's heavy arrays (vertices, indices, parts, geometries, materials):
// copies of a scene share them, and one is copied only when a copy changes it (copy on write).
#pragma once

#include <cstddef>
#include <initializer_list>
#include <memory>
#include <utility>
#include <vector>

namespace scene {

// A std::vector whose copies share one buffer. Const access never copies; non-const access
// (data(), operator[], begin(), push_back, ...) first gives this array its own buffer where
// another copy shares it. So a read path should take the array, or its scene, by const
// reference, and a reference or iterator got from non-const access must not outlive a copy
// of the array made after it (it would write through to the copy). Copies may be read from
// any thread, as a vector may; an array is changed by one thread at a time, as a vector is.
template <typename T>
class SharedArray {
  public:
    using value_type = T;
    using size_type = std::size_t;
    using difference_type = std::ptrdiff_t;
    using reference = T&;
    using const_reference = const T&;
    using iterator = typename std::vector<T>::iterator;
    using const_iterator = typename std::vector<T>::const_iterator;

    SharedArray() = default;
    SharedArray(std::vector<T> values) // NOLINT: assigned from vectors, as before
        : values_(std::make_shared<std::vector<T>>(std::move(values))) {}
    SharedArray(std::initializer_list<T> values) : SharedArray(std::vector<T>(values)) {}
    SharedArray& operator=(std::vector<T> values) {
        values_ = std::make_shared<std::vector<T>>(std::move(values));
        return *this;
    }
    SharedArray& operator=(std::initializer_list<T> values) {
        return *this = std::vector<T>(values);
    }

    // Reading: the shared buffer as it is.
    const std::vector<T>& get() const { return values_ ? *values_ : empty_(); }
    operator const std::vector<T>&() const& { return get(); } // NOLINT: passed as a vector
    // A vector moved out is take()n: converting would copy it.
    operator const std::vector<T>&() && = delete;
    size_type size() const { return get().size(); }
    bool empty() const { return get().empty(); }
    size_type capacity() const { return get().capacity(); }
    const T* data() const { return get().data(); }
    const T& operator[](size_type i) const { return get()[i]; }
    const T& at(size_type i) const { return get().at(i); }
    const T& front() const { return get().front(); }
    const T& back() const { return get().back(); }
    const_iterator begin() const { return get().begin(); }
    const_iterator end() const { return get().end(); }
    const_iterator cbegin() const { return get().begin(); }
    const_iterator cend() const { return get().end(); }

    // Writing: this copy's own buffer, copied from the shared one first where it is shared.
    std::vector<T>& edit() {
        if (!values_)
            values_ = std::make_shared<std::vector<T>>();
        else if (values_.use_count() > 1)
            values_ = std::make_shared<std::vector<T>>(*values_);
        return *values_;
    }
    T* data() { return edit().data(); }
    T& operator[](size_type i) { return edit()[i]; }
    T& at(size_type i) { return edit().at(i); }
    T& front() { return edit().front(); }
    T& back() { return edit().back(); }
    iterator begin() { return edit().begin(); }
    iterator end() { return edit().end(); }
    void push_back(const T& value) { edit().push_back(value); }
    void push_back(T&& value) { edit().push_back(std::move(value)); }
    template <typename... Args>
    T& emplace_back(Args&&... args) {
        return edit().emplace_back(std::forward<Args>(args)...);
    }
    void pop_back() { edit().pop_back(); }
    void resize(size_type count) { edit().resize(count); }
    void resize(size_type count, const T& value) { edit().resize(count, value); }
    void reserve(size_type count) { edit().reserve(count); }
    void shrink_to_fit() { edit().shrink_to_fit(); }
    template <typename... Args>
    void assign(Args&&... args) {
        edit().assign(std::forward<Args>(args)...);
    }
    // `at` may come from before the buffer was copied: it is taken as an index.
    template <typename... Args>
    iterator insert(const_iterator at, Args&&... args) {
        const difference_type i = at - std::as_const(*this).begin();
        std::vector<T>& values = edit();
        return values.insert(values.begin() + i, std::forward<Args>(args)...);
    }
    iterator insert(const_iterator at, std::initializer_list<T> values) {
        return insert<std::initializer_list<T>>(at, std::move(values));
    }
    iterator erase(const_iterator first, const_iterator last) {
        const difference_type i = first - std::as_const(*this).begin(), n = last - first;
        std::vector<T>& values = edit();
        return values.erase(values.begin() + i, values.begin() + i + n);
    }
    iterator erase(const_iterator at) { return erase(at, at + 1); }
    // Emptied without copying what the other copies keep.
    void clear() {
        if (values_ && values_.use_count() > 1)
            values_.reset();
        else if (values_)
            values_->clear();
    }
    // The buffer, moved out (copied where it is shared); this array is left empty.
    std::vector<T> take() {
        std::vector<T> values = std::move(edit());
        values_.reset();
        return values;
    }
    void swap(SharedArray& other) noexcept { values_.swap(other.values_); }

    // Whether both use one buffer (tests, and the memory report).
    bool shares(const SharedArray& other) const { return values_ && values_ == other.values_; }

    friend bool operator==(const SharedArray& a, const SharedArray& b) {
        return a.get() == b.get();
    }
    friend bool operator==(const SharedArray& a, const std::vector<T>& b) { return a.get() == b; }

  private:
    static const std::vector<T>& empty_() {
        static const std::vector<T> none;
        return none;
    }
    std::shared_ptr<std::vector<T>> values_; // null: empty
};

} // namespace scene
