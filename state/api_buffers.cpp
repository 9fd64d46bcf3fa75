// glDrawBuffer and glReadBuffer: which colour buffer of the drawable is drawn and read.
#include "glapi/gl_entry_points.h"
#include "state/context.h"

namespace pineda::gl {
namespace {

// A drawable has a front buffer, and a back buffer when double-buffered; no aux buffers.
bool buffer_exists(const Context& ctx, GLenum buffer) {
  const Drawable* d = ctx.draw_drawable();
  const bool double_buffered = d && d->double_buffered;
  switch (buffer) {
    case GL_FRONT: case GL_LEFT: case GL_FRONT_LEFT: case GL_FRONT_AND_BACK: case GL_NONE: return true;
    case GL_BACK: case GL_BACK_LEFT: return double_buffered;
    default: return false;
  }
}

bool is_buffer_enum(GLenum b) {
  switch (b) {
    case GL_NONE: case GL_FRONT_LEFT: case GL_FRONT_RIGHT: case GL_BACK_LEFT: case GL_BACK_RIGHT: case GL_FRONT:
    case GL_BACK: case GL_LEFT: case GL_RIGHT: case GL_FRONT_AND_BACK: case GL_AUX0: case GL_AUX1: case GL_AUX2:
    case GL_AUX3:
      return true;
    default: return b >= GL_COLOR_ATTACHMENT0 && b <= GL_COLOR_ATTACHMENT15;  // no window buffer: INVALID_OPERATION
  }
}

}  // namespace

void DrawBuffer(Context& ctx, GLenum buffer) {
  if (ctx.framebuffers.draw_binding) return set_object_color_buffer(ctx, buffer, false);
  if (!is_buffer_enum(buffer)) return ctx.record_error(GL_INVALID_ENUM, "mode is not a colour buffer name");
  if (!buffer_exists(ctx, buffer))
    return ctx.record_error(GL_INVALID_OPERATION, "the drawable has no such colour buffer");
  ctx.draw_buffer = buffer;
  ctx.extra_draw_buffers.fill(GL_NONE);  // GL 2.0 4.2.1: DrawBuffer sets the other outputs' to NONE
  ctx.drawable_changed();  // the renderer targets the selected colour buffer from now on
}

void ReadBuffer(Context& ctx, GLenum buffer) {
  if (ctx.framebuffers.read_binding) return set_object_color_buffer(ctx, buffer, true);
  if (!is_buffer_enum(buffer) || buffer == GL_FRONT_AND_BACK || buffer == GL_NONE)
    return ctx.record_error(GL_INVALID_ENUM, "mode is not a colour buffer name that selects one buffer");
  if (!buffer_exists(ctx, buffer))
    return ctx.record_error(GL_INVALID_OPERATION, "the drawable has no such colour buffer");
  ctx.read_buffer = buffer;
}

}  // namespace pineda::gl
