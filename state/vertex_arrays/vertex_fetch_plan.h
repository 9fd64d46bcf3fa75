// A draw's fixed-function vertex fetch worked out once from the arrays' state: which arrays give
// which fields, where each array's elements start and how many lie inside its buffer, and the
// values of the fields no array gives. Fetching a vertex is then a copy of those values and one
// read per enabled array, with fetch_vertex's result (the per-vertex tests of every array's
// state, and of every element against its buffer's store, were most of a small draw's fetch).
#pragma once
#include <cstddef>
#include <cstdint>

#include "raster/vertex.h"

namespace pineda {

class Context;
struct ClientArray;

class VertexFetchPlan {
 public:
  // The plan of `ctx`'s arrays as they are now (they must not change while it is used).
  void build(const Context& ctx);
  // fetch_vertex(ctx, index, out) for the context the plan was built from.
  void fetch(size_t index, raster::VertexInput& out) const;

 private:
  struct Read {
    const uint8_t* first = nullptr;  // element 0 (in client memory or the buffer's store)
    size_t stride = 0;
    size_t count = 0;  // the elements inside the buffer's store (SIZE_MAX in client memory)
    size_t field = 0;  // the field's offset in a VertexInput
    unsigned type = 0;
    int size = 0;
    bool normalize = false;
    bool edge_flag = false;  // the field is the edge flag (a GLboolean), not floats
  };
  void add(const ClientArray& array, bool normalize, size_t field, bool edge_flag = false);

  const Context* generic_position_ = nullptr;  // generic array 0 gives the position (fetch_array_position)
  raster::VertexInput values_;  // every field before the arrays are read
  static constexpr int kMaxReads = 6 + raster::kMaxTextureUnits;
  Read reads_[kMaxReads];
  int read_count_ = 0;
};

}  // namespace pineda
