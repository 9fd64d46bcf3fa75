// A texture level's texels (or a depth-stencil level's stencil indices), held by shared_ptr:
// a framebuffer-object view that renders into the level in place keeps them alive
// (Drawable::kept_storage), so another context of the share group may respecify or delete
// the texture while rendering is still queued into it. Copies are deep; assign and resize
// allocate anew and never move elements that a view may point into.
#pragma once
#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

#include "raster/cache_line_vector.h"

namespace pineda {

template <typename T>
class SharedTexels {
 public:
  SharedTexels() = default;
  SharedTexels(const SharedTexels& other) : v_(other.v_ ? std::make_shared<raster::CacheLineVector<T>>(*other.v_) : nullptr) {}
  SharedTexels& operator=(const SharedTexels& other) {
    if (this != &other) *this = SharedTexels(other);
    return *this;
  }
  SharedTexels(SharedTexels&&) noexcept = default;
  SharedTexels& operator=(SharedTexels&&) noexcept = default;

  size_t size() const { return v_ ? v_->size() : 0; }
  bool empty() const { return size() == 0; }
  T* data() { return v_ ? v_->data() : nullptr; }
  const T* data() const { return v_ ? v_->data() : nullptr; }
  T& operator[](size_t i) { return (*v_)[i]; }
  const T& operator[](size_t i) const { return (*v_)[i]; }
  T* begin() { return data(); }
  T* end() { return data() + size(); }
  const T* begin() const { return data(); }
  const T* end() const { return data() + size(); }

  void assign(size_t n, T value) { v_ = std::make_shared<raster::CacheLineVector<T>>(n, value); }
  void resize(size_t n, T value = T{}) {
    auto next = std::make_shared<raster::CacheLineVector<T>>(begin(), begin() + std::min(n, size()));
    next->resize(n, value);
    v_ = std::move(next);
  }

  // What keeps the elements alive for a holder that points into them.
  std::shared_ptr<const void> owner() const { return v_; }

 private:
  std::shared_ptr<raster::CacheLineVector<T>> v_;
};

}  // namespace pineda
