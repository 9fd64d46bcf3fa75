// The fog coordinate and secondary colour arrays (GL 1.4).
#include <initializer_list>

#include "glapi/gl_entry_points.h"
#include "state/context.h"

namespace pineda::gl {
namespace {

void set_array(Context& ctx, ClientArray& array, GLint size, GLenum type, GLsizei stride, const void* ptr,
               std::initializer_list<GLenum> types) {
  if (stride < 0) return ctx.record_error(GL_INVALID_VALUE, "stride is negative");
  bool known = false;
  for (GLenum t : types) known |= t == type;
  if (!known) return ctx.record_error(GL_INVALID_ENUM, "type is not a type of this array");
  array.size = size;
  array.type = type;
  array.stride = stride;
  array.pointer = ptr;
  array.buffer = ctx.buffers.array;  // with a buffer bound, ptr is an offset into it
}

void fog_coord_pointer(Context& ctx, GLenum type, GLsizei stride, const void* ptr) {
  set_array(ctx, ctx.fog_coord_array, 1, type, stride, ptr, {GL_FLOAT, GL_DOUBLE});
}

void secondary_color_pointer(Context& ctx, GLint size, GLenum type, GLsizei stride, const void* ptr) {
  if (size != 3) return ctx.record_error(GL_INVALID_VALUE, "size is not 3");
  set_array(ctx, ctx.secondary_color_array, size, type, stride, ptr,
            {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE});
}

}  // namespace

void FogCoordPointer(Context& ctx, GLenum type, GLsizei stride, const void* ptr) {
  fog_coord_pointer(ctx, type, stride, ptr);
}
void FogCoordPointerEXT(Context& ctx, GLenum type, GLsizei stride, const void* ptr) {
  fog_coord_pointer(ctx, type, stride, ptr);
}
void SecondaryColorPointer(Context& ctx, GLint size, GLenum type, GLsizei stride, const void* ptr) {
  secondary_color_pointer(ctx, size, type, stride, ptr);
}
void SecondaryColorPointerEXT(Context& ctx, GLint size, GLenum type, GLsizei stride, const void* ptr) {
  secondary_color_pointer(ctx, size, type, stride, ptr);
}

}  // namespace pineda::gl
