// glPointSizePointerOES (OpenGL ES 1.1, OES_point_size_array): a size per vertex, which the
// draw passes to the vertex stage (PointParameters::size_per_vertex) before attenuation.
#include "glapi/gl_entry_points.h"
#include "state/context.h"

namespace pineda::gl {

void PointSizePointerOES(Context& ctx, GLenum type, GLsizei stride, const void* pointer) {
  if (stride < 0) return ctx.record_error(GL_INVALID_VALUE, "stride is negative");
  if (type != GL_FIXED && type != GL_FLOAT)
    return ctx.record_error(GL_INVALID_ENUM, "type is not GL_FIXED or GL_FLOAT");
  ctx.point_size_array.type = type;
  ctx.point_size_array.stride = stride;
  ctx.point_size_array.pointer = pointer;
  ctx.point_size_array.buffer = ctx.buffers.array;
}

}  // namespace pineda::gl
