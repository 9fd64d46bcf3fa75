// A std::vector whose elements start on a 64-byte cache line, for the buffers tiles are rendered
// into. A tile row is a whole number of lines (64 pixels of 1, 2 or 4 bytes) only when the row
// starts on one; glibc's large allocations start 16 bytes past a page, so two threads rendering
// side-by-side tiles shared a line at every row's edges, and passed it back and forth
// (overdraw with two threads took as long as with one).
#pragma once
#include <cstddef>
#include <new>
#include <vector>

namespace pineda::raster {

template <typename T>
struct CacheLineAllocator {
  using value_type = T;
  static constexpr std::align_val_t kAlignment{64};

  CacheLineAllocator() = default;
  template <typename U>
  CacheLineAllocator(const CacheLineAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), kAlignment)); }
  void deallocate(T* p, std::size_t) noexcept { ::operator delete(p, kAlignment); }

  template <typename U>
  bool operator==(const CacheLineAllocator<U>&) const noexcept {
    return true;
  }
};

template <typename T>
using CacheLineVector = std::vector<T, CacheLineAllocator<T>>;

}  // namespace pineda::raster
