// glDrawBuffers (GL 2.0, ARB_draw_buffers, ATI_draw_buffers): on the window-system framebuffer
// its colour buffers are the front left one and, when double-buffered, the back left one; on a
// framebuffer object, its colour attachments.
#include <algorithm>
#include <vector>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/draw_buffer_list.h"
#include "state/framebuffers/framebuffer_object.h"
#include "shader/program.h"

namespace pineda {

static_assert(kMaxDrawBuffers == raster::kMaxColorTargets, "the colour buffers a draw writes");

namespace {

enum BufferBits : unsigned { kFrontLeft = 1, kBackLeft = 2 };

// What one glDrawBuffers entry names, and the error it gets when it cannot be used.
struct Named {
  unsigned bits = 0;  // the buffers of the drawable it names
  GlError error;
};

// With a framebuffer object bound (GL 3.0 4.2.1): NONE or a colour attachment, each once.
Named name_object_buffer(GLenum buffer) {
  if (buffer == GL_NONE) return {};
  if (buffer >= GL_COLOR_ATTACHMENT0 && buffer <= GL_COLOR_ATTACHMENT15) {
    const int point = attachment_point(buffer);
    if (point < 0) return {0, {GL_INVALID_OPERATION, "a buffer is above GL_MAX_COLOR_ATTACHMENTS"}};
    return {1u << point, {}};
  }
  switch (buffer) {
    // Names of several buffers: INVALID_ENUM, as on the window-system framebuffer (GL 4.5).
    case GL_FRONT: case GL_LEFT: case GL_RIGHT: case GL_FRONT_AND_BACK:
      return {0, {GL_INVALID_ENUM, "a buffer names several buffers"}};
    // The window-system framebuffer's buffers, which an object has not.
    case GL_BACK: case GL_FRONT_LEFT: case GL_FRONT_RIGHT: case GL_BACK_LEFT: case GL_BACK_RIGHT: case GL_AUX0:
    case GL_AUX1: case GL_AUX2: case GL_AUX3:
      return {0, {GL_INVALID_OPERATION, "a buffer is a window-system buffer and a framebuffer object is bound"}};
    default: return {0, {GL_INVALID_ENUM, "a buffer is not GL_NONE or a colour attachment"}};
  }
}

Named name_buffer(const Context& ctx, GLenum buffer) {
  if (ctx.framebuffers.draw_binding) return name_object_buffer(buffer);
  const Drawable* d = ctx.draw_drawable();
  switch (buffer) {
    case GL_NONE: return {};
    case GL_FRONT_LEFT: return {kFrontLeft, {}};
    case GL_BACK_LEFT:
      if (d && d->double_buffered) return {kBackLeft, {}};
      return {0, {GL_INVALID_OPERATION, "a buffer is GL_BACK_LEFT and the drawable is single-buffered"}};
    // Buffers GL defines that a Pineda drawable never has (no stereo, no aux buffers).
    case GL_FRONT_RIGHT: case GL_BACK_RIGHT: case GL_AUX0: case GL_AUX1: case GL_AUX2: case GL_AUX3:
      return {0, {GL_INVALID_OPERATION, "a buffer is one the drawable does not have (no stereo, no aux)"}};
    // Names of several buffers: GL 2.0 4.2.1 says INVALID_OPERATION; GL 4.5 corrected it to
    // INVALID_ENUM, which Mesa (and the Khronos conformance tests) use at every version.
    case GL_FRONT: case GL_BACK: case GL_LEFT: case GL_RIGHT: case GL_FRONT_AND_BACK:
      return {0, {GL_INVALID_ENUM, "a buffer names several buffers"}};
    default:
      // A framebuffer object's attachments, which the window-system framebuffer has not.
      if (buffer >= GL_COLOR_ATTACHMENT0 && buffer <= GL_COLOR_ATTACHMENT15)
        return {0, {GL_INVALID_OPERATION, "a buffer is a colour attachment and no framebuffer object is bound"}};
      return {0, {GL_INVALID_ENUM, "a buffer is not a colour buffer name"}};
  }
}

}  // namespace

bool query_draw_buffers(Context& ctx, unsigned pname, GetValues& out) {
  if (pname == GL_MAX_DRAW_BUFFERS) {
    out = get_ints({kMaxDrawBuffers});
    return true;
  }
  if (pname < GL_DRAW_BUFFER0 || pname >= GL_DRAW_BUFFER0 + unsigned(kMaxDrawBuffers)) return false;
  const unsigned i = pname - GL_DRAW_BUFFER0;
  GLenum buffer = i == 0 ? ctx.draw_buffer : ctx.extra_draw_buffers[i - 1];
  // OpenGL ES names the window's colour buffer BACK, single-buffered or not (EXT_draw_buffers).
  if (ctx.es2() && !ctx.framebuffers.draw_binding && buffer == GL_FRONT) buffer = GL_BACK;
  out = get_enums({double(buffer)});
  return true;
}

void set_draw_buffers(Context& ctx, int n, const GLenum* bufs) {
  const bool object = ctx.framebuffers.draw_binding != 0;
  if (object) resolve_rendered_textures(ctx);
  ctx.draw_buffer = n > 0 ? bufs[0] : GL_NONE;
  for (int i = 1; i < kMaxDrawBuffers; ++i) ctx.extra_draw_buffers[i - 1] = i < n ? bufs[i] : GL_NONE;
  // The renderer targets the selected colour buffers from now on.
  if (object) refresh_framebuffer_views(ctx);
  else ctx.drawable_changed();
}

}  // namespace pineda

namespace pineda::gl {

void DrawBuffers(Context& ctx, GLsizei n, const GLenum* bufs) {
  if (n < 0 || n > kMaxDrawBuffers)
    return ctx.record_error(GL_INVALID_VALUE, "n is negative or above GL_MAX_DRAW_BUFFERS");
  if (n > 0 && !bufs) return;
  unsigned used = 0;
  for (GLsizei i = 0; i < n; ++i) {
    const Named named = name_buffer(ctx, bufs[i]);
    if (named.error != GL_NO_ERROR) return ctx.record_error(named.error);
    if (named.bits & used) return ctx.record_error(GL_INVALID_OPERATION, "bufs names a buffer twice");
    used |= named.bits;
  }
  set_draw_buffers(ctx, n, bufs);
}

void DrawBuffersARB(Context& ctx, GLsizei n, const GLenum* bufs) { DrawBuffers(ctx, n, bufs); }
void DrawBuffersATI(Context& ctx, GLsizei n, const GLenum* bufs) { DrawBuffers(ctx, n, bufs); }

// In a display list: the names are copied only for an `n` that DrawBuffers accepts (found by the
// API fuzzer: n = 2^31 - 1 copied 8 GB from a 5-name array); DrawBuffers names the error when
// the list runs.
void compile_DrawBuffers(Context& ctx, GLsizei n, const GLenum* bufs) {
  std::vector<GLenum> copy;
  if (n >= 0 && n <= kMaxDrawBuffers && bufs) copy.assign(bufs, bufs + n);
  ctx.record_list_command([n, copy = std::move(copy), null = !bufs](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION, "called between glBegin and glEnd");
    DrawBuffers(c, n, null ? nullptr : copy.data());
  });
}
void compile_DrawBuffersARB(Context& ctx, GLsizei n, const GLenum* bufs) { compile_DrawBuffers(ctx, n, bufs); }
void compile_DrawBuffersATI(Context& ctx, GLsizei n, const GLenum* bufs) { compile_DrawBuffers(ctx, n, bufs); }

}  // namespace pineda::gl
