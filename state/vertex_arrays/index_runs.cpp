#include "state/vertex_arrays/index_runs.h"

#include <bit>

namespace pineda {

size_t IndexRuns::next(std::span<const uint32_t> indices, size_t position, size_t group, size_t max_vertices,
                       size_t vertex_count, std::vector<uint32_t>& vertices, std::vector<uint32_t>& run_indices) {
  vertices.clear();
  run_indices.clear();
  if (group == 0 || max_vertices < group) return indices.size();
  const size_t slot_count = std::bit_ceil(2 * max_vertices);
  if (slots_.size() < slot_count) slots_.assign(slot_count, Slot{});
  const size_t mask = slot_count - 1;
  ++run_;
  while (indices.size() - position >= group && vertices.size() + group <= max_vertices) {
    bool inside = true;
    for (size_t k = 0; k < group; ++k) inside &= indices[position + k] < vertex_count;
    if (!inside) {
      position += group;
      continue;
    }
    for (size_t k = 0; k < group; ++k) {
      const uint32_t vertex = indices[position + k];
      Slot& slot = slots_[vertex & mask];
      if (slot.run != run_ || slot.vertex != vertex) {
        slot = {run_, vertex, static_cast<uint32_t>(vertices.size())};
        vertices.push_back(vertex);
      }
      run_indices.push_back(slot.position);
    }
    position += group;
  }
  // An incomplete last primitive draws nothing.
  return indices.size() - position < group ? indices.size() : position;
}

}  // namespace pineda
