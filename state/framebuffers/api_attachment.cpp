// glFramebufferTexture1D/2D/3D, glFramebufferTextureLayer, glFramebufferRenderbuffer and
// glGetFramebufferAttachmentParameteriv.
#include <algorithm>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/framebuffers/framebuffer_object.h"
#include "state/limits.h"
#include "state/textures/texture_target.h"

namespace pineda::gl {
namespace {

// The framebuffer object a target names and the attachment points an attachment enum names
// (DEPTH_STENCIL_ATTACHMENT: both); records the error and returns null otherwise.
FramebufferObject* attachment_target(Context& ctx, GLenum target, GLenum attachment, int points[2], int& count) {
  bool draw = false, read = false;
  if (!framebuffer_target(target, draw, read)) {
    ctx.record_error(GL_INVALID_ENUM, "target is not a framebuffer target");
    return nullptr;
  }
  count = 1;
  if (attachment == GL_DEPTH_STENCIL_ATTACHMENT) {
    points[0] = kDepthPoint;
    points[1] = kStencilPoint;
    count = 2;
  } else {
    points[0] = attachment_point(attachment);
    if (points[0] < 0) {
      // A colour attachment past MAX_COLOR_ATTACHMENTS is INVALID_OPERATION, as Mesa.
      const bool color = attachment >= GL_COLOR_ATTACHMENT0 && attachment <= GL_COLOR_ATTACHMENT15;
      if (color) ctx.record_error(GL_INVALID_OPERATION, "attachment is above GL_MAX_COLOR_ATTACHMENTS");
      else ctx.record_error(GL_INVALID_ENUM, "attachment is not an attachment point");
      return nullptr;
    }
  }
  FramebufferObject* fb = draw ? ctx.framebuffers.draw_object() : ctx.framebuffers.read_object();
  if (!fb) ctx.record_error(GL_INVALID_OPERATION, "the default framebuffer, which has no attachments, is bound");
  return fb;
}

bool same_image(const Attachment& a, const Attachment& b) {
  return a.type == b.type && a.renderbuffer == b.renderbuffer && a.name == b.name && a.level == b.level &&
         a.face == b.face && a.cube == b.cube && a.layer == b.layer;
}

void set_attachments(Context& ctx, FramebufferObject& fb, const int points[2], int count, const Attachment& a) {
  // Attaching the image already attached changes nothing: the queued rendering stays queued and
  // a depth texture keeps its integer copy (glmark2's shadow scene attaches its depth texture
  // again every frame).
  if (std::all_of(points, points + count, [&](int p) { return same_image(fb.attachments[p], a); })) return;
  resolve_rendered_textures(ctx);
  ctx.finish();
  for (int i = 0; i < count; ++i) fb.attachments[points[i]] = a;
  fb.attachments_changed();
  refresh_framebuffer_views(ctx);
}

// Whether textarget suits a glFramebufferTexture<dims>D call (cube faces and rectangles for 2D).
bool textarget_for(int dims, GLenum textarget, TexTarget& kind, int& face) {
  face = 0;
  switch (dims) {
    case 1: kind = TexTarget::T1D; return textarget == GL_TEXTURE_1D;
    case 3: kind = TexTarget::T3D; return textarget == GL_TEXTURE_3D;
    default: break;
  }
  if (textarget == GL_TEXTURE_2D || textarget == GL_TEXTURE_RECTANGLE_ARB) {
    kind = textarget == GL_TEXTURE_2D ? TexTarget::T2D : TexTarget::Rect;
    return true;
  }
  if (textarget >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && textarget <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z) {
    kind = TexTarget::Cube;
    face = int(textarget - GL_TEXTURE_CUBE_MAP_POSITIVE_X);
    return true;
  }
  return false;
}

// The shared part of the texture attachment calls, after the target and attachment checks.
void attach_texture(Context& ctx, FramebufferObject& fb, const int points[2], int count, TexTarget kind, int face,
                    GLuint texture, GLint level, GLint layer) {
  Attachment a;
  if (texture != 0) {
    const TextureObject* tex = ctx.textures.find(texture);
    if (!tex || tex->target != binding_enum(kind))
      return ctx.record_error(GL_INVALID_OPERATION, "texture is not a texture of the call's target");
    if (level < 0 || level > max_texture_level(kind))
      return ctx.record_error(GL_INVALID_VALUE, "level is negative or above log2 of the maximum texture size");
    if (layer < 0 || (kind == TexTarget::T3D && layer >= kMax3DTextureSize))
      return ctx.record_error(GL_INVALID_VALUE, "layer is negative or not less than GL_MAX_3D_TEXTURE_SIZE");
    a.type = GL_TEXTURE;
    a.name = texture;
    a.level = level;
    a.cube = kind == TexTarget::Cube;
    a.face = face;
    a.layer = kind == TexTarget::T3D ? layer : 0;
  }
  set_attachments(ctx, fb, points, count, a);
}

void framebuffer_texture(Context& ctx, int dims, GLenum target, GLenum attachment, GLenum textarget, GLuint texture,
                         GLint level, GLint layer) {
  int points[2], count = 0;
  FramebufferObject* fb = attachment_target(ctx, target, attachment, points, count);
  if (!fb) return;
  TexTarget kind = TexTarget::T2D;
  int face = 0;
  if (texture != 0 && !textarget_for(dims, textarget, kind, face))
    return ctx.record_error(GL_INVALID_OPERATION, "textarget is not a texture image target of the call");
  attach_texture(ctx, *fb, points, count, kind, face, texture, level, layer);
}

bool is_attachment_pname(GLenum pname) {
  switch (pname) {
    case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL: case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE:
    case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER: case GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE:
    case GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE: case GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE:
    case GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE: case GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE:
    case GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE: case GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE:
    case GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING:
      return true;
    default: return false;
  }
}

GLint attachment_parameter(Context& ctx, const Attachment& a, GLenum pname, bool& ok) {
  ok = true;
  if (pname == GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE) return GLint(a.type);
  if (pname == GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME) return GLint(a.name);
  const bool texture = a.type == GL_TEXTURE;
  switch (pname) {
    case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL: ok = texture; return a.level;
    case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE:
      ok = texture;
      return a.cube ? GLint(GL_TEXTURE_CUBE_MAP_POSITIVE_X + a.face) : 0;
    case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER: ok = texture; return a.layer;
    default: break;
  }
  if (a.type == GL_NONE) {
    ok = false;
    return 0;
  }
  const std::optional<RenderableFormat> f = attachment_format(ctx, a);
  const bool color = f && f->kind == RenderableFormat::Kind::Color;
  switch (pname) {
    case GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE: return color ? f->color.red : 0;
    case GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE: return color ? f->color.green : 0;
    case GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE: return color ? f->color.blue : 0;
    case GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE: return color ? f->color.alpha : 0;
    case GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE: return f ? f->depth_bits : 0;
    case GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE: return f ? f->stencil_bits : 0;
    case GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE:
      if (f && f->kind == RenderableFormat::Kind::Stencil) return GL_UNSIGNED_INT;
      return f && f->depth_float ? GL_FLOAT : GL_UNSIGNED_NORMALIZED;
    case GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING: return GL_LINEAR;
    default: ok = false; return 0;
  }
}

}  // namespace

void FramebufferTexture1D(Context& ctx, GLenum target, GLenum attachment, GLenum textarget, GLuint texture,
                          GLint level) {
  framebuffer_texture(ctx, 1, target, attachment, textarget, texture, level, 0);
}

void FramebufferTexture2D(Context& ctx, GLenum target, GLenum attachment, GLenum textarget, GLuint texture,
                          GLint level) {
  framebuffer_texture(ctx, 2, target, attachment, textarget, texture, level, 0);
}

void FramebufferTexture3D(Context& ctx, GLenum target, GLenum attachment, GLenum textarget, GLuint texture,
                          GLint level, GLint zoffset) {
  framebuffer_texture(ctx, 3, target, attachment, textarget, texture, level, zoffset);
}

// Any layer of a 3D texture (Pineda has no array textures).
void FramebufferTextureLayer(Context& ctx, GLenum target, GLenum attachment, GLuint texture, GLint level, GLint layer) {
  int points[2], count = 0;
  FramebufferObject* fb = attachment_target(ctx, target, attachment, points, count);
  if (!fb) return;
  if (texture != 0) {
    const TextureObject* tex = ctx.textures.find(texture);
    if (!tex || tex->target != GL_TEXTURE_3D)
      return ctx.record_error(GL_INVALID_OPERATION, "texture is not a 3D texture");
  }
  attach_texture(ctx, *fb, points, count, TexTarget::T3D, 0, texture, level, layer);
}

void FramebufferRenderbuffer(Context& ctx, GLenum target, GLenum attachment, GLenum renderbuffertarget,
                             GLuint renderbuffer) {
  int points[2], count = 0;
  FramebufferObject* fb = attachment_target(ctx, target, attachment, points, count);
  if (!fb) return;
  if (renderbuffertarget != GL_RENDERBUFFER)
    return ctx.record_error(GL_INVALID_ENUM, "renderbuffertarget is not GL_RENDERBUFFER");
  Attachment a;
  if (renderbuffer != 0) {
    auto it = ctx.framebuffers.renderbuffers.find(renderbuffer);
    if (it == ctx.framebuffers.renderbuffers.end() || !it->second)
      return ctx.record_error(GL_INVALID_OPERATION, "renderbuffer is not a renderbuffer object");
    a.type = GL_RENDERBUFFER;
    a.renderbuffer = it->second;
    a.name = renderbuffer;
  }
  set_attachments(ctx, *fb, points, count, a);
}

namespace {

// The window-system framebuffer's buffers (GL 3.0 6.1.17): FRONT_LEFT, BACK_LEFT, DEPTH and
// STENCIL, of type FRAMEBUFFER_DEFAULT when the drawable has them.
void default_framebuffer_parameter(Context& ctx, const Drawable* d, GLenum attachment, GLenum pname, GLint* params) {
  bool exists = false;
  int bits[6] = {0, 0, 0, 0, 0, 0};  // red, green, blue, alpha, depth, stencil
  switch (attachment) {
    case GL_FRONT_LEFT: case GL_BACK_LEFT: case GL_FRONT_RIGHT: case GL_BACK_RIGHT:
      exists = d && (attachment == GL_FRONT_LEFT || (attachment == GL_BACK_LEFT && d->double_buffered));
      if (exists) {
        bits[0] = d->red_bits, bits[1] = d->green_bits, bits[2] = d->blue_bits, bits[3] = d->alpha_bits;
      }
      break;
    case GL_DEPTH: exists = d && d->framebuffer.depth.bits; bits[4] = exists ? d->framebuffer.depth.bits : 0; break;
    case GL_STENCIL: exists = d && d->framebuffer.stencil.bits; bits[5] = exists ? d->framebuffer.stencil.bits : 0; break;
    default: return ctx.record_error(GL_INVALID_ENUM, "attachment is not a buffer of the default framebuffer");
  }
  GLint value = 0;
  switch (pname) {
    case GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE: value = exists ? GL_FRAMEBUFFER_DEFAULT : GL_NONE; break;
    case GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME: value = 0; break;
    case GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE: case GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE:
    case GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE: case GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE:
    case GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE: case GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE:
      if (!exists) return ctx.record_error(GL_INVALID_OPERATION, "the default framebuffer has no such buffer");
      value = bits[pname - GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE];
      break;
    case GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE:
      if (!exists) return ctx.record_error(GL_INVALID_OPERATION, "the default framebuffer has no such buffer");
      value = attachment == GL_STENCIL ? GL_UNSIGNED_INT : GL_UNSIGNED_NORMALIZED;
      break;
    case GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING:
      if (!exists) return ctx.record_error(GL_INVALID_OPERATION, "the default framebuffer has no such buffer");
      value = GL_LINEAR;
      break;
    default:
      if (is_attachment_pname(pname))
        return ctx.record_error(GL_INVALID_OPERATION, "pname is not a parameter of the default framebuffer");
      return ctx.record_error(GL_INVALID_ENUM, "pname is not a framebuffer attachment parameter");
  }
  if (params) *params = value;
}

}  // namespace

void GetFramebufferAttachmentParameteriv(Context& ctx, GLenum target, GLenum attachment, GLenum pname,
                                         GLint* params) {
  bool draw = false, read = false;
  if (framebuffer_target(target, draw, read) &&
      !(draw ? ctx.framebuffers.draw_binding : ctx.framebuffers.read_binding))
    return default_framebuffer_parameter(ctx, draw ? ctx.window_draw_drawable() : ctx.window_read_drawable(),
                                         attachment, pname, params);
  int points[2], count = 0;
  FramebufferObject* fb = attachment_target(ctx, target, attachment, points, count);
  if (!fb) return;
  const Attachment& a = fb->attachments[points[0]];
  // DEPTH_STENCIL_ATTACHMENT names one image only when depth and stencil share it.
  if (count == 2) {
    const Attachment& s = fb->attachments[points[1]];
    if (a.type != s.type || a.name != s.name || a.level != s.level || a.face != s.face || a.layer != s.layer)
      return ctx.record_error(GL_INVALID_OPERATION, "depth and stencil have different images attached");
  }
  bool ok = false;
  const GLint value = attachment_parameter(ctx, a, pname, ok);
  // Of an attachment point with nothing attached only the type and name can be queried
  // (GL 3.0 6.1.17: INVALID_OPERATION for a known pname, as Mesa).
  if (!ok && a.type == GL_NONE && is_attachment_pname(pname))
    return ctx.record_error(GL_INVALID_OPERATION, "nothing is attached: only the type and name can be queried");
  if (!ok) return ctx.record_error(GL_INVALID_ENUM, "pname is not a framebuffer attachment parameter");
  if (params) *params = value;
}

}  // namespace pineda::gl
