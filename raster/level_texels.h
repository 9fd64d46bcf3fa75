// A texture level's texels as the samplers read them. A snapshot's levels share the texels of
// the texture's state (state/textures/shared_texels.h) instead of copying them at the first draw
// after a change: a 1 MiB copy into new memory was most of a streamed texture's first frame. The
// elements are read only; edit() gives writable ones, copied first unless this holder alone
// owns them.
#pragma once
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <utility>

#include "raster/cache_line_vector.h"

namespace pineda::raster {

class LevelTexels {
 public:
  using Storage = CacheLineVector<uint32_t>;

  LevelTexels() = default;
  LevelTexels(Storage texels) : v_(std::make_shared<Storage>(std::move(texels))), owned_(true) {}
  LevelTexels(std::initializer_list<uint32_t> texels) : LevelTexels(Storage(texels)) {}
  // Elements someone else owns and may write while no queued draw holds them.
  explicit LevelTexels(std::shared_ptr<const Storage> shared) : v_(std::move(shared)) {}

  size_t size() const { return v_ ? v_->size() : 0; }
  bool empty() const { return size() == 0; }
  const uint32_t* data() const { return v_ ? v_->data() : nullptr; }
  const uint32_t* begin() const { return data(); }
  const uint32_t* end() const { return data() + size(); }
  const uint32_t& operator[](size_t i) const { return (*v_)[i]; }

  // The elements to change: copied into storage of this holder's own first, unless it alone
  // holds storage it made.
  Storage& edit() {
    if (!owned_ || v_.use_count() != 1) {
      v_ = std::make_shared<Storage>(v_ ? Storage(*v_) : Storage());
      owned_ = true;
    }
    // Made here as a non-const Storage, and held by no one else.
    return const_cast<Storage&>(*v_);
  }

 private:
  std::shared_ptr<const Storage> v_;
  bool owned_ = false;  // v_ was made by a LevelTexels (copies share it: use_count tells)
};

}  // namespace pineda::raster
