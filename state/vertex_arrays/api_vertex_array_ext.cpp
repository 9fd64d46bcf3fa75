// GL_EXT_vertex_array: the GL 1.1 vertex arrays under their extension names. The pointer
// calls take a `count` that only has to be non-negative (EXT_vertex_array, Errors).
#include "glapi/gl_entry_points.h"
#include "state/context.h"

namespace pineda::gl {
namespace {

bool count_valid(Context& ctx, GLsizei count) {
  if (count >= 0) return true;
  ctx.record_error(GL_INVALID_VALUE, "count is negative");
  return false;
}

}  // namespace

void ColorPointerEXT(Context& ctx, GLint size, GLenum type, GLsizei stride, GLsizei count, const void* pointer) {
  if (count_valid(ctx, count)) ColorPointer(ctx, size, type, stride, pointer);
}
void EdgeFlagPointerEXT(Context& ctx, GLsizei stride, GLsizei count, const GLboolean* pointer) {
  if (count_valid(ctx, count)) EdgeFlagPointer(ctx, stride, pointer);
}
void IndexPointerEXT(Context& ctx, GLenum type, GLsizei stride, GLsizei count, const void* pointer) {
  if (count_valid(ctx, count)) IndexPointer(ctx, type, stride, pointer);
}
void NormalPointerEXT(Context& ctx, GLenum type, GLsizei stride, GLsizei count, const void* pointer) {
  if (count_valid(ctx, count)) NormalPointer(ctx, type, stride, pointer);
}
void TexCoordPointerEXT(Context& ctx, GLint size, GLenum type, GLsizei stride, GLsizei count, const void* pointer) {
  if (count_valid(ctx, count)) TexCoordPointer(ctx, size, type, stride, pointer);
}
void VertexPointerEXT(Context& ctx, GLint size, GLenum type, GLsizei stride, GLsizei count, const void* pointer) {
  if (count_valid(ctx, count)) VertexPointer(ctx, size, type, stride, pointer);
}
void GetPointervEXT(Context& ctx, GLenum pname, void** params) { GetPointerv(ctx, pname, params); }
void ArrayElementEXT(Context& ctx, GLint i) { ArrayElement(ctx, i); }
void DrawArraysEXT(Context& ctx, GLenum mode, GLint first, GLsizei count) { DrawArrays(ctx, mode, first, count); }
void compile_ArrayElementEXT(Context& ctx, GLint i) { compile_ArrayElement(ctx, i); }
void compile_DrawArraysEXT(Context& ctx, GLenum mode, GLint first, GLsizei count) {
  compile_DrawArrays(ctx, mode, first, count);
}

}  // namespace pineda::gl
