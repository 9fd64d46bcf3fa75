// glCopyTexImage1D/2D and glCopyTexSubImage1D/2D/3D: texture images from the read buffer.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "glapi/gl_entry_points.h"
#include "raster/color_reduction.h"
#include "state/es2/es2_rules.h"
#include "state/context.h"
#include "state/framebuffers/packed_depth_stencil.h"
#include "state/limits.h"
#include "state/textures/texture_format.h"
#include "state/textures/texture_target.h"

namespace pineda::gl {
namespace {

// Calls visit(fx, fy, index) for each pixel of [x, x + width) x [y, y + height) inside the
// framebuffer; index counts the rectangle's pixels row by row, bottom row first.
template <typename Visit>
void for_each_read_pixel(const raster::Framebuffer& fb, GLint x, GLint y, GLsizei width, GLsizei height, Visit visit) {
  for (GLsizei row = 0; row < height; ++row) {
    const int64_t fy = int64_t(y) + row;
    if (fy < 0 || fy >= fb.height) continue;
    for (GLsizei col = 0; col < width; ++col) {
      const int64_t fx = int64_t(x) + col;
      if (fx >= 0 && fx < fb.width) visit(fx, fy, size_t(row) * width + col);
    }
  }
}

// RGBA8 rows, bottom row first: `row_length` pixels from one row to the next (0: tight).
struct Rgba8Rows {
  const uint8_t* pixels = nullptr;
  GLint row_length = 0;
};

// The read drawable's pixels in [x, x + width) x [y, y + height) as RGBA8 rows. Inside a
// window's (not a framebuffer object's, which may be the texture written) plain RGBA8 colour
// buffer with alpha and rows upwards in memory, and when `in_place`, they are the buffer's own
// rows; otherwise tight rows in the context's copied_pixels (reused: a blur copying the frame
// several times a frame would otherwise fault fresh pages in each time), where pixels outside
// the drawable read as zero (GL leaves them undefined).
Rgba8Rows read_rgba8(Context& ctx, GLint x, GLint y, GLsizei width, GLsizei height, bool in_place = true) {
  const size_t row_bytes = size_t(std::max(width, 0)) * 4, rows = size_t(std::max(height, 0));
  std::vector<uint8_t>& out = ctx.copied_pixels;
  const Drawable* d = ctx.read_drawable();
  if (!d || row_bytes * rows == 0) {
    if (out.size() < row_bytes * rows) out.resize(row_bytes * rows);
    std::fill_n(out.begin(), row_bytes * rows, uint8_t(0));
    return {out.data(), 0};
  }
  ctx.finish();
  const raster::Framebuffer fb = ctx.read_framebuffer();
  const bool inside = x >= 0 && y >= 0 && int64_t(x) + width <= fb.width && int64_t(y) + height <= fb.height;
  const bool plain_rgba8 = !fb.color.reduction.active && fb.color.format == raster::ColorFormat::RGBA8;
  if (in_place && inside && plain_rgba8 && d == ctx.window_read_drawable() && d->alpha_bits && fb.color.stride > 0 &&
      fb.color.stride % 4 == 0 && fb.color.stride / 4 <= INT32_MAX)
    return {fb.color.base + fb.color.stride * y + 4 * ptrdiff_t(x), GLint(fb.color.stride / 4)};
  // (Grown only here: a copy read in place touches no staging memory, which a first frame pays for.)
  if (out.size() < row_bytes * rows) out.resize(row_bytes * rows);
  // Row by row: the columns inside the framebuffer; RGBA8 and BGRA8 rows in whole words.
  const int64_t col0 = std::clamp<int64_t>(-int64_t(x), 0, width);
  const int64_t col1 = std::clamp<int64_t>(int64_t(fb.width) - x, col0, width);
  const bool plain = !fb.color.reduction.active, bgra = fb.color.format == raster::ColorFormat::BGRA8;
  for (GLsizei row = 0; row < height; ++row) {
    uint8_t* dst_row = &out[size_t(row) * row_bytes];
    const int64_t fy = int64_t(y) + row;
    if (fy < 0 || fy >= fb.height || col0 == col1) {
      std::fill_n(dst_row, row_bytes, uint8_t(0));
      continue;
    }
    std::fill_n(dst_row, size_t(col0) * 4, uint8_t(0));
    std::fill(dst_row + size_t(col1) * 4, dst_row + row_bytes, uint8_t(0));
    const uint8_t* src = fb.color.base + fb.color.stride * fy + 4 * (x + col0);
    uint8_t* dst = dst_row + size_t(col0) * 4;
    const size_t n = size_t(col1 - col0);
    if (plain && !bgra) {
      std::memcpy(dst, src, n * 4);
    } else if (plain) {
      for (size_t i = 0; i < n; ++i) {
        uint32_t v;
        std::memcpy(&v, src + 4 * i, 4);
        v = (v & 0xff00ff00u) | ((v >> 16) & 0xffu) | ((v & 0xffu) << 16);
        std::memcpy(dst + 4 * i, &v, 4);
      }
    } else {
      for (size_t i = 0; i < n; ++i) raster::read_rgba8(fb.color, src + 4 * i, dst + 4 * i);
    }
    if (!d->alpha_bits)
      for (size_t i = 0; i < n; ++i) dst[4 * i + 3] = 255;
  }
  return {out.data(), 0};
}

// glCopyTexImage takes the targets of glTexImage with `dims` dimensions but no proxy
// (INVALID_ENUM, before any pixel is read).
bool valid_copy_target(Context& ctx, GLenum target, int dims) {
  ImageTarget t;
  if (image_target(target, t) && !t.proxy && image_dimensions(t.kind) == dims) return true;
  ctx.record_error(GL_INVALID_ENUM, "target is not a texture image target of the call's dimensions");
  return false;
}

// The read drawable's depth values in the same rectangle as floats in [0, 1]; outside the
// drawable, zero.
std::vector<float> read_depth(Context& ctx, GLint x, GLint y, GLsizei width, GLsizei height) {
  std::vector<float> out(size_t(std::max(width, 0)) * size_t(std::max(height, 0)), 0.f);
  ctx.finish();
  const raster::Framebuffer fb = ctx.read_framebuffer();
  const double max = std::ldexp(1.0, fb.depth.bits) - 1.0;
  for_each_read_pixel(fb, x, y, width, height, [&](int64_t fx, int64_t fy, size_t i) {
    out[i] = static_cast<float>(fb.depth.base[fb.depth.stride * fy + fx] / max);
  });
  return out;
}

// The read framebuffer's depth and stencil in the same rectangle as DEPTH_STENCIL pixels for a
// texture of `internal_format`: FLOAT_32_UNSIGNED_INT_24_8_REV for a float depth format (no
// precision lost), UNSIGNED_INT_24_8 otherwise; outside the rectangle, zero. Records
// INVALID_OPERATION and returns false when either buffer is missing.
struct DepthStencilWords {
  GLenum type = GL_UNSIGNED_INT_24_8;
  std::vector<uint32_t> words;
};
bool read_depth_stencil(Context& ctx, GLint x, GLint y, GLsizei width, GLsizei height, GLint internal_format,
                        DepthStencilWords& out) {
  const Drawable* d = ctx.read_drawable();
  if (!d || !d->framebuffer.depth.bits || !d->framebuffer.stencil.bits) {
    ctx.record_error(GL_INVALID_OPERATION, "the read framebuffer has no depth or no stencil buffer");
    return false;
  }
  const bool float_depth = texture_format(internal_format).value_or(TextureFormat{}).depth_float;
  out.type = float_depth ? GL_FLOAT_32_UNSIGNED_INT_24_8_REV : GL_UNSIGNED_INT_24_8;
  const size_t words_per_pixel = float_depth ? 2 : 1;
  out.words.assign(size_t(std::max(width, 0)) * size_t(std::max(height, 0)) * words_per_pixel, 0u);
  ctx.finish();
  const raster::Framebuffer fb = ctx.read_framebuffer();
  const double max = std::ldexp(1.0, fb.depth.bits) - 1.0;
  for_each_read_pixel(fb, x, y, width, height, [&](int64_t fx, int64_t fy, size_t i) {
    store_depth_stencil(fb.depth.base[fb.depth.stride * fy + fx] / max, fb.stencil.base[fb.stencil.stride * fy + fx],
                        out.type, false, reinterpret_cast<uint8_t*>(&out.words[i * words_per_pixel]));
  });
  return true;
}

bool is_depth_stencil_format(GLint internal_format) {
  return texture_format(internal_format).value_or(TextureFormat{}).stencil > 0;
}

bool is_depth_format(GLint internal_format) { return texture_format(internal_format).value_or(TextureFormat{}).depth > 0; }

// The internal format of the level a glCopyTexSubImage writes; 0 when it has no image.
GLint level_internal_format(Context& ctx, GLenum target, GLint level) {
  ImageTarget t;
  if (!image_target(target, t) || t.proxy || level < 0) return 0;
  const GLuint name = bound_name(ctx.texture_units[ctx.active_texture], t.kind);
  const std::vector<TextureLevelData>& levels = ctx.textures.get_or_create(name, binding_enum(t.kind)).face_levels(t.face);
  if (size_t(level) >= levels.size() || levels[level].width == 0) return 0;
  return levels[level].internal_format;
}

// Whether the level a glCopyTexSubImage writes is a depth image (read from the depth buffer).
bool depth_level(Context& ctx, GLenum target, GLint level, bool with_stencil = false) {
  const GLint format = level_internal_format(ctx, target, level);
  return with_stencil ? is_depth_stencil_format(format) : is_depth_format(format);
}

// A depth copy needs a depth buffer to read (Mesa: INVALID_OPERATION).
bool has_read_depth(Context& ctx) {
  const Drawable* d = ctx.read_drawable();
  if (d && d->framebuffer.depth.bits > 0) return true;
  ctx.record_error(GL_INVALID_OPERATION, "the read framebuffer has no depth buffer");
  return false;
}

// A colour copy needs a colour buffer to read: a framebuffer object's read buffer may be
// NONE or name an attachment without an image (INVALID_OPERATION, as glReadPixels).
bool has_read_color(Context& ctx) {
  if (ctx.read_framebuffer().color.base) return true;
  ctx.record_error(GL_INVALID_OPERATION, "the read framebuffer has no colour buffer to read");
  return false;
}

// Sizes no texture can have are rejected before any pixel is read.
bool valid_copy_size(Context& ctx, GLsizei width, GLsizei height) {
  if (!check_read_single_sampled(ctx)) return false;
  if (width >= 0 && height >= 0 && width <= kMaxTextureSize + 2 && height <= kMaxTextureSize + 2) return true;
  ctx.record_error(GL_INVALID_VALUE, "width or height is negative or above the maximum texture size");
  return false;
}

// GL 1.1 3.8.2: CopyTexImage takes the internal formats of TexImage but 1, 2, 3 and 4.
bool valid_copy_internal_format(Context& ctx, GLenum internalformat) {
  if (internalformat < 1 || internalformat > 4) return true;
  ctx.record_error(GL_INVALID_ENUM, "internalformat is 1, 2, 3 or 4");
  return false;
}

// Runs `upload` with a packed unpack state (rows `row_length` pixels apart, 0: tight), then
// restores the application's.
template <typename Upload>
void with_tight_unpack(Context& ctx, Upload upload, GLint row_length = 0) {
  const PixelStore saved = ctx.unpack;
  ctx.unpack = PixelStore{};
  ctx.unpack.alignment = 1;
  ctx.unpack.row_length = row_length;
  upload();
  ctx.unpack = saved;
}

}  // namespace

void CopyTexImage2D(Context& ctx, GLenum target, GLint level, GLenum internalformat, GLint x, GLint y,
                    GLsizei width, GLsizei height, GLint border) {
  if (ctx.es2() && !es2_copy_tex_image_format(internalformat))
    return ctx.record_error(GL_INVALID_VALUE, "internalformat is not a base format of OpenGL ES 2.0");
  if (ctx.es2() && border != 0) return ctx.record_error(GL_INVALID_VALUE, "border is not 0");
  if (!valid_copy_target(ctx, target, 2) || !valid_copy_internal_format(ctx, internalformat) ||
      !valid_copy_size(ctx, width, height))
    return;
  if (is_depth_stencil_format(GLint(internalformat))) {
    DepthStencilWords ds;
    if (!read_depth_stencil(ctx, x, y, width, height, GLint(internalformat), ds)) return;
    return with_tight_unpack(ctx, [&] {
      TexImage2D(ctx, target, level, GLint(internalformat), width, height, border, GL_DEPTH_STENCIL, ds.type,
                 ds.words.data());
    });
  }
  if (is_depth_format(GLint(internalformat))) {
    if (!has_read_depth(ctx)) return;
    const std::vector<float> depths = read_depth(ctx, x, y, width, height);
    return with_tight_unpack(ctx, [&] {
      TexImage2D(ctx, target, level, GLint(internalformat), width, height, border, GL_DEPTH_COMPONENT, GL_FLOAT,
                 depths.data());
    });
  }
  if (!has_read_color(ctx)) return;
  const Rgba8Rows rows = read_rgba8(ctx, x, y, width, height, !ctx.es2());
  if (ctx.es2()) {
    // ES 2.0's glTexImage2D takes only format == internalformat: the pixels are passed in it.
    const std::vector<uint8_t> base =
        es2_base_format_pixels(rows.pixels, size_t(width) * size_t(height), internalformat);
    return with_tight_unpack(ctx, [&] {
      TexImage2D(ctx, target, level, GLint(internalformat), width, height, border, internalformat, GL_UNSIGNED_BYTE,
                 base.data());
    });
  }
  with_tight_unpack(
      ctx, [&] {
        TexImage2D(ctx, target, level, GLint(internalformat), width, height, border, GL_RGBA, GL_UNSIGNED_BYTE,
                       rows.pixels);
      },
      rows.row_length);
}

void CopyTexImage1D(Context& ctx, GLenum target, GLint level, GLenum internalformat, GLint x, GLint y,
                    GLsizei width, GLint border) {
  if (!valid_copy_target(ctx, target, 1) || !valid_copy_internal_format(ctx, internalformat) ||
      !valid_copy_size(ctx, width, 1))
    return;
  if (is_depth_stencil_format(GLint(internalformat))) {
    DepthStencilWords ds;
    if (!read_depth_stencil(ctx, x, y, width, 1, GLint(internalformat), ds)) return;
    return with_tight_unpack(ctx, [&] {
      TexImage1D(ctx, target, level, GLint(internalformat), width, border, GL_DEPTH_STENCIL, ds.type, ds.words.data());
    });
  }
  if (is_depth_format(GLint(internalformat))) {
    if (!has_read_depth(ctx)) return;
    const std::vector<float> depths = read_depth(ctx, x, y, width, 1);
    return with_tight_unpack(ctx, [&] {
      TexImage1D(ctx, target, level, GLint(internalformat), width, border, GL_DEPTH_COMPONENT, GL_FLOAT, depths.data());
    });
  }
  if (!has_read_color(ctx)) return;
  const Rgba8Rows rows = read_rgba8(ctx, x, y, width, 1);
  with_tight_unpack(
      ctx, [&] {
        TexImage1D(ctx, target, level, GLint(internalformat), width, border, GL_RGBA, GL_UNSIGNED_BYTE, rows.pixels);
      },
      rows.row_length);
}

void CopyTexSubImage2D(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint x, GLint y,
                       GLsizei width, GLsizei height) {
  if (!valid_copy_size(ctx, width, height)) return;
  if (depth_level(ctx, target, level, true)) {
    DepthStencilWords ds;
    if (!read_depth_stencil(ctx, x, y, width, height, level_internal_format(ctx, target, level), ds)) return;
    return with_tight_unpack(ctx, [&] {
      TexSubImage2D(ctx, target, level, xoffset, yoffset, width, height, GL_DEPTH_STENCIL, ds.type, ds.words.data());
    });
  }
  if (depth_level(ctx, target, level)) {
    if (!has_read_depth(ctx)) return;
    const std::vector<float> depths = read_depth(ctx, x, y, width, height);
    return with_tight_unpack(ctx, [&] {
      TexSubImage2D(ctx, target, level, xoffset, yoffset, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depths.data());
    });
  }
  if (!has_read_color(ctx)) return;
  const Rgba8Rows rows = read_rgba8(ctx, x, y, width, height);
  with_tight_unpack(
      ctx, [&] {
        TexSubImage2D(ctx, target, level, xoffset, yoffset, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rows.pixels);
      },
      rows.row_length);
}

void CopyTexSubImage1D(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint x, GLint y, GLsizei width) {
  if (!valid_copy_size(ctx, width, 1)) return;
  if (depth_level(ctx, target, level, true)) {
    DepthStencilWords ds;
    if (!read_depth_stencil(ctx, x, y, width, 1, level_internal_format(ctx, target, level), ds)) return;
    return with_tight_unpack(ctx, [&] {
      TexSubImage1D(ctx, target, level, xoffset, width, GL_DEPTH_STENCIL, ds.type, ds.words.data());
    });
  }
  if (depth_level(ctx, target, level)) {
    if (!has_read_depth(ctx)) return;
    const std::vector<float> depths = read_depth(ctx, x, y, width, 1);
    return with_tight_unpack(ctx, [&] {
      TexSubImage1D(ctx, target, level, xoffset, width, GL_DEPTH_COMPONENT, GL_FLOAT, depths.data());
    });
  }
  if (!has_read_color(ctx)) return;
  const Rgba8Rows rows = read_rgba8(ctx, x, y, width, 1);
  with_tight_unpack(
      ctx, [&] {
        TexSubImage1D(ctx, target, level, xoffset, width, GL_RGBA, GL_UNSIGNED_BYTE, rows.pixels);
      },
      rows.row_length);
}

// One slice (zoffset) of a 3D texture level from the read buffer.
void CopyTexSubImage3D(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset, GLint x,
                       GLint y, GLsizei width, GLsizei height) {
  if (!valid_copy_size(ctx, width, height)) return;
  if (!has_read_color(ctx)) return;
  const Rgba8Rows rows = read_rgba8(ctx, x, y, width, height);
  with_tight_unpack(
      ctx, [&] {
        TexSubImage3D(ctx, target, level, xoffset, yoffset, zoffset, width, height, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                      rows.pixels);
      },
      rows.row_length);
}

void CopyTexSubImage3DEXT(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset,
                          GLint x, GLint y, GLsizei width, GLsizei height) {
  CopyTexSubImage3D(ctx, target, level, xoffset, yoffset, zoffset, x, y, width, height);
}

}  // namespace pineda::gl
