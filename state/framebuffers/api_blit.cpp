// glBlitFramebuffer (GL_EXT_framebuffer_blit, GL_ARB_framebuffer_object; GL 3.0 4.3.3): a
// rectangle of the read framebuffer copied, scaled and mirrored as the two rectangles say,
// into the draw framebuffer. Only the scissor test applies; pixels whose source lies
// outside the read framebuffer are not written.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "glapi/gl_entry_points.h"
#include "raster/color_reduction.h"
#include "raster/multisample.h"
#include "state/context.h"
#include "state/framebuffers/framebuffer_object.h"

namespace pineda::gl {
namespace {

// Whether a framebuffer object's depth image has a float format (a window's never has).
bool float_depth(Context& ctx, const FramebufferObject* fb) {
  if (!fb) return false;
  const std::optional<RenderableFormat> format = attachment_format(ctx, fb->attachments[kDepthPoint]);
  return format && format->depth_float;
}

// The source rectangle's pixels, copied before anything is written (the rectangles may
// overlap in one framebuffer): bytes R, G, B, A; depth values; stencil indices.
struct SourceImage {
  int x0 = 0, y0 = 0, width = 0, height = 0;  // the part of the read framebuffer copied
  std::vector<uint8_t> color;
  std::vector<uint32_t> depth;
  std::vector<uint8_t> stencil;
};

SourceImage read_source(const raster::Framebuffer& fb, bool opaque, GLint sx0, GLint sy0, GLint sx1, GLint sy1,
                        bool color, bool depth, bool stencil) {
  SourceImage img;
  img.x0 = int(std::clamp<int64_t>(std::min(sx0, sx1), 0, fb.width));
  img.y0 = int(std::clamp<int64_t>(std::min(sy0, sy1), 0, fb.height));
  img.width = int(std::clamp<int64_t>(std::max(sx0, sx1), 0, fb.width)) - img.x0;
  img.height = int(std::clamp<int64_t>(std::max(sy0, sy1), 0, fb.height)) - img.y0;
  const size_t n = size_t(img.width) * size_t(img.height);
  if (color) img.color.resize(4 * n);
  if (depth) img.depth.resize(n);
  if (stencil) img.stencil.resize(n);
  for (int j = 0; j < img.height; ++j) {
    const int y = img.y0 + j;
    if (color && fb.samples > 1)  // depth and stencil: sample 0's
      raster::resolve_rgba8_row(fb, img.x0, y, img.width, &img.color[4 * size_t(j) * img.width]);
    for (int i = 0; i < img.width; ++i) {
      const int x = img.x0 + i;
      const size_t k = size_t(j) * img.width + i;
      if (color) {
        uint8_t* o = &img.color[4 * k];
        if (fb.samples == 1) raster::read_rgba8(fb.color, fb.color.base + fb.color.stride * y + 4 * x, o);
        if (opaque) o[3] = 255;
      }
      if (depth) img.depth[k] = fb.depth.base[fb.depth.stride * y + x];
      if (stencil) img.stencil[k] = fb.stencil.base[fb.stencil.stride * y + x];
    }
  }
  return img;
}

// One axis of the mapping: destination pixel d (its centre d + 0.5) reads source coordinate
// s0 + (d + 0.5 - d0) * (s1 - s0) / (d1 - d0).
struct Axis {
  double s0, scale, d0;
  double source(int d) const { return s0 + (d + 0.5 - d0) * scale; }
};

void write_color(const raster::ColorBuffer& cb, int x, int y, const uint8_t source[4]) {
  uint8_t rgba[4] = {source[0], source[1], source[2], source[3]};
  if (cb.reduction.active) raster::reduce_bytes(cb.reduction, rgba);
  uint8_t* p = cb.base + cb.stride * y + 4 * x;
  const bool bgra = cb.format == raster::ColorFormat::BGRA8;
  p[bgra ? 2 : 0] = rgba[0];
  p[1] = rgba[1];
  p[bgra ? 0 : 2] = rgba[2];
  p[3] = rgba[3];
}

// write_color of n pixels from (x, y) rightwards; source[4 * i]: pixel i.
void write_color_row(const raster::ColorBuffer& cb, int x, int y, int n, const uint8_t* source) {
  uint8_t* p = cb.base + cb.stride * y + 4 * x;
  if (cb.reduction.active) {
    for (int i = 0; i < n; ++i) write_color(cb, x + i, y, source + 4 * i);
  } else if (cb.format == raster::ColorFormat::BGRA8) {
    for (int i = 0; i < n; ++i) {
      p[4 * i] = source[4 * i + 2];
      p[4 * i + 1] = source[4 * i + 1];
      p[4 * i + 2] = source[4 * i];
      p[4 * i + 3] = source[4 * i + 3];
    }
  } else {
    std::copy_n(source, 4 * n, p);
  }
}

}  // namespace

void BlitFramebuffer(Context& ctx, GLint srcX0, GLint srcY0, GLint srcX1, GLint srcY1, GLint dstX0, GLint dstY0,
                     GLint dstX1, GLint dstY1, GLbitfield mask, GLenum filter) {
  if (!check_draw_framebuffer(ctx) || !check_read_framebuffer(ctx)) return;
  if (filter != GL_NEAREST && filter != GL_LINEAR)
    return ctx.record_error(GL_INVALID_ENUM, "filter is not GL_NEAREST or GL_LINEAR");
  if (mask & ~GLbitfield(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT))
    return ctx.record_error(GL_INVALID_VALUE, "mask has bits other than colour, depth and stencil");
  if ((mask & (GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT)) && filter != GL_NEAREST)
    return ctx.record_error(GL_INVALID_OPERATION, "depth or stencil copies take filter GL_NEAREST only");
  const Drawable* draw = ctx.draw_drawable();
  const Drawable* read = ctx.read_drawable();
  if (!draw || !read) return;
  const raster::Framebuffer src_fb = ctx.read_framebuffer();
  const raster::Framebuffer& dst_all = draw->framebuffer;
  // Depth and stencil copy between buffers of one format only.
  const bool depth = (mask & GL_DEPTH_BUFFER_BIT) && src_fb.depth.bits && dst_all.depth.bits;
  const bool stencil = (mask & GL_STENCIL_BUFFER_BIT) && src_fb.stencil.bits && dst_all.stencil.bits;
  if (depth && (src_fb.depth.bits != dst_all.depth.bits ||
                float_depth(ctx, ctx.framebuffers.read_object()) != float_depth(ctx, ctx.framebuffers.draw_object())))
    return ctx.record_error(GL_INVALID_OPERATION, "the framebuffers' depth formats differ");
  if (stencil && src_fb.stencil.bits != dst_all.stencil.bits)
    return ctx.record_error(GL_INVALID_OPERATION, "the framebuffers' stencil formats differ");
  const bool color = (mask & GL_COLOR_BUFFER_BIT) && src_fb.color.base;
  if ((!color && !depth && !stencil) || srcX0 == srcX1 || srcY0 == srcY1 || dstX0 == dstX1 || dstY0 == dstY1) return;

  // GL 3.0 4.3.3 (EXT_framebuffer_multisample): samples are copied between equal counts, a
  // multisampled source is resolved into a single-sampled destination, a single-sampled one
  // replicated into every sample; a multisampled source takes no scaling. It may move or mirror:
  // EXT_framebuffer_multisample asks for rectangles of one size only, as Mesa does on desktop GL
  // (GL 3.0's same bounds would refuse resolves into another place that programs make).
  const int src_samples = src_fb.samples, dst_samples = dst_all.samples;
  if (src_samples > 1 && dst_samples > 1 && src_samples != dst_samples)
    return ctx.record_error(GL_INVALID_OPERATION, "the framebuffers' sample counts differ");
  auto extent = [](GLint a, GLint b) { return std::abs(int64_t{b} - a); };
  if (src_samples > 1 &&
      (extent(srcX0, srcX1) != extent(dstX0, dstX1) || extent(srcY0, srcY1) != extent(dstY0, dstY1)))
    return ctx.record_error(GL_INVALID_OPERATION, "a multisampled source and the destination differ in size");
  const bool per_sample = src_samples > 1 && dst_samples > 1;

  ctx.finish();
  std::vector<SourceImage> images;  // one per sample when copied sample by sample
  for (int sample = 0; sample < (per_sample ? src_samples : 1); ++sample)
    images.push_back(read_source(per_sample ? raster::sample_plane(src_fb, sample) : src_fb, read->alpha_bits == 0, srcX0,
                                 srcY0, srcX1, srcY1, color, depth, stencil));
  const SourceImage& img = images[0];
  if (img.width <= 0 || img.height <= 0) return;
  const Axis ax{double(srcX0), (double(srcX1) - srcX0) / (double(dstX1) - dstX0), double(dstX0)};
  const Axis ay{double(srcY0), (double(srcY1) - srcY0) / (double(dstY1) - dstY0), double(dstY0)};
  const bool linear = filter == GL_LINEAR;
  // Source coordinates outside the copied part (so outside the read framebuffer or the source
  // rectangle) are not written.
  auto inside = [&](double u, double v) {
    return u >= img.x0 && u < img.x0 + img.width && v >= img.y0 && v < img.y0 + img.height;
  };
  auto copy_into = [&](const raster::Framebuffer& fb, const SourceImage& img) {
    int x0 = std::max(std::min(dstX0, dstX1), 0), x1 = int(std::min<int64_t>(std::max(dstX0, dstX1), fb.width));
    int y0 = std::max(std::min(dstY0, dstY1), 0), y1 = int(std::min<int64_t>(std::max(dstY0, dstY1), fb.height));
    const raster::DrawState& s = ctx.draw_state;
    if (s.scissor_test) {
      x0 = std::max(x0, s.scissor.x);
      y0 = std::max(y0, s.scissor.y);
      x1 = int(std::min<int64_t>(x1, int64_t{s.scissor.x} + std::max(s.scissor.width, 0)));
      y1 = int(std::min<int64_t>(y1, int64_t{s.scissor.y} + std::max(s.scissor.height, 0)));
    }
    // A copy of the same size and orientation without filtering: the source pixel of
    // destination x is x + shift, and the colour is copied a row at a time.
    const bool copy_rows = color && !linear && ax.scale == 1.0 && ay.scale == 1.0;
    const int64_t shift = int64_t{srcX0} - dstX0;
    for (int y = y0; y < y1; ++y) {
      const double v = ay.source(y);
      if (copy_rows && v >= img.y0 && v < img.y0 + img.height) {
        const int first = int(std::max<int64_t>(x0, img.x0 - shift));
        const int last = int(std::min<int64_t>(x1, img.x0 + img.width - shift));
        const int sj = int(std::floor(v)) - img.y0;
        const uint8_t* row = &img.color[4 * (size_t(sj) * img.width + size_t(first + shift - img.x0))];
        if (first < last)
          for (int t = 0; t < fb.color_targets; ++t)
            if (fb.target_color(t).base) write_color_row(fb.target_color(t), first, y, last - first, row);
      }
      if (copy_rows && !depth && !stencil) continue;
      for (int x = x0; x < x1; ++x) {
        const double u = ax.source(x);
        if (!inside(u, v)) continue;
        const int si = int(std::floor(u)) - img.x0, sj = int(std::floor(v)) - img.y0;
        const size_t k = size_t(sj) * img.width + si;
        if (color && !copy_rows) {
          uint8_t rgba[4];
          if (!linear) {
            std::copy_n(&img.color[4 * k], 4, rgba);
          } else {  // bilinear between the four nearest source pixel centres, clamped to the copied part
            const double fu = u - 0.5 - img.x0, fv = v - 0.5 - img.y0;
            const double bu = std::floor(fu), bv = std::floor(fv);
            const double wu = fu - bu, wv = fv - bv;
            auto at = [&](double i, double j, int c) {
              const int ci = int(std::clamp(i, 0.0, double(img.width - 1)));
              const int cj = int(std::clamp(j, 0.0, double(img.height - 1)));
              return double(img.color[4 * (size_t(cj) * img.width + ci) + c]);
            };
            for (int c = 0; c < 4; ++c) {
              const double top = at(bu, bv + 1, c) * (1 - wu) + at(bu + 1, bv + 1, c) * wu;
              const double bottom = at(bu, bv, c) * (1 - wu) + at(bu + 1, bv, c) * wu;
              rgba[c] = uint8_t(std::clamp(std::nearbyint(bottom * (1 - wv) + top * wv), 0.0, 255.0));
            }
          }
          for (int t = 0; t < fb.color_targets; ++t)  // every draw buffer (GL 3.0 4.3.3)
            if (fb.target_color(t).base) write_color(fb.target_color(t), x, y, rgba);
        }
        if (depth) fb.depth.base[fb.depth.stride * y + x] = img.depth[k];
        if (stencil) fb.stencil.base[fb.stencil.stride * y + x] = img.stencil[k];
      }
    }
  };
  ctx.render_to_draw_buffers([&] {
    ctx.finish();
    const raster::Framebuffer& fb = ctx.renderer().framebuffer();
    for (int sample = 0; sample < fb.samples; ++sample)
      copy_into(fb.samples > 1 ? raster::sample_plane(fb, sample) : fb, images[per_sample ? sample : 0]);
  });
}

}  // namespace pineda::gl
