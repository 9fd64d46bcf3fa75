// glDrawBuffersEXT (GL_EXT_draw_buffers, OpenGL ES 2.0): on a framebuffer object, output i goes
// to COLOR_ATTACHMENTi_EXT or nowhere; on the window-system framebuffer, one output to BACK or
// nowhere (the window's own colour buffer: the back buffer, or the only one of a single-buffered
// surface).
#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/draw_buffer_list.h"

namespace pineda::gl {

void DrawBuffersEXT(Context& ctx, GLsizei n, const GLenum* bufs) {
  if (n < 0 || n > kMaxDrawBuffers)
    return ctx.record_error(GL_INVALID_VALUE, "n is negative or above MAX_DRAW_BUFFERS_EXT");
  if (n > 0 && !bufs) return;
  if (ctx.framebuffers.draw_binding) {
    for (GLsizei i = 0; i < n; ++i)
      if (bufs[i] != GL_NONE && bufs[i] != GLenum(GL_COLOR_ATTACHMENT0 + i))
        return ctx.record_error(GL_INVALID_OPERATION, "output i is neither NONE nor COLOR_ATTACHMENTi_EXT");
    return set_draw_buffers(ctx, n, bufs);
  }
  if (n != 1 || (bufs[0] != GL_BACK && bufs[0] != GL_NONE))
    return ctx.record_error(GL_INVALID_OPERATION, "the window-system framebuffer takes one buffer, BACK or NONE");
  const Drawable* d = ctx.draw_drawable();
  const GLenum window = d && !d->double_buffered ? GL_FRONT : GL_BACK;
  const GLenum buffer = bufs[0] == GL_BACK ? window : GL_NONE;
  set_draw_buffers(ctx, 1, &buffer);
}

}  // namespace pineda::gl
