// A texture level's texels (or a depth-stencil level's stencil indices), held by shared_ptr:
// a framebuffer-object view that renders into the level in place keeps them alive
// (Drawable::kept_storage), so another context of the share group may respecify or delete
// the texture while rendering is still queued into it. Copies are deep; assign and resize
// allocate anew and never move elements that a view may point into.
//
// Texture snapshots read the elements where they are (share()): through a pin of their own, so
// that snapshot_holders() counts them apart from the views. Before the elements change in place,
// the texture detaches them from snapshots that queued draws hold (TextureObject::
// before_texels_change).
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
  using Storage = raster::CacheLineVector<T>;

  SharedTexels() = default;
  SharedTexels(const SharedTexels& other) : v_(other.v_ ? std::make_shared<Storage>(*other.v_) : nullptr) {}
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

  void assign(size_t n, T value) {
    v_ = std::make_shared<Storage>(n, value);
    pin_.reset();
  }
  void resize(size_t n, T value = T{}) {
    auto next = std::make_shared<Storage>(begin(), begin() + std::min(n, size()));
    next->resize(n, value);
    v_ = std::move(next);
    pin_.reset();
  }

  // What keeps the elements alive for a holder that points into them.
  std::shared_ptr<const void> owner() const { return v_; }

  // The elements for a texture snapshot to read where they are (null when there are none).
  std::shared_ptr<const Storage> share() const {
    if (!v_) return nullptr;
    if (!pin_) pin_ = std::make_shared<Pin>(Pin{v_});
    return std::shared_ptr<const Storage>(pin_, v_.get());
  }
  // How many snapshot levels read the elements where they are.
  long snapshot_holders() const { return pin_ ? pin_.use_count() - 1 : 0; }
  // The elements copied into storage of their own, which no snapshot reads (views keep theirs:
  // a changed data() rebuilds them).
  void detach() {
    if (v_) v_ = std::make_shared<Storage>(*v_);
    pin_.reset();
  }

 private:
  struct Pin {
    std::shared_ptr<Storage> storage;
  };
  std::shared_ptr<Storage> v_;
  mutable std::shared_ptr<Pin> pin_;  // held by the snapshots that share v_
};

}  // namespace pineda
