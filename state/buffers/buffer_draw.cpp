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
  // While the state stays the same, so do how many elements the arrays' buffers hold.
  Context::ArraysReady& known = ctx.arrays_known_ready;
  const StateKey key = ctx.state_key();
  if (key == known.state && last_index < known.elements) return true;
  bool mapped = false, client_memory = false;
  size_t elements = SIZE_MAX;  // that every enabled buffer-backed array holds
  for_each_array(ctx, [&](const ClientArray& a) {
    client_memory |= a.active() && !a.buffer;
    if (!a.active() || !a.buffer) return;
    mapped |= a.buffer->mapped;
    const size_t bytes = element_bytes(a, &a == &ctx.edge_flag_array);  // array_element's test
    elements = std::min(elements, elements_inside(*a.buffer, reinterpret_cast<uintptr_t>(a.pointer),
                                                  a.stride ? size_t(a.stride) : bytes, bytes));
  });
  check_generic_arrays(ctx, mapped, elements);
  if (mapped) {
    ctx.record_error(GL_INVALID_OPERATION, "the buffer of an enabled array is mapped");
    return false;
  }
  for (const GenericArray& a : ctx.programs.arrays) client_memory |= a.active() && !a.buffer;
  known = {key, elements, client_memory};
  return last_index < elements;
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
