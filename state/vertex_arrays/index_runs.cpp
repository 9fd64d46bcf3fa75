#include "state/vertex_arrays/index_runs.h"

#include <bit>

namespace pineda {

size_t IndexRuns::next(std::span<const uint32_t> indices, size_t position, size_t group, size_t max_vertices,
                       size_t vertex_count) {
  vertex_count_ = index_count_ = 0;
  if (group == 0 || max_vertices < group) return indices.size();
  const size_t slot_count = std::bit_ceil(2 * max_vertices);
  if (slots_.size() != slot_count || ++run_ == 0) {  // (a new size, or the run numbers wrapped)
    slots_.assign(slot_count, Slot{});
    run_ = 1;
  }
  const size_t mask = slot_count - 1;
  const size_t max_indices = kIndicesPerVertex * max_vertices;
  if (vertices_.size() < max_vertices) vertices_.resize(max_vertices);
  if (run_indices_.size() < max_indices) run_indices_.resize(max_indices);
  uint32_t* const vertex_out = vertices_.data();
  uint32_t* const index_out = run_indices_.data();
  size_t vertex_count_out = 0, index_count_out = 0;
  const uint32_t* const in = indices.data();
  while (indices.size() - position >= group && vertex_count_out + group <= max_vertices &&
         index_count_out + group <= max_indices) {
    bool inside = true;
    for (size_t k = 0; k < group; ++k) inside &= in[position + k] < vertex_count;
    if (inside) {
      for (size_t k = 0; k < group; ++k) {
        const uint32_t vertex = in[position + k];
        Slot& slot = slots_[vertex & mask];
        if (slot.run != run_ || slot.vertex != vertex) {
          slot = {run_, vertex, static_cast<uint32_t>(vertex_count_out)};
          vertex_out[vertex_count_out++] = vertex;
        }
        index_out[index_count_out++] = slot.position;
      }
    }
    position += group;
  }
  vertex_count_ = vertex_count_out;
  index_count_ = index_count_out;
  // An incomplete last primitive draws nothing.
  return indices.size() - position < group ? indices.size() : position;
}

}  // namespace pineda
