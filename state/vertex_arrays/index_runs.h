// A large indexed draw of independent primitives in runs of a bounded number of vertices: each
// run's vertices are fetched, transformed and drawn while they are in the cache, instead of the
// whole draw's vertices (240 bytes each after transform) going through memory between the
// stages, and being first touched in the first frame.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace pineda {

class IndexRuns {
 public:
  // The run of `indices` from `position` on: whole primitives of `group` indices (at least
  // one, and as many as keep the run's distinct vertices at most `max_vertices`, which must be
  // at least `group`). `vertices` receives the run's vertices (the indices they have in the
  // draw, each once, in the order of first use) and `run_indices` each index's position in
  // `vertices`. Returns the position after the run. Left out, as primitive assembly leaves them
  // out: an incomplete last primitive, and primitives with an index past `vertex_count`.
  size_t next(std::span<const uint32_t> indices, size_t position, size_t group, size_t max_vertices,
              size_t vertex_count, std::vector<uint32_t>& vertices, std::vector<uint32_t>& run_indices);

 private:
  // Where a draw vertex was put in the current run, by the vertex's low bits: a vertex whose
  // slot another one took gets a second place in the run (the same values, transformed twice).
  struct Slot {
    uint64_t run = 0;  // 0: none
    uint32_t vertex = 0, position = 0;
  };
  std::vector<Slot> slots_;
  uint64_t run_ = 0;
};

}  // namespace pineda
