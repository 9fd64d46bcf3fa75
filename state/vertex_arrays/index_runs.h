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
  // one, and as many as keep the run's vertices at most `max_vertices`, which must be at least
  // `group`, and its indices at most kIndicesPerVertex times that). vertices() are then the
  // run's vertices (the indices they have in the draw, in the order of first use; one appears
  // twice only when another vertex took its slot between its uses) and run_indices() each index's
  // position in vertices(). Returns the position after the run. Left out, as primitive assembly
  // leaves them out: an incomplete last primitive, and primitives with an index past
  // `vertex_count`.
  size_t next(std::span<const uint32_t> indices, size_t position, size_t group, size_t max_vertices,
              size_t vertex_count);
  std::span<const uint32_t> vertices() const { return {vertices_.data(), vertex_count_}; }
  std::span<const uint32_t> run_indices() const { return {run_indices_.data(), index_count_}; }

 private:
  // Where a draw vertex was put in the current run, by the vertex's low bits: a vertex whose
  // slot another one took gets a second place in the run (the same values, transformed twice).
  struct Slot {
    uint32_t run = 0;  // 0: none
    uint32_t vertex = 0, position = 0;
  };
  static constexpr size_t kIndicesPerVertex = 8;
  std::vector<Slot> slots_;
  uint32_t run_ = 0;
  // The current run, at the front of rooms of the bounds' size (written through pointers:
  // no capacity test per index, as push_back makes).
  std::vector<uint32_t> vertices_, run_indices_;
  size_t vertex_count_ = 0, index_count_ = 0;
};

}  // namespace pineda
