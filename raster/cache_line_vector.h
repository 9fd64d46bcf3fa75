// A std::vector whose elements start on a 64-byte cache line, for the buffers tiles are rendered
// into. A tile row is a whole number of lines (64 pixels of 1, 2 or 4 bytes) only when the row
// starts on one; glibc's large allocations start 16 bytes past a page, so two threads rendering
// side-by-side tiles shared a line at every row's edges, and passed it back and forth
// (overdraw with two threads took as long as with one). Blocks of 2 MiB and more are huge
// blocks (huge_blocks.h): a 1024x768 RGBA8 buffer takes 4 MiB, in two huge pages. Their
// contents are not zero: the vector constructs its elements.
#pragma once
#include <cstddef>
#include <new>
#include <vector>

#include "raster/huge_blocks.h"

namespace pineda::raster {

template <typename T>
struct CacheLineAllocator {
  using value_type = T;
  static constexpr std::align_val_t kAlignment{64};

  CacheLineAllocator() = default;
  template <typename U>
  CacheLineAllocator(const CacheLineAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    return static_cast<T*>(bytes >= kHugePageBytes ? take_huge_block(bytes) : ::operator new(bytes, kAlignment));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) >= kHugePageBytes) release_huge_block(p, n * sizeof(T));
    else ::operator delete(p, kAlignment);
  }

  template <typename U>
  bool operator==(const CacheLineAllocator<U>&) const noexcept {
    return true;
  }
};

template <typename T>
using CacheLineVector = std::vector<T, CacheLineAllocator<T>>;

}  // namespace pineda::raster
