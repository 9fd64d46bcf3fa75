#pragma once
// The vertex stage's output of the current draw (ctx.transformed).
#include <cstddef>
#include <span>

#include "raster/vertex.h"
#include "raster/zeroed_store.h"

namespace pineda {

// The store only grows: a draw after a smaller one would otherwise construct (zero) every
// vertex past the smaller count again, which the vertex stage then writes over (glmark2's
// terrain and shadow scenes alternate a mesh with a quad: 4-5% of their time). It grows
// into zeroed pages from the system rather than by constructing each vertex (raster/zeroed_store.h):
// half a million vertices are 120 MB, and their construction and first touch were most of a
// large draw's first frame.
class TransformedVertices {
 public:
  // Room for `count` vertices, each left as an earlier draw wrote it (zero if none did).
  std::span<raster::ClipVertex> resize(size_t count);
  std::span<raster::ClipVertex> vertices() { return {store_.data(), count_}; }

 private:
  raster::ZeroedStore<raster::ClipVertex> store_;
  size_t count_ = 0;
};

}  // namespace pineda
