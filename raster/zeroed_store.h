// A grow-only array of a trivially copyable type in zeroed pages from the system: growing costs
// no pass of constructors over the new elements, and a page is first touched (the kernel
// zeroing it: about 1.6 ms per MiB on this project's VM) only when an element on it is written.
// A large store asks for 2 MiB pages, one fault per 2 MiB rather than per 4 KiB. The first
// frame of a draw of half a million vertices spent most of its time on first touches.
#pragma once
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace pineda::raster {

// madvise(MADV_HUGEPAGE) over the whole 2 MiB pieces of [p, p + bytes).
void prefer_huge_pages(void* p, size_t bytes);

template <typename T>
class ZeroedStore {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

 public:
  ZeroedStore() = default;
  ZeroedStore(ZeroedStore&& other) noexcept
      : store_(std::move(other.store_)), capacity_(std::exchange(other.capacity_, 0)) {}
  ZeroedStore& operator=(ZeroedStore&& other) noexcept {
    store_ = std::move(other.store_);
    capacity_ = std::exchange(other.capacity_, 0);
    return *this;
  }

  // Room for `count` elements: those below the previous size as they were, the new ones zero
  // (T, an implicit-lifetime type, begins its life there). Throws std::bad_alloc.
  T* grow(size_t count) {
    if (capacity_ < count) {
      auto* grown = static_cast<T*>(std::calloc(count, sizeof(T)));
      if (!grown) throw std::bad_alloc();
      prefer_huge_pages(grown, count * sizeof(T));
      if (capacity_) std::memcpy(static_cast<void*>(grown), store_.get(), capacity_ * sizeof(T));
      store_.reset(grown);
      capacity_ = count;
    }
    return store_.get();
  }
  T* data() const { return store_.get(); }
  size_t capacity() const { return capacity_; }

 private:
  struct Release {
    void operator()(T* p) const { std::free(p); }
  };
  std::unique_ptr<T[], Release> store_;
  size_t capacity_ = 0;
};

}  // namespace pineda::raster
