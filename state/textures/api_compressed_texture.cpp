// GL 1.3 compressed texture images (ARB_texture_compression). Desktop GL contexts support no
// specific compressed format (NUM_COMPRESSED_TEXTURE_FORMATS is 0), so there these calls only
// ever give the spec's errors, checked in Mesa's order: the target (INVALID_ENUM), then the
// format, which cannot be a supported one (INVALID_ENUM); glGetCompressedTexImage: the target,
// the level (INVALID_VALUE), then the image, never compressed (INVALID_OPERATION). The generic
// formats (GL_COMPRESSED_RGB...) are taken by glTexImage and stored uncompressed
// (texture_format.h). An OpenGL ES 1.1 context has the paletted formats (state/es1/).
#include <functional>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/es1/paletted_texture.h"
#include "state/get_values.h"
#include "state/textures/texture_target.h"

namespace pineda {

bool query_compressed_formats(const Context& ctx, unsigned pname, GetValues& out) {
  const int count = ctx.es1() ? kPalettedFormatCount : 0;
  switch (pname) {
    case GL_NUM_COMPRESSED_TEXTURE_FORMATS: out = get_ints({double(count)}); return true;
    case GL_COMPRESSED_TEXTURE_FORMATS:
      out = GetValues{GetKind::Enum, {}};
      for (int i = 0; i < count; ++i) out.v.push_back(paletted_format_at(i));
      return true;
    default: return false;
  }
}

}  // namespace pineda

namespace pineda::gl {
namespace {

bool image_target_of(GLenum target, int dims, bool proxy_ok) {
  ImageTarget t;
  return image_target(target, t) && image_dimensions(t.kind) == dims && (proxy_ok || !t.proxy);
}

// glCompressedTexImage*D and glCompressedTexSubImage*D: every format is unsupported.
void compressed_image(Context& ctx, GLenum target, int dims, bool proxy_ok) {
  if (!image_target_of(target, dims, proxy_ok))
    return ctx.record_error(GL_INVALID_ENUM, "target is not a texture image target of the call");
  ctx.record_error(GL_INVALID_ENUM, "internalformat or format is not a supported compressed format (none is)");
}

}  // namespace

void CompressedTexImage1D(Context& ctx, GLenum target, GLint, GLenum, GLsizei, GLint, GLsizei, const void*) {
  compressed_image(ctx, target, 1, true);
}
void CompressedTexImage2D(Context& ctx, GLenum target, GLint level, GLenum internalformat, GLsizei width,
                          GLsizei height, GLint border, GLsizei image_size, const void* data) {
  if (ctx.es1() && paletted_format(internalformat))
    return paletted_tex_image(ctx, target, level, internalformat, width, height, border, image_size, data);
  compressed_image(ctx, target, 2, true);
}
void CompressedTexImage3D(Context& ctx, GLenum target, GLint, GLenum, GLsizei, GLsizei, GLsizei, GLint, GLsizei,
                          const void*) {
  compressed_image(ctx, target, 3, true);
}
void CompressedTexSubImage1D(Context& ctx, GLenum target, GLint, GLint, GLsizei, GLenum, GLsizei, const void*) {
  compressed_image(ctx, target, 1, false);
}
void CompressedTexSubImage2D(Context& ctx, GLenum target, GLint, GLint, GLint, GLsizei, GLsizei, GLenum format,
                             GLsizei, const void*) {
  if (ctx.es1() && image_target_of(target, 2, false) && paletted_format(format))  // OpenGL ES 1.1 3.7.3
    return ctx.record_error(GL_INVALID_OPERATION, "a paletted texture cannot be replaced in part");
  compressed_image(ctx, target, 2, false);
}
void CompressedTexSubImage3D(Context& ctx, GLenum target, GLint, GLint, GLint, GLint, GLsizei, GLsizei, GLsizei,
                             GLenum, GLsizei, const void*) {
  compressed_image(ctx, target, 3, false);
}

void GetCompressedTexImage(Context& ctx, GLenum target, GLint level, void*) {
  ImageTarget t;
  if (!image_target(target, t) || t.proxy)
    return ctx.record_error(GL_INVALID_ENUM, "target is not a texture image target");
  if (level < 0 || level > max_texture_level(t.kind))
    return ctx.record_error(GL_INVALID_VALUE, "level is negative or above log2 of the maximum texture size");
  ctx.record_error(GL_INVALID_OPERATION, "the level is missing or not compressed");
}

void CompressedTexImage1DARB(Context& ctx, GLenum target, GLint level, GLenum internalformat, GLsizei width,
                             GLint border, GLsizei image_size, const void* data) {
  CompressedTexImage1D(ctx, target, level, internalformat, width, border, image_size, data);
}
void CompressedTexImage2DARB(Context& ctx, GLenum target, GLint level, GLenum internalformat, GLsizei width,
                             GLsizei height, GLint border, GLsizei image_size, const void* data) {
  CompressedTexImage2D(ctx, target, level, internalformat, width, height, border, image_size, data);
}
void CompressedTexImage3DARB(Context& ctx, GLenum target, GLint level, GLenum internalformat, GLsizei width,
                             GLsizei height, GLsizei depth, GLint border, GLsizei image_size, const void* data) {
  CompressedTexImage3D(ctx, target, level, internalformat, width, height, depth, border, image_size, data);
}
void CompressedTexSubImage1DARB(Context& ctx, GLenum target, GLint level, GLint xoffset, GLsizei width,
                                GLenum format, GLsizei image_size, const void* data) {
  CompressedTexSubImage1D(ctx, target, level, xoffset, width, format, image_size, data);
}
void CompressedTexSubImage2DARB(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                GLsizei width, GLsizei height, GLenum format, GLsizei image_size, const void* data) {
  CompressedTexSubImage2D(ctx, target, level, xoffset, yoffset, width, height, format, image_size, data);
}
void CompressedTexSubImage3DARB(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                GLint zoffset, GLsizei width, GLsizei height, GLsizei depth, GLenum format,
                                GLsizei image_size, const void* data) {
  CompressedTexSubImage3D(ctx, target, level, xoffset, yoffset, zoffset, width, height, depth, format, image_size,
                          data);
}
void GetCompressedTexImageARB(Context& ctx, GLenum target, GLint level, void* img) {
  GetCompressedTexImage(ctx, target, level, img);
}
// No level is compressed: nothing is ever written, whatever bufSize.
void GetnCompressedTexImageARB(Context& ctx, GLenum target, GLint lod, GLsizei, void* img) {
  GetCompressedTexImage(ctx, target, lod, img);
}

// In a display list the calls keep their arguments but not the data, which no execution reads
// (GL 1.5 5.4: a proxy target executes at once, as for glTexImage).
namespace {

void record(Context& ctx, GLenum target, std::function<void(Context&)> call) {
  ImageTarget t;
  if (image_target(target, t) && t.proxy) return call(ctx);
  ctx.record_list_command([call = std::move(call)](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION, "called between glBegin and glEnd");
    call(c);
  });
}

}  // namespace

