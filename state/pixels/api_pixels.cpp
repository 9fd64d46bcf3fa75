// glPixelStore and glReadPixels.
#include <algorithm>
#include <cstring>
#include <vector>

#include "glapi/gl_entry_points.h"
#include "raster/color_reduction.h"
#include "state/es2/es2_rules.h"
#include "state/pixels/bitmap_layout.h"
#include "state/pixels/color_byte_reads.h"
#include "state/pixels/color_component_reads.h"
#include "state/pixels/depth_stencil_reads.h"
#include "state/context.h"
#include "state/framebuffers/packed_depth_stencil.h"
#include "state/buffers/pixel_buffer.h"
#include "state/pixels/pixel_format.h"
#include "state/pixels/pixel_transfer.h"

namespace pineda::gl {
namespace {

void set_store(Context& ctx, GLenum pname, double value) {
  const bool pack = (pname >= GL_PACK_SWAP_BYTES && pname <= GL_PACK_ALIGNMENT) || pname == GL_PACK_SKIP_IMAGES ||
                    pname == GL_PACK_IMAGE_HEIGHT;
  PixelStore& s = pack ? ctx.pack : ctx.unpack;
  const GLint v = round_int_param(value);  // GL 2.1 3.6.1: -0.9 is -1, an INVALID_VALUE row length
  switch (pname) {
    case GL_PACK_SWAP_BYTES: case GL_UNPACK_SWAP_BYTES: s.swap_bytes = value != 0.0; return;
    case GL_PACK_LSB_FIRST: case GL_UNPACK_LSB_FIRST: s.lsb_first = value != 0.0; return;
    default: break;
  }
  if (pname != GL_PACK_ROW_LENGTH && pname != GL_PACK_SKIP_ROWS && pname != GL_PACK_SKIP_PIXELS &&
      pname != GL_PACK_ALIGNMENT && pname != GL_UNPACK_ROW_LENGTH && pname != GL_UNPACK_SKIP_ROWS &&
      pname != GL_UNPACK_SKIP_PIXELS && pname != GL_UNPACK_ALIGNMENT && pname != GL_PACK_SKIP_IMAGES &&
      pname != GL_PACK_IMAGE_HEIGHT && pname != GL_UNPACK_SKIP_IMAGES && pname != GL_UNPACK_IMAGE_HEIGHT)
    return ctx.record_error(GL_INVALID_ENUM, "pname is not a pixel storage parameter");
  if (v < 0) return ctx.record_error(GL_INVALID_VALUE, "param is negative");
  switch (pname) {
    case GL_PACK_ROW_LENGTH: case GL_UNPACK_ROW_LENGTH: s.row_length = v; return;
    case GL_PACK_SKIP_ROWS: case GL_UNPACK_SKIP_ROWS: s.skip_rows = v; return;
    case GL_PACK_SKIP_PIXELS: case GL_UNPACK_SKIP_PIXELS: s.skip_pixels = v; return;
    case GL_PACK_SKIP_IMAGES: case GL_UNPACK_SKIP_IMAGES: s.skip_images = v; return;
    case GL_PACK_IMAGE_HEIGHT: case GL_UNPACK_IMAGE_HEIGHT: s.image_height = v; return;
    default:
      if (v != 1 && v != 2 && v != 4 && v != 8)
        return ctx.record_error(GL_INVALID_VALUE, "the alignment is not 1, 2, 4 or 8");
      s.alignment = v;
  }
}

// GL 1.5 spec 4.3.2: format/type as for DrawPixels; colour indices cannot be read from an
// RGBA framebuffer, depth and stencil need their buffer.
GlError read_pixels_error(const Context& ctx, GLenum format, GLenum type) {
  if (GlError error; packed_depth_stencil_pixels(format, type, error)) {
    const Drawable* d = ctx.read_drawable();
    if (error == GL_NO_ERROR && (!d || !d->framebuffer.depth.bits || !d->framebuffer.stencil.bits))
      return {GL_INVALID_OPERATION, "the read framebuffer has no depth or no stencil buffer"};
    return error;
  }
  if (const GlError error = pixel_rect_format_type_error(format, type); error != GL_NO_ERROR) return error;
  const Drawable* d = ctx.read_drawable();
  if (format == GL_COLOR_INDEX) return {GL_INVALID_OPERATION, "format is GL_COLOR_INDEX and the framebuffer is RGBA"};
  if (format == GL_DEPTH_COMPONENT && (!d || d->framebuffer.depth.bits == 0))
    return {GL_INVALID_OPERATION, "the read framebuffer has no depth buffer"};
  if (format == GL_STENCIL_INDEX && (!d || d->framebuffer.stencil.bits == 0))
    return {GL_INVALID_OPERATION, "the read framebuffer has no stencil buffer"};
  // A framebuffer object's read buffer may be NONE or name an attachment without an image.
  if (color_format_components(format) > 0 && d && !ctx.read_framebuffer().color.base)
    return {GL_INVALID_OPERATION, "the read framebuffer has no colour buffer to read"};
  return GL_NO_ERROR;
}

// Reads a framebuffer pixel in RGBA floats.
void read_color(const raster::ColorBuffer& cb, int x, int y, double rgba[4]) {
  uint8_t bytes[4];
  raster::read_rgba8(cb, cb.base + cb.stride * y + 4 * x, bytes);
  for (int c = 0; c < 4; ++c) rgba[c] = bytes[c] / 255.0;
}

void transfer_read_color(const Context& ctx, double rgba[4]) {
  float f[4] = {float(rgba[0]), float(rgba[1]), float(rgba[2]), float(rgba[3])};
  transfer_color(ctx.pixel_mode, ctx.pixel_maps, f);
  for (int c = 0; c < 4; ++c) rgba[c] = f[c];
}

// `client_bytes`: how much client memory `pixels` holds (glReadnPixelsARB), when no pack buffer is bound.
void read_pixels(Context& ctx, GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type,
                 void* pixels, size_t client_bytes) {
  if (width < 0 || height < 0) return ctx.record_error(GL_INVALID_VALUE, "width or height is negative");
  if (ctx.es2()) {
    if (const GlError error = es2_read_pixels_error(format, type); error != GL_NO_ERROR) return ctx.record_error(error);
  }
  if (!check_read_single_sampled(ctx)) return;
  if (const GlError error = read_pixels_error(ctx, format, type); error != GL_NO_ERROR) return ctx.record_error(error);
  const Drawable* d = ctx.read_drawable();
  if (!d || width == 0 || height == 0) return;
  if (!pack_pixels(ctx, pixels, client_image_extent(ctx.pack, width, height, 1, false, format, type), client_bytes) ||
      !pixels)
    return;
  ctx.finish_for_reading();
  const raster::Framebuffer fb = ctx.read_framebuffer();
  // Pixels outside the framebuffer are undefined in GL; Pineda leaves the memory untouched.
  const int x0 = std::max(x, 0), x1 = std::min<int64_t>(int64_t(x) + width, fb.width);
  const int y0 = std::max(y, 0), y1 = std::min<int64_t>(int64_t(y) + height, fb.height);
  auto stencil_at = [&](int fx, int fy) {
    return transfer_stencil(ctx.pixel_mode, ctx.pixel_maps, fb.stencil.base[fb.stencil.stride * fy + fx]);
  };
  if (type == GL_BITMAP) {  // stencil indices, one bit each: the index's lowest bit
    const BitmapLayout bits(ctx.pack, width);
    for (int fy = y0; fy < y1; ++fy)
      for (int fx = x0; fx < x1; ++fx)
        bits.set_bit(static_cast<uint8_t*>(pixels), fx - x, fy - y, stencil_at(fx, fy) & 1);
    return;
  }
  const double depth_max = fb.depth.bits >= 32 ? 4294967295.0 : double((1ull << fb.depth.bits) - 1);
  if (format == GL_DEPTH_STENCIL) {
    const ImageLayout layout = packed_depth_stencil_layout(ctx.pack, width, type);
    auto* out = static_cast<uint8_t*>(pixels) + layout.offset;
    for (int fy = y0; fy < y1; ++fy)
      for (int fx = x0; fx < x1; ++fx) {
        const double z = transfer_depth(ctx.pixel_mode, fb.depth.base[fb.depth.stride * fy + fx] / depth_max);
        uint8_t* dst = out + layout.row_stride * size_t(fy - y) + layout.pixel_bytes * size_t(fx - x);
        store_depth_stencil(z, uint32_t(stencil_at(fx, fy)), type, ctx.pack.swap_bytes, dst);
      }
    return;
  }
  const ImageLayout layout = image_layout(ctx.pack, width, format, type);
  auto* out = static_cast<uint8_t*>(pixels) + layout.offset;
  const bool color_identity = color_transfer_is_identity(ctx.pixel_mode);
  if (x0 >= x1 || y0 >= y1) return;
  uint8_t* const first = out + layout.row_stride * size_t(y0 - y) + layout.pixel_bytes * size_t(x0 - x);
  if (color_identity && reads_color_bytes(fb.color, format, type))
    return read_color_bytes(fb.color, d->alpha_bits == 0, format, x0, x1, y0, y1, first, layout.row_stride,
                            reverses_rgba8_words(type, ctx.pack.swap_bytes));
  if (color_identity && reads_color_components(fb.color, format, type, ctx.pack.swap_bytes))
    return read_color_components(fb.color, d->alpha_bits == 0, format, type, x0, x1, y0, y1, first, layout.row_stride);
  if (format == GL_DEPTH_COMPONENT && reads_depth_rows(ctx.pixel_mode, type, ctx.pack.swap_bytes))
    return read_depth_rows(fb.depth, type, x0, x1, y0, y1, first, layout.row_stride);
  if (format == GL_STENCIL_INDEX && reads_stencil_rows(ctx.pixel_mode, type))
    return read_stencil_rows(fb.stencil, x0, x1, y0, y1, first, layout.row_stride);
  for (int fy = y0; fy < y1; ++fy) {
    uint8_t* row = out + layout.row_stride * size_t(fy - y);
    for (int fx = x0; fx < x1; ++fx) {
      uint8_t* dst = row + layout.pixel_bytes * size_t(fx - x);
      if (format == GL_DEPTH_COMPONENT) {
        double z = fb.depth.base[fb.depth.stride * fy + fx] / depth_max;
        z = transfer_depth(ctx.pixel_mode, z);
        store_depth(z, type, dst);
      } else if (format == GL_STENCIL_INDEX) {
        store_index(stencil_at(fx, fy), type, dst);
      } else {
        double rgba[4];
        read_color(fb.color, fx, fy, rgba);
        if (d->alpha_bits == 0) rgba[3] = 1.0;
        if (!color_identity) transfer_read_color(ctx, rgba);
        store_color(rgba, format, type, dst);
      }
      if (ctx.pack.swap_bytes) swap_pixel_bytes(dst, format, type);
    }
  }
}

}  // namespace

void PixelStorei(Context& ctx, GLenum pname, GLint param) { set_store(ctx, pname, param); }
void PixelStoref(Context& ctx, GLenum pname, GLfloat param) { set_store(ctx, pname, param); }

void ReadPixels(Context& ctx, GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type,
                void* pixels) {
  read_pixels(ctx, x, y, width, height, format, type, pixels, SIZE_MAX);
}

void ReadnPixelsARB(Context& ctx, GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type,
                    GLsizei buf_size, void* data) {
  read_pixels(ctx, x, y, width, height, format, type, data, client_buffer_bytes(buf_size));
}

}  // namespace pineda::gl
