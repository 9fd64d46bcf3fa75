// glDrawPixels and glCopyPixels (GL 1.5 spec 3.6.4, 4.3.3).
#include <algorithm>
#include <cstring>

#include "glapi/gl_entry_points.h"
#include "raster/color_reduction.h"
#include "state/context.h"
#include "state/framebuffers/packed_depth_stencil.h"
#include "state/buffers/pixel_buffer.h"
#include "state/pixels/pixel_format.h"
#include "state/pixels/pixel_rect_draw.h"
#include "state/pixels/pixel_transfer.h"
#include "state/pixels/pixel_unpack.h"

namespace pineda::gl {
namespace {

bool has_depth(const Drawable* d) { return d && d->framebuffer.depth.bits > 0; }
bool has_stencil(const Drawable* d) { return d && d->framebuffer.stencil.bits > 0; }

GlError draw_pixels_error(const Context& ctx, GLenum format, GLenum type) {
  if (GlError error; packed_depth_stencil_pixels(format, type, error)) {
    if (error == GL_NO_ERROR && (!has_depth(ctx.draw_drawable()) || !has_stencil(ctx.draw_drawable())))
      return {GL_INVALID_OPERATION, "the draw framebuffer has no depth or no stencil buffer"};
    return error;
  }
  if (const GlError error = pixel_rect_format_type_error(format, type); error != GL_NO_ERROR) return error;
  if (format == GL_DEPTH_COMPONENT && !has_depth(ctx.draw_drawable()))
    return {GL_INVALID_OPERATION, "the draw framebuffer has no depth buffer"};
  if (format == GL_STENCIL_INDEX && !has_stencil(ctx.draw_drawable()))
    return {GL_INVALID_OPERATION, "the draw framebuffer has no stencil buffer"};
  return GL_NO_ERROR;
}

// The source rectangle of glCopyPixels, read before anything is drawn (the rectangles may
// overlap). Pixels outside the read buffer produce no fragments.
PixelRectImage read_rect(const Context& ctx, const raster::Framebuffer& fb, int x, int y, int width, int height,
                         GLenum type) {
  PixelRectImage image;
  image.width = width;
  image.height = height;
  const size_t n = size_t(width) * size_t(height);
  image.present.assign(n, 0);
  // Without pixel transfer, colour is kept as the bytes read (PixelRectImage::rgba8).
  const bool color_words = type == GL_COLOR && color_transfer_is_identity(ctx.pixel_mode);
  if (type == GL_COLOR) {
    image.kind = PixelRectImage::Kind::Color;
    if (color_words) image.rgba8.assign(n, 0);
    else image.color.assign(4 * n, 0.f);
  } else {
    image.kind = type == GL_DEPTH     ? PixelRectImage::Kind::Depth
                 : type == GL_STENCIL ? PixelRectImage::Kind::Stencil
                                      : PixelRectImage::Kind::DepthStencil;
    if (type != GL_STENCIL) image.depth.assign(n, 0.0);
    if (type != GL_DEPTH) image.stencil.assign(n, 0);
  }
  if (color_words && !fb.color.reduction.active) {  // rows of stored words, BGRA8's swapped
    const int64_t left = std::max<int64_t>(x, 0), right = std::min<int64_t>(int64_t(x) + width, fb.width);
    for (int j = 0; j < height && left < right; ++j) {
      const int64_t sy = int64_t(y) + j;
      if (sy < 0 || sy >= fb.height) continue;
      const size_t k = size_t(j) * width + size_t(left - x), count = size_t(right - left);
      std::memcpy(&image.rgba8[k], fb.color.base + fb.color.stride * sy + 4 * left, 4 * count);
      if (fb.color.format == raster::ColorFormat::BGRA8)
        for (size_t i = 0; i < count; ++i) image.rgba8[k + i] = raster::swap_red_blue(image.rgba8[k + i]);
      std::memset(&image.present[k], 1, count);
    }
    return image;
  }
  const double depth_max = fb.depth.bits >= 32 ? 4294967295.0 : double((1ull << fb.depth.bits) - 1);
  for (int j = 0; j < height; ++j) {
    const int64_t sy = int64_t(y) + j;
    if (sy < 0 || sy >= fb.height) continue;
    for (int i = 0; i < width; ++i) {
      const int64_t sx = int64_t(x) + i;
      if (sx < 0 || sx >= fb.width) continue;
      const size_t k = size_t(j) * width + i;
      image.present[k] = 1;
      if (type == GL_COLOR) {
        uint8_t bytes[4];
        raster::read_rgba8(fb.color, fb.color.base + fb.color.stride * sy + 4 * sx, bytes);
        if (color_words) {
          std::memcpy(&image.rgba8[k], bytes, 4);
          continue;
        }
        float* rgba = &image.color[4 * k];
        for (int c = 0; c < 4; ++c) rgba[c] = bytes[c] / 255.f;
        transfer_color(ctx.pixel_mode, ctx.pixel_maps, rgba);
        continue;
      }
      if (type != GL_STENCIL)
        image.depth[k] = transfer_depth(ctx.pixel_mode, fb.depth.base[fb.depth.stride * sy + sx] / depth_max);
      if (type != GL_DEPTH)
        image.stencil[k] = transfer_stencil(ctx.pixel_mode, ctx.pixel_maps, fb.stencil.base[fb.stencil.stride * sy + sx]);
    }
  }
  return image;
}

}  // namespace

void DrawPixels(Context& ctx, GLsizei width, GLsizei height, GLenum format, GLenum type, const void* pixels) {
  if (width < 0 || height < 0) return ctx.record_error(GL_INVALID_VALUE, "width or height is negative");
  if (!check_draw_framebuffer(ctx)) return;
  if (const GlError error = draw_pixels_error(ctx, format, type); error != GL_NO_ERROR) return ctx.record_error(error);
  if (!ctx.raster_pos.valid || pixel_rect_feedback(ctx, GL_DRAW_PIXEL_TOKEN)) return;
  if (width == 0 || height == 0 || !ctx.draw_drawable()) return;
  if (!unpack_pixels(ctx, pixels, client_image_extent(ctx.unpack, width, height, 1, false, format, type)) || !pixels)
    return;
  PixelRectImage image;
  image.width = width;
  image.height = height;
  const ColorImageReader color_reader(ctx, width, format, type, pixels);
  if (format == GL_DEPTH_COMPONENT) {
    image.kind = PixelRectImage::Kind::Depth;
    image.depth = unpack_depth_image(ctx, width, height, type, pixels);
  } else if (format == GL_DEPTH_STENCIL) {
    image.kind = PixelRectImage::Kind::DepthStencil;
    unpack_depth_stencil_image(ctx, width, height, type, pixels, image.depth, image.stencil);
  } else if (format == GL_STENCIL_INDEX) {
    image.kind = PixelRectImage::Kind::Stencil;
    image.stencil = unpack_stencil_image(ctx, width, height, type, pixels);
  } else {
    image.color_reader = &color_reader;
  }
  draw_pixel_rect(ctx, image);
}

void CopyPixels(Context& ctx, GLint x, GLint y, GLsizei width, GLsizei height, GLenum type) {
  if (width < 0 || height < 0) return ctx.record_error(GL_INVALID_VALUE, "width or height is negative");
  // GL_DEPTH_STENCIL: EXT_packed_depth_stencil's copy of both, as Mesa takes it at any version.
  if (type != GL_COLOR && type != GL_DEPTH && type != GL_STENCIL && type != GL_DEPTH_STENCIL)
    return ctx.record_error(GL_INVALID_ENUM, "type is not GL_COLOR, GL_DEPTH, GL_STENCIL or GL_DEPTH_STENCIL");
  if (!check_draw_framebuffer(ctx) || !check_read_single_sampled(ctx)) return;
  const Drawable* draw = ctx.draw_drawable();
  const Drawable* read = ctx.read_drawable();
  const bool depth = type == GL_DEPTH || type == GL_DEPTH_STENCIL, stencil = type == GL_STENCIL || type == GL_DEPTH_STENCIL;
  if (depth && (!has_depth(draw) || !has_depth(read)))
    return ctx.record_error(GL_INVALID_OPERATION, "the draw or read framebuffer has no depth buffer");
  if (type == GL_COLOR && read && !ctx.read_framebuffer().color.base)
    return ctx.record_error(GL_INVALID_OPERATION, "the read framebuffer has no colour buffer to read");
  if (stencil && (!has_stencil(draw) || !has_stencil(read)))
    return ctx.record_error(GL_INVALID_OPERATION, "the draw or read framebuffer has no stencil buffer");
  if (!ctx.raster_pos.valid || pixel_rect_feedback(ctx, GL_COPY_PIXEL_TOKEN)) return;
  if (width == 0 || height == 0 || !draw || !read) return;
  ctx.finish();
  const raster::Framebuffer& fb = ctx.read_framebuffer();
  // Colour rows read as they are drawn (PixelRectImage::source_rows) where that order can keep
  // every source row intact until it is read; else the rectangle copied first.
  if (type == GL_COLOR && color_transfer_is_identity(ctx.pixel_mode) && !fb.color.reduction.active &&
      ctx.pixel_mode.zoom_y == 1.f && ctx.renders_draw_buffers_in_one_pass() && x >= 0 && y >= 0 &&
      int64_t(x) + width <= fb.width && int64_t(y) + height <= fb.height) {
    PixelRectImage image;
    image.width = width;
    image.height = height;
    image.source_rows = {fb.color, x, y};
    return draw_pixel_rect(ctx, image);
  }
  draw_pixel_rect(ctx, read_rect(ctx, fb, x, y, width, height, type));
}

}  // namespace pineda::gl
