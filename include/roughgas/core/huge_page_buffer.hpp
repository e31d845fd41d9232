#pragma once
// Storage for the large arrays of the collision loop (the particle stores, dsmc/particles.hpp, and
// the engine's index array, dsmc/engine.hpp): 2 MiB-aligned and madvise(MADV_HUGEPAGE) on Linux,
// so that a random access costs no page walk. With 4 KiB pages, 64 MB of grains span 16384 pages,
// eight times what the second-level TLB holds, and every random grain would add a walk to its miss.
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <cstdint>
#include <new>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace roughgas {

// Advises MADV_HUGEPAGE for the whole 2 MiB pages inside [p, p + bytes), before anything touches
// them, so that their first touch faults in huge pages. A hint: without it the memory works on
// 4 KiB pages.
inline void advise_huge_pages([[maybe_unused]] const void* p, [[maybe_unused]] std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr std::uintptr_t huge = std::uintptr_t{2} << 20;
    const auto first = reinterpret_cast<std::uintptr_t>(p);
    const std::uintptr_t from = (first + huge - 1) / huge * huge, to = (first + bytes) / huge * huge;
    if (to > from)
        madvise(reinterpret_cast<void*>(from), to - from, MADV_HUGEPAGE);
#endif
}

// A std::vector resized to n elements with the 2 MiB pages inside its new storage advised
// MADV_HUGEPAGE before anything touches them (the capacity is reserved first, then advised, then
// filled), so that their first touch faults in huge pages: the box solver's grain arrays, which the
// sort rewrites at every step in cell order, then cost neither 4 KiB page faults at the start nor a
// page walk per page of a scattered write.
template <class T> void resize_on_huge_pages(std::vector<T>& v, std::size_t n) {
    if (v.capacity() < n) {
        // New storage, advised before the elements already held are copied into it (a reserve on v
        // itself would copy them first and fault their pages in small).
        std::vector<T> fresh;
        fresh.reserve(n);
        advise_huge_pages(fresh.data(), n * sizeof(T));
        fresh.insert(fresh.end(), std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
        v.swap(fresh);
    }
    v.resize(n);
}

// A fixed-size buffer of trivially copyable T, value-initialised, on (transparent) huge pages.
template <class T> class HugePageBuffer {
  public:
    HugePageBuffer() = default;
    explicit HugePageBuffer(std::size_t n) : size_(n) {
        if (n == 0)
            return;
        constexpr std::size_t huge = std::size_t{2} << 20;
        const std::size_t bytes = (n * sizeof(T) + huge - 1) / huge * huge;
        void* p = std::aligned_alloc(huge, bytes);
        if (!p)
            throw std::bad_alloc();
        advise_huge_pages(p, bytes); // 2 MiB-aligned and whole pages: all of it
        std::memset(p, 0, bytes);
        data_ = static_cast<T*>(p);
    }
    HugePageBuffer(const HugePageBuffer& o) : HugePageBuffer(o.size_) {
        if (size_)
            std::memcpy(data_, o.data_, size_ * sizeof(T));
    }
    HugePageBuffer(HugePageBuffer&& o) noexcept
        : data_(std::exchange(o.data_, nullptr)), size_(std::exchange(o.size_, 0)) {}
    HugePageBuffer& operator=(HugePageBuffer o) noexcept {
        std::swap(data_, o.data_);
        std::swap(size_, o.size_);
        return *this;
    }
    ~HugePageBuffer() {
        std::free(data_);
    }

    T* data() {
        return data_;
    }
    const T* data() const {
        return data_;
    }
    std::size_t size() const {
        return size_;
    }
    T& operator[](std::size_t i) {
        return data_[i];
    }
    const T& operator[](std::size_t i) const {
        return data_[i];
    }
    T* begin() {
        return data_;
    }
    T* end() {
        return data_ + size_;
    }
    const T* begin() const {
        return data_;
    }
    const T* end() const {
        return data_ + size_;
    }

  private:
    T* data_ = nullptr;
    std::size_t size_ = 0;
};

} // namespace roughgas
