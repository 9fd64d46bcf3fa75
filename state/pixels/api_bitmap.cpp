// glBitmap (GL 1.5 spec 3.7).
#include <algorithm>
#include <cmath>
#include <vector>

#include "glapi/gl_entry_points.h"
#include "raster/fragment_ops.h"
#include "raster/pixel_rect.h"
#include "state/context.h"
#include "state/draw.h"
#include "state/buffers/pixel_buffer.h"
#include "state/pixels/pixel_unpack.h"

namespace pineda::gl {
namespace {

// Every set bit becomes a fragment with the raster position's colour, depth and texture
// coordinates; the bitmap's lower-left corner is at floor(raster position - origin).
void draw_bitmap(Context& ctx, GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig, const GLubyte* bitmap) {
  ctx.finish();
  const RasterPosition& rp = ctx.raster_pos;
  raster::PixelFragmentWriter writer(fragment_snapshot(ctx), ctx.renderer().framebuffer(), rp.texcoord,
                                     rp.distance);
  // As Mesa: a small epsilon keeps a position computed as 9.99999 on pixel 10.
  constexpr double kEpsilon = 0.0001;
  const double fx = std::floor(double(rp.window[0]) - xorig + kEpsilon);
  const double fy = std::floor(double(rp.window[1]) - yorig + kEpsilon);
  if (!std::isfinite(fx) || !std::isfinite(fy) || std::abs(fx) > 1e9 || std::abs(fy) > 1e9) return;
  const int x0 = int(fx), y0 = int(fy);
  const BitmapLayout bits(ctx.unpack, width);
  if (writer.writes_rgba8_rows()) {  // runs of set bits straight into the colour buffer
    const uint32_t word = raster::to_rgba8_word(rp.color);
    const int fb_width = ctx.renderer().framebuffer().width;
    const std::vector<uint32_t> run(size_t(std::clamp(fb_width, 0, width)), word);  // a run is at most both
    for (int j = 0; j < height; ++j) {
      const int64_t y = int64_t(y0) + j;
      if (y < 0 || y > 0x7fffffff) continue;
      for (int i = 0; i < width;) {
        if (!bits.bit(bitmap, i, j)) {
          ++i;
          continue;
        }
        const int first = i;
        while (i < width && bits.bit(bitmap, i, j)) ++i;
        // The run's columns inside the framebuffer (rgba8_row clips to the scissor rectangle).
        const int64_t left = std::max<int64_t>(int64_t(x0) + first, 0), right = std::min<int64_t>(int64_t(x0) + i, fb_width);
        if (left < right) writer.rgba8_row(int(left), int(y), run.data(), int(right - left), rp.window[2]);
      }
    }
    return;
  }
  for (int j = 0; j < height; ++j) {
    const int64_t y = int64_t(y0) + j;
    if (y < 0 || y > 0x7fffffff) continue;
    for (int i = 0; i < width; ++i) {
      const int64_t x = int64_t(x0) + i;
      if (x < 0 || x > 0x7fffffff || !writer.inside(int(x), int(y))) continue;
      if (bits.bit(bitmap, i, j)) writer.fragment(int(x), int(y), rp.color, rp.window[2]);
    }
  }
}

}  // namespace

void Bitmap(Context& ctx, GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig, GLfloat xmove, GLfloat ymove,
            const GLubyte* bitmap) {
  if (width < 0 || height < 0) return ctx.record_error(GL_INVALID_VALUE, "width or height is negative");
  if (!check_draw_framebuffer(ctx)) return;
  RasterPosition& rp = ctx.raster_pos;
  if (!rp.valid) return;
  if (!pixel_rect_feedback(ctx, GL_BITMAP_TOKEN) && width > 0 && height > 0) {
    const void* data = bitmap;  // a bad pixel unpack buffer range leaves the raster position too (as Mesa)
    if (!unpack_pixels(ctx, data, client_image_extent(ctx.unpack, width, height, 1, false, GL_COLOR_INDEX, GL_BITMAP)))
      return;
    if (data && ctx.draw_drawable())
      ctx.render_to_draw_buffers(
          [&] { draw_bitmap(ctx, width, height, xorig, yorig, static_cast<const GLubyte*>(data)); });
  }
  rp.window[0] += xmove;
  rp.window[1] += ymove;
}

}  // namespace pineda::gl
