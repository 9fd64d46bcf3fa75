#include "state/transformed_vertices.h"

namespace pineda {

std::span<raster::ClipVertex> TransformedVertices::resize(size_t count) {
  store_.grow(count);
  count_ = count;
  return vertices();
}

}  // namespace pineda