void compile_CompressedTexImage1D(Context& ctx, GLenum target, GLint level, GLenum internalformat, GLsizei width,
                                  GLint border, GLsizei image_size, const void*) {
  record(ctx, target, [=](Context& c) {
    CompressedTexImage1D(c, target, level, internalformat, width, border, image_size, nullptr);
  });
}
void compile_CompressedTexImage2D(Context& ctx, GLenum target, GLint level, GLenum internalformat, GLsizei width,
                                  GLsizei height, GLint border, GLsizei image_size, const void*) {
  record(ctx, target, [=](Context& c) {
    CompressedTexImage2D(c, target, level, internalformat, width, height, border, image_size, nullptr);
  });
}
void compile_CompressedTexImage3D(Context& ctx, GLenum target, GLint level, GLenum internalformat, GLsizei width,
                                  GLsizei height, GLsizei depth, GLint border, GLsizei image_size, const void*) {
  record(ctx, target, [=](Context& c) {
    CompressedTexImage3D(c, target, level, internalformat, width, height, depth, border, image_size, nullptr);
  });
}
void compile_CompressedTexSubImage1D(Context& ctx, GLenum target, GLint level, GLint xoffset, GLsizei width,
                                     GLenum format, GLsizei image_size, const void*) {
  record(ctx, target, [=](Context& c) {
    CompressedTexSubImage1D(c, target, level, xoffset, width, format, image_size, nullptr);
  });
}
void compile_CompressedTexSubImage2D(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                     GLsizei width, GLsizei height, GLenum format, GLsizei image_size, const void*) {
  record(ctx, target, [=](Context& c) {
    CompressedTexSubImage2D(c, target, level, xoffset, yoffset, width, height, format, image_size, nullptr);
  });
}
void compile_CompressedTexSubImage3D(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                     GLint zoffset, GLsizei width, GLsizei height, GLsizei depth, GLenum format,
                                     GLsizei image_size, const void*) {
  record(ctx, target, [=](Context& c) {
    CompressedTexSubImage3D(c, target, level, xoffset, yoffset, zoffset, width, height, depth, format, image_size,
                            nullptr);
  });
}
void compile_CompressedTexImage1DARB(Context& ctx, GLenum target, GLint level, GLenum internalformat, GLsizei width,
                                     GLint border, GLsizei image_size, const void* data) {
  compile_CompressedTexImage1D(ctx, target, level, internalformat, width, border, image_size, data);
}
void compile_CompressedTexImage2DARB(Context& ctx, GLenum target, GLint level, GLenum internalformat, GLsizei width,
                                     GLsizei height, GLint border, GLsizei image_size, const void* data) {
  compile_CompressedTexImage2D(ctx, target, level, internalformat, width, height, border, image_size, data);
}
void compile_CompressedTexImage3DARB(Context& ctx, GLenum target, GLint level, GLenum internalformat, GLsizei width,
                                     GLsizei height, GLsizei depth, GLint border, GLsizei image_size,
                                     const void* data) {
  compile_CompressedTexImage3D(ctx, target, level, internalformat, width, height, depth, border, image_size, data);
}
void compile_CompressedTexSubImage1DARB(Context& ctx, GLenum target, GLint level, GLint xoffset, GLsizei width,
                                        GLenum format, GLsizei image_size, const void* data) {
  compile_CompressedTexSubImage1D(ctx, target, level, xoffset, width, format, image_size, data);
}
void compile_CompressedTexSubImage2DARB(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                        GLsizei width, GLsizei height, GLenum format, GLsizei image_size,
                                        const void* data) {
  compile_CompressedTexSubImage2D(ctx, target, level, xoffset, yoffset, width, height, format, image_size, data);
}
void compile_CompressedTexSubImage3DARB(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                        GLint zoffset, GLsizei width, GLsizei height, GLsizei depth, GLenum format,
                                        GLsizei image_size, const void* data) {
  compile_CompressedTexSubImage3D(ctx, target, level, xoffset, yoffset, zoffset, width, height, depth, format,
                                  image_size, data);
}

}  // namespace pineda::gl
