// Client vertex arrays: the pointers, glDrawArrays, glDrawElements, glArrayElement,
// glInterleavedArrays.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>

#include "glapi/gl_entry_points.h"
#include "state/buffers/buffer_draw.h"
#include "state/color_material.h"
#include "state/es1/es1_enums.h"
#include "state/context.h"
#include "state/draw.h"
#include "state/programs/generic_attribs.h"
#include "state/enum_translate.h"
#include "state/render_mode_get.h"
#include "state/vertex_arrays/array_elements.h"
#include "state/vertex_arrays/held_draws.h"
#include "state/vertex_arrays/vertex_fetch.h"

namespace pineda::gl {
namespace {

void set_pointer(Context& ctx, ClientArray& array, GLint size, GLenum type, GLsizei stride, const void* ptr,
                 std::initializer_list<GLint> sizes, std::initializer_list<GLenum> types) {
  if (std::find(sizes.begin(), sizes.end(), size) == sizes.end())
    return ctx.record_error(GL_INVALID_VALUE, "size is not a size of this array");
  if (stride < 0) return ctx.record_error(GL_INVALID_VALUE, "stride is negative");
  if (std::find(types.begin(), types.end(), type) == types.end())
    return ctx.record_error(GL_INVALID_ENUM, "type is not a type of this array");
  array.size = size;
  array.type = type;
  array.stride = stride;
  array.pointer = ptr;
  array.buffer = ctx.buffers.array;
}

bool valid_mode(Context& ctx, GLenum mode) {
  raster::Primitive p;
  if (to_primitive(mode, p)) return true;
  ctx.record_error(GL_INVALID_ENUM, "mode is not a primitive type");
  return false;
}

// OpenGL ES 2.0: attribute 0 is not special, a program draws with any arrays or none.
bool can_fetch(const Context& ctx) {
  return ctx.vertex_array.active() || ctx.programs.arrays[0].active() || (ctx.es2() && ctx.programs.active());
}

// A draw of indexed elements, its indices in [lo, hi].
template <typename Index>
void draw_indexed_now(Context& ctx, GLenum mode, GLsizei count, const Index* indices, Index lo, Index hi) {
  const size_t range = size_t(hi) - lo + 1;
  if (range <= size_t(count) * 4) {
    // Dense indices: transform each referenced vertex once and pass the indices along.
    const ArrayVertices vertices = array_elements(ctx, range, [lo](size_t i) { return lo + i; });
    std::vector<uint32_t> rebased;
    std::span<const uint32_t> from_zero;
    if constexpr (std::is_same_v<Index, uint32_t>) {
      if (lo == 0) from_zero = std::span(indices, size_t(count));  // already based at the first vertex
    }
    if (from_zero.empty()) {
      rebased.resize(count);
      for (GLsizei i = 0; i < count; ++i) rebased[i] = uint32_t(indices[i] - lo);
      from_zero = rebased;
    }
    draw_array_vertices(ctx, mode, vertices, from_zero);
  } else {
    draw_array_vertices(ctx, mode, array_elements(ctx, size_t(count), [indices](size_t i) { return size_t(indices[i]); }), {});
  }
}

template <typename Index>
void draw_indexed(Context& ctx, GLenum mode, GLsizei count, const Index* indices) {
  Index lo = indices[0], hi = indices[0];
  for (GLsizei i = 1; i < count; ++i) {
    lo = std::min(lo, indices[i]);
    hi = std::max(hi, indices[i]);
  }
  if (!arrays_ready(ctx, hi)) return;
  if (count <= kMaxHeldIndices && may_hold_back(ctx, mode, count)) {
    hold_back(ctx.held_draws, count, [indices](GLsizei i) { return indices[i]; });
    take_current_index(ctx, indices[count - 1]);
    return;
  }
  const uint64_t errors = ctx.errors_recorded();
  draw_indexed_now(ctx, mode, count, indices, lo, hi);
  note_draw_ran(ctx, mode, ctx.errors_recorded() == errors);
  take_current_index(ctx, indices[count - 1]);  // GL leaves it indeterminate: the last element's
}

}  // namespace

// OpenGL ES 1.1 (table 2.4) takes its own sizes and types: GL_FIXED, bytes, no doubles or ints.
void VertexPointer(Context& ctx, GLint size, GLenum type, GLsizei stride, const void* ptr) {
  if (ctx.es1())
    return set_pointer(ctx, ctx.vertex_array, size, type, stride, ptr, {2, 3, 4}, {GL_BYTE, GL_SHORT, GL_FIXED, GL_FLOAT});
  set_pointer(ctx, ctx.vertex_array, size, type, stride, ptr, {2, 3, 4}, {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE});
}

void ColorPointer(Context& ctx, GLint size, GLenum type, GLsizei stride, const void* ptr) {
  if (ctx.es1())
    return set_pointer(ctx, ctx.color_array, size, type, stride, ptr, {4}, {GL_UNSIGNED_BYTE, GL_FIXED, GL_FLOAT});
  set_pointer(ctx, ctx.color_array, size, type, stride, ptr, {3, 4},
              {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE});
}

void NormalPointer(Context& ctx, GLenum type, GLsizei stride, const void* ptr) {
  if (ctx.es1())
    return set_pointer(ctx, ctx.normal_array, 3, type, stride, ptr, {3}, {GL_BYTE, GL_SHORT, GL_FIXED, GL_FLOAT});
  set_pointer(ctx, ctx.normal_array, 3, type, stride, ptr, {3}, {GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE});
}

void IndexPointer(Context& ctx, GLenum type, GLsizei stride, const void* ptr) {
  set_pointer(ctx, ctx.index_array, 1, type, stride, ptr, {1}, {GL_UNSIGNED_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE});
}

void TexCoordPointer(Context& ctx, GLint size, GLenum type, GLsizei stride, const void* ptr) {
  if (ctx.es1())
    return set_pointer(ctx, ctx.texture_units[ctx.client_active_texture].texcoord_array, size, type, stride, ptr,
                       {2, 3, 4}, {GL_BYTE, GL_SHORT, GL_FIXED, GL_FLOAT});
  set_pointer(ctx, ctx.texture_units[ctx.client_active_texture].texcoord_array, size, type, stride, ptr,
              {1, 2, 3, 4}, {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE});
}

void EdgeFlagPointer(Context& ctx, GLsizei stride, const void* ptr) {
  if (stride < 0) return ctx.record_error(GL_INVALID_VALUE, "stride is negative");
  ctx.edge_flag_array.stride = stride;
  ctx.edge_flag_array.pointer = ptr;
  ctx.edge_flag_array.buffer = ctx.buffers.array;
}

void DrawArrays(Context& ctx, GLenum mode, GLint first, GLsizei count) {
  if (!valid_mode(ctx, mode)) return;
  if (count < 0) return ctx.record_error(GL_INVALID_VALUE, "count is negative");
  if (first < 0) return ctx.record_error(GL_INVALID_VALUE, "first is negative");
  if (!check_draw_framebuffer(ctx)) return;
  if (count == 0 || !can_fetch(ctx) || !arrays_ready(ctx, size_t(first) + size_t(count) - 1)) return;
  if (may_hold_back(ctx, mode, count)) {
    hold_back(ctx.held_draws, count, [first](GLsizei i) { return size_t(first) + size_t(i); });
  } else {
    const uint64_t errors = ctx.errors_recorded();
    draw_array_vertices(ctx, mode, array_elements(ctx, size_t(count), [first](size_t i) { return size_t(first) + i; }), {});
    note_draw_ran(ctx, mode, ctx.errors_recorded() == errors);
  }
  take_current_index(ctx, size_t(first) + count - 1);  // GL leaves it indeterminate: the last element's
}

void DrawElements(Context& ctx, GLenum mode, GLsizei count, GLenum type, const void* indices) {
  if (!valid_mode(ctx, mode)) return;
  if (count < 0) return ctx.record_error(GL_INVALID_VALUE, "count is negative");
  if (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT)
    return ctx.record_error(GL_INVALID_ENUM, "type is not GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT or GL_UNSIGNED_INT");
  if (!check_draw_framebuffer(ctx)) return;
  if (count == 0 || !can_fetch(ctx)) return;
  indices = element_indices(ctx, indices, size_t(count) * gl_type_size(type));
  if (!indices) return;
  switch (type) {
    case GL_UNSIGNED_BYTE: return draw_indexed(ctx, mode, count, static_cast<const GLubyte*>(indices));
    case GL_UNSIGNED_SHORT: return draw_indexed(ctx, mode, count, static_cast<const GLushort*>(indices));
    default: return draw_indexed(ctx, mode, count, static_cast<const GLuint*>(indices));
  }
}

// Behaves as the Color/Normal/TexCoord/Vertex calls it stands for: the current values change.
void ArrayElement(Context& ctx, GLint i) {
  if (i < 0) return ctx.record_error(GL_INVALID_VALUE, "i is negative");
  // The array draws' fetch plan, built again only when a counted call other than this one
  // changed state since it was (this call changes nothing the plan reads: it sets the current
  // values of enabled arrays, which the plan reads from the arrays): a glBegin/glEnd of
  // glArrayElement calls built one per vertex (wireframe's strips).
  const StateKey key = ctx.state_key();
  if (key != ctx.vertex_fetch_planned && StateKey{key.context - 1, key.group} != ctx.vertex_fetch_planned)
    ctx.vertex_fetch_plan.build(ctx);
  ctx.vertex_fetch_planned = key;
  raster::VertexInput v;
  ctx.vertex_fetch_plan.fetch(size_t(i), v);
  if (ctx.color_array.active()) {
    std::copy(v.color, v.color + 4, ctx.current_color);
    track_color_material(ctx);
  }
  if (ctx.normal_array.active()) std::copy(v.normal, v.normal + 3, ctx.current_normal);
  if (ctx.edge_flag_array.active()) ctx.current_edge_flag = v.edge_flag;
  take_current_index(ctx, size_t(i));
  for (int u = 0; u < raster::kMaxTextureUnits; ++u) {
    TextureUnitState& unit = ctx.texture_units[u];
    if (unit.texcoord_array.active())
      std::copy(v.texcoord[u], v.texcoord[u] + 4, unit.current_texcoord);
  }
  if (can_fetch(ctx) && ctx.in_begin_end) {
    const size_t element = size_t(i);
    capture_immediate_generics(ctx, v, &element);
    ctx.immediate.push_back(v);
  }
}

void InterleavedArrays(Context& ctx, GLenum format, GLsizei stride, const void* pointer) {
  // Table 2.5 of the GL 1.1 spec: which arrays each format enables, sizes and offsets.
  struct Layout {
    GLenum format;
    bool tex, color, normal;
    GLint st, sc, sv;
    GLenum tc;
    int pc, pn, pv, s;  // offsets and default stride in units of sizeof(float)
  };
  constexpr int f = sizeof(GLfloat);
  static constexpr Layout layouts[] = {
      {GL_V2F, false, false, false, 0, 0, 2, 0, 0, 0, 0, 2},
      {GL_V3F, false, false, false, 0, 0, 3, 0, 0, 0, 0, 3},
      {GL_C4UB_V2F, false, true, false, 0, 4, 2, GL_UNSIGNED_BYTE, 0, 0, 1, 3},
      {GL_C4UB_V3F, false, true, false, 0, 4, 3, GL_UNSIGNED_BYTE, 0, 0, 1, 4},
      {GL_C3F_V3F, false, true, false, 0, 3, 3, GL_FLOAT, 0, 0, 3, 6},
      {GL_N3F_V3F, false, false, true, 0, 0, 3, 0, 0, 0, 3, 6},
      {GL_C4F_N3F_V3F, false, true, true, 0, 4, 3, GL_FLOAT, 0, 4, 7, 10},
      {GL_T2F_V3F, true, false, false, 2, 0, 3, 0, 0, 0, 2, 5},
      {GL_T4F_V4F, true, false, false, 4, 0, 4, 0, 0, 0, 4, 8},
      {GL_T2F_C4UB_V3F, true, true, false, 2, 4, 3, GL_UNSIGNED_BYTE, 2, 0, 3, 6},
      {GL_T2F_C3F_V3F, true, true, false, 2, 3, 3, GL_FLOAT, 2, 0, 5, 8},
      {GL_T2F_N3F_V3F, true, false, true, 2, 0, 3, 0, 0, 2, 5, 8},
      {GL_T2F_C4F_N3F_V3F, true, true, true, 2, 4, 3, GL_FLOAT, 2, 6, 9, 12},
      {GL_T4F_C4F_N3F_V4F, true, true, true, 4, 4, 4, GL_FLOAT, 4, 8, 11, 15},
  };
  if (stride < 0) return ctx.record_error(GL_INVALID_VALUE, "stride is negative");
  const Layout* layout = nullptr;
  for (const Layout& l : layouts)
    if (l.format == format) layout = &l;
  if (!layout) return ctx.record_error(GL_INVALID_ENUM, "format is not an interleaved array format");
  const GLsizei s = stride ? stride : layout->s * f;
  // Integer arithmetic: `pointer` is an offset into the array buffer when one is bound (often 0,
  // a null pointer, which C++ forbids offsetting).
  const auto at = [pointer](int offset) {
    return reinterpret_cast<const uint8_t*>(reinterpret_cast<uintptr_t>(pointer) + uintptr_t(offset));
  };
  const auto* base = at(0);
  ClientArray& tex = ctx.texture_units[ctx.client_active_texture].texcoord_array;
  tex.enabled = layout->tex;
  if (layout->tex) tex = {true, layout->st, GL_FLOAT, s, base, nullptr};
  ctx.color_array.enabled = layout->color;
  if (layout->color) ctx.color_array = {true, layout->sc, layout->tc, s, at(layout->pc * f), nullptr};
  ctx.normal_array.enabled = layout->normal;
  if (layout->normal) ctx.normal_array = {true, 3, GL_FLOAT, s, at(layout->pn * f), nullptr};
  ctx.index_array.enabled = false;
  ctx.edge_flag_array.enabled = false;
  ctx.vertex_array = {true, layout->sv, GL_FLOAT, s, at(layout->pv * f), nullptr};
  for (ClientArray* a : {&tex, &ctx.color_array, &ctx.normal_array, &ctx.vertex_array}) a->buffer = ctx.buffers.array;
}

void GetPointerv(Context& ctx, GLenum pname, void** params) {
  if (!params) return;
  if (render_mode_pointer(ctx, pname, params)) return;
  switch (pname) {
    case GL_VERTEX_ARRAY_POINTER: *params = const_cast<void*>(ctx.vertex_array.pointer); break;
    case GL_COLOR_ARRAY_POINTER: *params = const_cast<void*>(ctx.color_array.pointer); break;
    case GL_NORMAL_ARRAY_POINTER: *params = const_cast<void*>(ctx.normal_array.pointer); break;
    case GL_INDEX_ARRAY_POINTER: *params = const_cast<void*>(ctx.index_array.pointer); break;
    case GL_EDGE_FLAG_ARRAY_POINTER: *params = const_cast<void*>(ctx.edge_flag_array.pointer); break;
    case GL_FOG_COORD_ARRAY_POINTER: *params = const_cast<void*>(ctx.fog_coord_array.pointer); break;
    case GL_SECONDARY_COLOR_ARRAY_POINTER: *params = const_cast<void*>(ctx.secondary_color_array.pointer); break;
    case GL_TEXTURE_COORD_ARRAY_POINTER:
      *params = const_cast<void*>(ctx.texture_units[ctx.client_active_texture].texcoord_array.pointer);
      break;
    case GL_DEBUG_CALLBACK_FUNCTION:
      if (ctx.es1()) return ctx.record_error(GL_INVALID_ENUM, "pname is not a pointer of OpenGL ES 1");
      *params = reinterpret_cast<void*>(ctx.debug.callback);
      break;
    case GL_DEBUG_CALLBACK_USER_PARAM:
      if (ctx.es1()) return ctx.record_error(GL_INVALID_ENUM, "pname is not a pointer of OpenGL ES 1");
      *params = const_cast<void*>(ctx.debug.user_param);
      break;
    case GL_POINT_SIZE_ARRAY_POINTER_OES:
      if (!ctx.es1()) return ctx.record_error(GL_INVALID_ENUM, "pname is an OpenGL ES 1 pointer");
      *params = const_cast<void*>(ctx.point_size_array.pointer);
      break;
    default: ctx.record_error(GL_INVALID_ENUM, "pname is not a pointer name");
  }
}

}  // namespace pineda::gl
