// glGen/Delete/Is/BindFramebuffer(s), glCheckFramebufferStatus, and glDrawBuffer/glReadBuffer
// while a framebuffer object is bound.
#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/framebuffers/framebuffer_object.h"

namespace pineda {

// Which bindings a framebuffer target names; false for an invalid target.
bool framebuffer_target(GLenum target, bool& draw, bool& read) {
  draw = target == GL_FRAMEBUFFER || target == GL_DRAW_FRAMEBUFFER;
  read = target == GL_FRAMEBUFFER || target == GL_READ_FRAMEBUFFER;
  return draw || read;
}

namespace {

void bind(Context& ctx, bool draw, bool read, GLuint name) {
  FramebufferState& fs = ctx.framebuffers;
  resolve_rendered_textures(ctx);
  if (draw) {
    if (FramebufferObject* old = fs.draw_object()) {
      old->draw_buffer = ctx.draw_buffer;
      old->extra_draw_buffers = ctx.extra_draw_buffers;
    } else {
      fs.window_draw_buffer = ctx.draw_buffer;
      fs.window_extra_draw_buffers = ctx.extra_draw_buffers;
    }
    fs.draw_binding = name;
    const FramebufferObject* now = fs.draw_object();
    ctx.draw_buffer = now ? now->draw_buffer : fs.window_draw_buffer;
    ctx.extra_draw_buffers = now ? now->extra_draw_buffers : fs.window_extra_draw_buffers;
  }
  if (read) {
    if (FramebufferObject* old = fs.read_object()) old->read_buffer = ctx.read_buffer;
    else fs.window_read_buffer = ctx.read_buffer;
    fs.read_binding = name;
    const FramebufferObject* now = fs.read_object();
    ctx.read_buffer = now ? now->read_buffer : fs.window_read_buffer;
  }
  refresh_framebuffer_views(ctx);
}

GLenum check_status(Context& ctx, GLenum target, bool ext_rules) {
  bool draw = false, read = false;
  if (!framebuffer_target(target, draw, read)) {
    ctx.record_error(GL_INVALID_ENUM, "target is not a framebuffer target");
    return 0;
  }
  FramebufferObject* fb = draw ? ctx.framebuffers.draw_object() : ctx.framebuffers.read_object();
  if (!fb) {
    const Drawable* window = draw ? ctx.window_draw_drawable() : ctx.window_read_drawable();
    return window ? GL_FRAMEBUFFER_COMPLETE : GL_FRAMEBUFFER_UNDEFINED;
  }
  return framebuffer_status(ctx, *fb, ext_rules);
}

bool is_window_buffer(GLenum b) {
  switch (b) {
    case GL_FRONT_LEFT: case GL_FRONT_RIGHT: case GL_BACK_LEFT: case GL_BACK_RIGHT: case GL_FRONT: case GL_BACK:
    case GL_LEFT: case GL_RIGHT: case GL_FRONT_AND_BACK: case GL_AUX0: case GL_AUX1: case GL_AUX2: case GL_AUX3:
      return true;
    default: return false;
  }
}

}  // namespace

// glDrawBuffer/glReadBuffer with a framebuffer object bound: NONE or one of its colour
// attachments; a window-system buffer or an attachment past the maximum is
// INVALID_OPERATION, any other value INVALID_ENUM.
void set_object_color_buffer(Context& ctx, GLenum buffer, bool read) {
  FramebufferState& fs = ctx.framebuffers;
  FramebufferObject* fb = read ? fs.read_object() : fs.draw_object();
  const bool attachment = buffer >= GL_COLOR_ATTACHMENT0 && buffer <= GL_COLOR_ATTACHMENT15;
  if (buffer != GL_NONE && !attachment && is_window_buffer(buffer))
    return ctx.record_error(GL_INVALID_OPERATION, "mode is a window-system buffer and a framebuffer object is bound");
  if (buffer != GL_NONE && !attachment)
    return ctx.record_error(GL_INVALID_ENUM, "mode is not GL_NONE or a colour attachment");
  if (attachment && attachment_point(buffer) < 0)
    return ctx.record_error(GL_INVALID_OPERATION, "mode is above GL_MAX_COLOR_ATTACHMENTS");
  resolve_rendered_textures(ctx);
  if (read) {
    fb->read_buffer = ctx.read_buffer = buffer;
  } else {
    fb->draw_buffer = ctx.draw_buffer = buffer;
    fb->extra_draw_buffers = ctx.extra_draw_buffers = {};  // GL 2.0 4.2.1: the other outputs' become NONE
  }
  refresh_framebuffer_views(ctx);
}

}  // namespace pineda

namespace pineda::gl {

void GenFramebuffers(Context& ctx, GLsizei n, GLuint* framebuffers) {
  if (n < 0) return ctx.record_error(GL_INVALID_VALUE, "n is negative");
  if (!framebuffers) return;
  FramebufferState& fs = ctx.framebuffers;
  GLuint next = 1;
  for (GLsizei i = 0; i < n; ++i) {
    while (fs.framebuffers.count(next) || fs.generated_framebuffers.count(next)) ++next;
    fs.generated_framebuffers.insert(next);
    framebuffers[i] = next;
  }
}

void DeleteFramebuffers(Context& ctx, GLsizei n, const GLuint* framebuffers) {
  if (n < 0) return ctx.record_error(GL_INVALID_VALUE, "n is negative");
  if (!framebuffers) return;
  FramebufferState& fs = ctx.framebuffers;
  for (GLsizei i = 0; i < n; ++i) {
    const GLuint name = framebuffers[i];
    if (name == 0) continue;
    // Deleting a bound framebuffer binds the window-system one in its place.
    const bool draw = fs.draw_binding == name, read = fs.read_binding == name;
    if (draw || read) bind(ctx, draw, read, 0);
    fs.framebuffers.erase(name);
    fs.generated_framebuffers.erase(name);
    ctx.debug.forget_label(GL_FRAMEBUFFER, name);
  }
}

GLboolean IsFramebuffer(Context& ctx, GLuint framebuffer) {
  return ctx.framebuffers.find(framebuffer) ? GL_TRUE : GL_FALSE;
}

void BindFramebuffer(Context& ctx, GLenum target, GLuint framebuffer) {
  bool draw = false, read = false;
  if (!framebuffer_target(target, draw, read))
    return ctx.record_error(GL_INVALID_ENUM, "target is not a framebuffer target");
  FramebufferState& fs = ctx.framebuffers;
  if (framebuffer != 0 && !fs.find(framebuffer)) {  // compatibility GL: any name may be bound
    fs.framebuffers[framebuffer] = std::make_unique<FramebufferObject>();
    fs.generated_framebuffers.erase(framebuffer);
  }
  bind(ctx, draw, read, framebuffer);
}

GLenum CheckFramebufferStatus(Context& ctx, GLenum target) { return check_status(ctx, target, false); }
GLenum CheckFramebufferStatusEXT(Context& ctx, GLenum target) { return check_status(ctx, target, true); }

}  // namespace pineda::gl
