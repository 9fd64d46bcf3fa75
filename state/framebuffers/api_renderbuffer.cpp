// glGen/Delete/Is/BindRenderbuffer(s), glRenderbufferStorage(Multisample) and
// glGetRenderbufferParameteriv.
#include <algorithm>
#include <new>

#include "glapi/gl_entry_points.h"
#include "state/es2/es2_rules.h"
#include "state/context.h"
#include "state/framebuffers/framebuffer_object.h"

namespace pineda::gl {
namespace {

Renderbuffer* bound_renderbuffer(Context& ctx) { return ctx.framebuffers.bound_renderbuffer.get(); }

void storage(Context& ctx, GLenum target, GLsizei samples, GLenum internalformat, GLsizei width, GLsizei height) {
  if (target != GL_RENDERBUFFER) return ctx.record_error(GL_INVALID_ENUM, "target is not GL_RENDERBUFFER");
  const std::optional<RenderableFormat> format = renderbuffer_format(internalformat);
  if (!format) return ctx.record_error(GL_INVALID_ENUM, "internalformat is not a renderable format");
  if (width < 0 || height < 0 || width > kMaxRenderbufferSize || height > kMaxRenderbufferSize)
    return ctx.record_error(GL_INVALID_VALUE, "width or height is negative or above GL_MAX_RENDERBUFFER_SIZE");
  if (samples > kMaxSamples) return ctx.record_error(GL_INVALID_VALUE, "samples is greater than GL_MAX_SAMPLES");
  Renderbuffer* rb = bound_renderbuffer(ctx);
  if (!rb) return ctx.record_error(GL_INVALID_OPERATION, "no renderbuffer is bound");
  resolve_rendered_textures(ctx);
  // Rendering queued here may still write the old pixels (and another context's keeps them
  // alive: RenderbufferPixels).
  ctx.finish();
  Renderbuffer fresh;
  fresh.width = width;
  fresh.height = height;
  fresh.internal_format = internalformat;
  fresh.format = *format;
  // As Mesa: the smallest supported count not below the one asked for (any of 1..4 gives 4).
  fresh.samples = samples > 0 ? kMaxSamples : 0;
  const size_t n = size_t(width) * size_t(height) * size_t(std::max(fresh.samples, 1));
  try {
    RenderbufferPixels& pixels = *fresh.pixels;
    if (format->kind == RenderableFormat::Kind::Color) pixels.color.assign(n, 0);
    if (format->has_depth()) pixels.depth.assign(n, 0);
    if (format->has_stencil()) pixels.stencil.assign(n, 0);
  } catch (const std::bad_alloc&) {
    return ctx.record_error(GL_OUT_OF_MEMORY, "no memory for the renderbuffer's storage");
  }
  *rb = std::move(fresh);
  refresh_framebuffer_views(ctx);
}

}  // namespace

void GenRenderbuffers(Context& ctx, GLsizei n, GLuint* renderbuffers) {
  if (n < 0) return ctx.record_error(GL_INVALID_VALUE, "n is negative");
  if (!renderbuffers) return;
  FramebufferState& fs = ctx.framebuffers;
  GLuint next = 1;
  for (GLsizei i = 0; i < n; ++i) {
    while (fs.renderbuffers.count(next)) ++next;
    fs.renderbuffers[next] = nullptr;  // reserved until first bound
    renderbuffers[i] = next;
  }
}

void DeleteRenderbuffers(Context& ctx, GLsizei n, const GLuint* renderbuffers) {
  if (n < 0) return ctx.record_error(GL_INVALID_VALUE, "n is negative");
  if (!renderbuffers) return;
  FramebufferState& fs = ctx.framebuffers;
  for (GLsizei i = 0; i < n; ++i) {
    const GLuint name = renderbuffers[i];
    auto it = fs.renderbuffers.find(name);
    if (name == 0 || it == fs.renderbuffers.end()) continue;
    // Unbound and detached in this context only; another context that has it bound or
    // attached keeps the object (GL 3.0 appendix D.1.2), without its name.
    if (fs.renderbuffer_binding == name) {
      fs.renderbuffer_binding = 0;
      fs.bound_renderbuffer.reset();
    }
    if (it->second) detach_deleted(ctx, GL_RENDERBUFFER, name);
    fs.renderbuffers.erase(name);
    ctx.debug.forget_label(GL_RENDERBUFFER, name);
  }
}

GLboolean IsRenderbuffer(Context& ctx, GLuint renderbuffer) {
  const FramebufferState& fs = ctx.framebuffers;
  auto it = fs.renderbuffers.find(renderbuffer);
  return renderbuffer != 0 && it != fs.renderbuffers.end() && it->second ? GL_TRUE : GL_FALSE;
}

void BindRenderbuffer(Context& ctx, GLenum target, GLuint renderbuffer) {
  if (target != GL_RENDERBUFFER) return ctx.record_error(GL_INVALID_ENUM, "target is not GL_RENDERBUFFER");
  FramebufferState& fs = ctx.framebuffers;
  fs.bound_renderbuffer.reset();
  if (renderbuffer != 0) {
    std::shared_ptr<Renderbuffer>& slot = fs.renderbuffers[renderbuffer];
    if (!slot) slot = std::make_shared<Renderbuffer>();
    fs.bound_renderbuffer = slot;
  }
  fs.renderbuffer_binding = renderbuffer;
}

void RenderbufferStorage(Context& ctx, GLenum target, GLenum internalformat, GLsizei width, GLsizei height) {
  // OpenGL ES 1.1's GL_OES_framebuffer_object takes the same formats (those of the extensions its
  // context has: the others are refused as enums it does not define).
  if ((ctx.es1() || ctx.es2()) && target == GL_RENDERBUFFER && !es2_renderbuffer_format(internalformat))
    return ctx.record_error(GL_INVALID_ENUM, "internalformat is not a renderable format of OpenGL ES");
  storage(ctx, target, 0, internalformat, width, height);
}

void RenderbufferStorageMultisample(Context& ctx, GLenum target, GLsizei samples, GLenum internalformat,
                                    GLsizei width, GLsizei height) {
  if (samples < 0) return ctx.record_error(GL_INVALID_VALUE, "samples is negative");
  storage(ctx, target, samples, internalformat, width, height);
}

void GetRenderbufferParameteriv(Context& ctx, GLenum target, GLenum pname, GLint* params) {
  if (target != GL_RENDERBUFFER) return ctx.record_error(GL_INVALID_ENUM, "target is not GL_RENDERBUFFER");
  const Renderbuffer* rb = bound_renderbuffer(ctx);
  if (!rb) return ctx.record_error(GL_INVALID_OPERATION, "no renderbuffer is bound");
  const RenderableFormat& f = rb->format;
  const bool color = f.kind == RenderableFormat::Kind::Color;
  GLint value = 0;
  switch (pname) {
    case GL_RENDERBUFFER_WIDTH: value = rb->width; break;
    case GL_RENDERBUFFER_HEIGHT: value = rb->height; break;
    case GL_RENDERBUFFER_INTERNAL_FORMAT: value = GLint(rb->internal_format); break;
    case GL_RENDERBUFFER_SAMPLES: value = rb->samples; break;
    // A renderbuffer without storage has no bits yet.
    case GL_RENDERBUFFER_RED_SIZE: value = color && rb->width ? f.color.red : 0; break;
    case GL_RENDERBUFFER_GREEN_SIZE: value = color && rb->width ? f.color.green : 0; break;
    case GL_RENDERBUFFER_BLUE_SIZE: value = color && rb->width ? f.color.blue : 0; break;
    case GL_RENDERBUFFER_ALPHA_SIZE: value = color && rb->width ? f.color.alpha : 0; break;
    case GL_RENDERBUFFER_DEPTH_SIZE: value = rb->width ? f.depth_bits : 0; break;
    case GL_RENDERBUFFER_STENCIL_SIZE: value = rb->width ? f.stencil_bits : 0; break;
    default: return ctx.record_error(GL_INVALID_ENUM, "pname is not a renderbuffer parameter");
  }
  if (params) *params = value;
}

}  // namespace pineda::gl
