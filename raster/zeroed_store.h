// A grow-only array of a trivially copyable type in zeroed pages from the system: growing costs
// no pass of constructors over the new elements, and a page is first touched (the kernel
// zeroing it) only when an element on it is written. A store of kHugeStoreBytes or more is a
// huge block (huge_blocks.h), one fault per 2 MiB rather than per 4 KiB: the first frame of a
// draw of half a million vertices spent most of its time on first touches, and a scene's
// primitive records (576 KiB) took a tenth of small scenes' first frames.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

#include "raster/huge_blocks.h"

namespace pineda::raster {

constexpr size_t kHugeStoreBytes = size_t{512} << 10;

template <typename T>
class ZeroedStore {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

 public:
  ZeroedStore() = default;
  ~ZeroedStore() { release(); }
  ZeroedStore(ZeroedStore&& other) noexcept
      : store_(std::exchange(other.store_, nullptr)), capacity_(std::exchange(other.capacity_, 0)) {}
  ZeroedStore& operator=(ZeroedStore&& other) noexcept {
    if (this != &other) {
      release();
      store_ = std::exchange(other.store_, nullptr);
      capacity_ = std::exchange(other.capacity_, 0);
    }
    return *this;
  }

  // Room for `count` elements: those below the previous size as they were, the new ones zero
  // (T, an implicit-lifetime type, begins its life there). Throws std::bad_alloc.
  T* grow(size_t count) {
    if (capacity_ < count) {
      if (count > SIZE_MAX / sizeof(T)) throw std::bad_alloc();
      T* grown = allocate(count);
      if (capacity_) std::memcpy(static_cast<void*>(grown), store_, capacity_ * sizeof(T));
      release();
      store_ = grown;
      capacity_ = count;
    }
    return store_;
  }
  T* data() const { return store_; }
  size_t capacity() const { return capacity_; }

 private:
  static bool huge(size_t count) { return count * sizeof(T) >= kHugeStoreBytes; }
  static T* allocate(size_t count) {
    if (huge(count)) return static_cast<T*>(map_huge_block(count * sizeof(T)));
    auto* p = static_cast<T*>(std::calloc(count, sizeof(T)));
    if (!p) throw std::bad_alloc();
    return p;
  }
  void release() noexcept {
    if (huge(capacity_)) unmap_huge_block(store_, capacity_ * sizeof(T));
    else std::free(store_);
    store_ = nullptr;
    capacity_ = 0;
  }

  T* store_ = nullptr;
  size_t capacity_ = 0;
};

}  // namespace pineda::raster
