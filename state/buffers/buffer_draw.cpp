#include "state/buffers/buffer_draw.h"

#include <algorithm>
#include <cstdint>

#include "state/context.h"
#include "state/programs/generic_attribs.h"
#include "state/vertex_arrays/vertex_fetch.h"

namespace pineda {
namespace {

template <typename Visit>
void for_each_array(Context& ctx, Visit visit) {
  for (ClientArray* a : {&ctx.vertex_array, &ctx.color_array, &ctx.normal_array, &ctx.edge_flag_array,
                         &ctx.fog_coord_array, &ctx.secondary_color_array})
    visit(*a);
  for (TextureUnitState& unit : ctx.texture_units) visit(unit.texcoord_array);
}

size_t element_bytes(const ClientArray& a, bool edge_flags) {
  return edge_flags ? sizeof(GLboolean) : size_t(gl_type_size(a.type)) * size_t(a.size);
}

}  // namespace

bool arrays_ready(Context& ctx, size_t last_index) {
  // An element inside every buffer is so for the elements before it too: a draw of the same
  // state needs no look at the arrays up to the last one found ready.
  Context::ArraysReady& known = ctx.arrays_known_ready;
  const StateKey key = ctx.state_key();
  if (key == known.state && last_index <= known.through) return true;
  bool mapped = false, inside = true;
  for_each_array(ctx, [&](const ClientArray& a) {
    if (!a.active() || !a.buffer) return;
    mapped |= a.buffer->mapped;
    inside &= array_element(a, last_index, element_bytes(a, &a == &ctx.edge_flag_array)) != nullptr;
  });
  check_generic_arrays(ctx, last_index, mapped, inside);
  if (mapped) ctx.record_error(GL_INVALID_OPERATION, "the buffer of an enabled array is mapped");
  if (mapped || !inside) return false;
  if (key != known.state) known = {key, last_index};
  known.through = std::max(known.through, last_index);
  return true;
}

const void* element_indices(Context& ctx, const void* indices, size_t bytes) {
  const BufferObject* b = ctx.buffers.element_array.get();
  if (!b) return indices;
  if (b->mapped) {
    ctx.record_error(GL_INVALID_OPERATION, "the element array buffer is mapped");
    return nullptr;
  }
  return buffer_range(*b, reinterpret_cast<uintptr_t>(indices), bytes);
}

}  // namespace pineda
