// glMultiDrawArrays, glMultiDrawElements (GL 1.4, GL_EXT_multi_draw_arrays) and
// glDrawRangeElements (GL 1.2, GL_EXT_draw_range_elements): each is a sequence of
// glDrawArrays / glDrawElements, checked as a whole first.
#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/enum_translate.h"

namespace pineda::gl {
namespace {

bool valid_index_type(GLenum type) {
  return type == GL_UNSIGNED_BYTE || type == GL_UNSIGNED_SHORT || type == GL_UNSIGNED_INT;
}

// The error of a multi-draw call before anything is drawn (GL_NO_ERROR when it may run).
GlError multi_draw_error(GLenum mode, const GLsizei* count, GLsizei drawcount) {
  raster::Primitive p;
  if (!to_primitive(mode, p)) return {GL_INVALID_ENUM, "mode is not a primitive type"};
  if (drawcount < 0) return {GL_INVALID_VALUE, "drawcount is negative"};
  for (GLsizei i = 0; count && i < drawcount; ++i)
    if (count[i] < 0) return {GL_INVALID_VALUE, "an element of count is negative"};
  return GL_NO_ERROR;
}

GlError range_error(GLuint start, GLuint end) {
  return end < start ? GlError{GL_INVALID_VALUE, "end is less than start"} : GlError{};
}

void compile_error(Context& ctx, GlError error) {
  ctx.record_list_command([error](Context& c) { c.record_error(error); });
}

}  // namespace

void MultiDrawArrays(Context& ctx, GLenum mode, const GLint* first, const GLsizei* count, GLsizei drawcount) {
  if (GlError e = multi_draw_error(mode, count, drawcount); e != GL_NO_ERROR) return ctx.record_error(e);
  if (!first || !count) return;
  for (GLsizei i = 0; i < drawcount; ++i) DrawArrays(ctx, mode, first[i], count[i]);
}

void MultiDrawElements(Context& ctx, GLenum mode, const GLsizei* count, GLenum type, const void* const* indices,
                       GLsizei drawcount) {
  if (GlError e = multi_draw_error(mode, count, drawcount); e != GL_NO_ERROR) return ctx.record_error(e);
  if (!valid_index_type(type))
    return ctx.record_error(GL_INVALID_ENUM, "type is not GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT or GL_UNSIGNED_INT");
  if (!count || !indices) return;
  for (GLsizei i = 0; i < drawcount; ++i) DrawElements(ctx, mode, count[i], type, indices[i]);
}

void DrawRangeElements(Context& ctx, GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type,
                       const void* indices) {
  if (GlError e = range_error(start, end); e != GL_NO_ERROR) return ctx.record_error(e);
  DrawElements(ctx, mode, count, type, indices);
}

void compile_MultiDrawArrays(Context& ctx, GLenum mode, const GLint* first, const GLsizei* count, GLsizei drawcount) {
  if (GlError e = multi_draw_error(mode, count, drawcount); e != GL_NO_ERROR) return compile_error(ctx, e);
  if (!first || !count) return;
  for (GLsizei i = 0; i < drawcount; ++i) compile_DrawArrays(ctx, mode, first[i], count[i]);
}

void compile_MultiDrawElements(Context& ctx, GLenum mode, const GLsizei* count, GLenum type,
                               const void* const* indices, GLsizei drawcount) {
  if (GlError e = multi_draw_error(mode, count, drawcount); e != GL_NO_ERROR) return compile_error(ctx, e);
  if (!valid_index_type(type)) return compile_error(ctx, GL_INVALID_ENUM);
  if (!count || !indices) return;
  for (GLsizei i = 0; i < drawcount; ++i) compile_DrawElements(ctx, mode, count[i], type, indices[i]);
}

void compile_DrawRangeElements(Context& ctx, GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type,
                               const void* indices) {
  if (GlError e = range_error(start, end); e != GL_NO_ERROR) return compile_error(ctx, e);
  compile_DrawElements(ctx, mode, count, type, indices);
}

// The EXT names.
void MultiDrawArraysEXT(Context& ctx, GLenum mode, const GLint* first, const GLsizei* count, GLsizei drawcount) {
  MultiDrawArrays(ctx, mode, first, count, drawcount);
}
void compile_MultiDrawArraysEXT(Context& ctx, GLenum mode, const GLint* first, const GLsizei* count,
                                GLsizei drawcount) {
  compile_MultiDrawArrays(ctx, mode, first, count, drawcount);
}
void MultiDrawElementsEXT(Context& ctx, GLenum mode, const GLsizei* count, GLenum type, const void* const* indices,
                          GLsizei drawcount) {
  MultiDrawElements(ctx, mode, count, type, indices, drawcount);
}
void compile_MultiDrawElementsEXT(Context& ctx, GLenum mode, const GLsizei* count, GLenum type,
                                  const void* const* indices, GLsizei drawcount) {
  compile_MultiDrawElements(ctx, mode, count, type, indices, drawcount);
}
void DrawRangeElementsEXT(Context& ctx, GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type,
                          const void* indices) {
  DrawRangeElements(ctx, mode, start, end, count, type, indices);
}
void compile_DrawRangeElementsEXT(Context& ctx, GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type,
                                  const void* indices) {
  compile_DrawRangeElements(ctx, mode, start, end, count, type, indices);
}

}  // namespace pineda::gl
