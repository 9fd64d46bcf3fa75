#pragma once
// The vertex stage's output of the current draw (ctx.transformed).
#include <span>
#include <vector>

#include "raster/vertex.h"

namespace pineda {

// The store only grows: a draw after a smaller one would otherwise construct (zero) every
// vertex past the smaller count again, which the vertex stage then writes over (glmark2's
// terrain and shadow scenes alternate a mesh with a quad: 4-5% of their time).
class TransformedVertices {
 public:
  // Room for `count` vertices, each left as an earlier draw wrote it.
  std::span<raster::ClipVertex> resize(size_t count) {
    if (store_.size() < count) store_.resize(count);
    count_ = count;
    return vertices();
  }
  std::span<raster::ClipVertex> vertices() { return {store_.data(), count_}; }

 private:
  std::vector<raster::ClipVertex> store_;
  size_t count_ = 0;
};

}  // namespace pineda
