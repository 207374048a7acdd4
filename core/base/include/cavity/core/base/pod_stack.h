#pragma once

#include <cstddef>
#include <memory>
#include <type_traits>

namespace cavity::core {

/// A growable array of trivially copyable values for the insertion loop's scratch lists (the
/// cavity's stack, created and deleted tetrahedra, free slots). Pushing is a compare and a store,
/// always inlined; growing is out of the way. std::vector's push_back was measured to stay an
/// out-of-line call in these loops (GCC 12, -O3).
template <class T>
class PodStack {
    static_assert(std::is_trivially_copyable_v<T>);

public:
    [[gnu::always_inline]] void push_back(const T& value) {
        if (size_ == capacity_) [[unlikely]] {
            grow();
        }
        data_[size_++] = value;
    }

    [[gnu::always_inline]] T pop_back() { return data_[--size_]; }

    void clear() { size_ = 0; }

    bool empty() const { return size_ == 0; }

    std::size_t size() const { return size_; }

    std::size_t capacity() const { return capacity_; }

    const T& operator[](std::size_t i) const { return data_[i]; }

    T& operator[](std::size_t i) { return data_[i]; }

    const T* begin() const { return data_.get(); }

    const T* end() const { return data_.get() + size_; }

    const T& front() const { return data_[0]; }

    const T& back() const { return data_[size_ - 1]; }

private:
    [[gnu::noinline]] void grow() {
        const std::size_t capacity = capacity_ == 0 ? 64 : 2 * capacity_;
        auto data = std::make_unique_for_overwrite<T[]>(capacity);
        for (std::size_t i = 0; i < size_; ++i) {
            data[i] = data_[i];
        }
        data_ = std::move(data);
        capacity_ = capacity;
    }

    std::unique_ptr<T[]> data_;
    std::size_t size_ = 0;
    std::size_t capacity_ = 0;
};

}  // namespace cavity::core
