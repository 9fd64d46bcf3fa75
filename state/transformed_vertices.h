#pragma once
// The vertex stage's output of the current draw (ctx.transformed).
#include <cstddef>
#include <memory>
#include <span>

#include "raster/vertex.h"

namespace pineda {

// The store only grows: a draw after a smaller one would otherwise construct (zero) every
// vertex past the smaller count again, which the vertex stage then writes over (glmark2's
// terrain and shadow scenes alternate a mesh with a quad: 4-5% of their time). It grows
// into zeroed pages from the system rather than by constructing each vertex: half a million
// vertices are 120 MB, and their construction and first touch were most of a large draw's
// first frame.
class TransformedVertices {
 public:
  // Room for `count` vertices, each left as an earlier draw wrote it (zero if none did).
  std::span<raster::ClipVertex> resize(size_t count);
  std::span<raster::ClipVertex> vertices() { return {store_.get(), count_}; }

 private:
  struct Release {
    void operator()(raster::ClipVertex* p) const;
  };
  std::unique_ptr<raster::ClipVertex[], Release> store_;
  size_t capacity_ = 0;
  size_t count_ = 0;
};

}  // namespace pineda
