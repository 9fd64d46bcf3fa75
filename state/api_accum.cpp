// glAccum and glClearAccum: the accumulation buffer's operations, in the arithmetic of Mesa's
// 16-bit signed accumulation buffers.
#include <algorithm>
#include <cmath>

#include "glapi/gl_entry_points.h"
#include "raster/multisample.h"
#include "state/accum.h"
#include "state/context.h"

namespace pineda::gl {
namespace {

constexpr float kAccumScale = 32767.f;

// NaN (an infinite value times a zero channel) is 0.
int16_t to_accum(float v) { return std::isnan(v) ? 0 : static_cast<int16_t>(std::clamp(v, -32768.f, 32767.f)); }

// Byte offsets of R, G, B, A in a pixel of `format`.
void channel_offsets(raster::ColorFormat format, int out[4]) {
  const bool bgra = format == raster::ColorFormat::BGRA8;
  out[0] = bgra ? 2 : 0;
  out[1] = 1;
  out[2] = bgra ? 0 : 2;
  out[3] = 3;
}

uint8_t* pixel_at(const raster::ColorBuffer& color, int x, int y) {
  return color.base + static_cast<ptrdiff_t>(y) * color.stride + static_cast<ptrdiff_t>(x) * 4;
}

// GL_ACCUM and GL_LOAD: the read buffer's colours times `value`, added or stored.
void accumulate(Context& ctx, const AccumRect& r, const raster::ColorBuffer& color, float value, bool load) {
  int offset[4];
  channel_offsets(color.format, offset);
  const float scale = value * kAccumScale;
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x) {
      const uint8_t* p = pixel_at(color, x, y);
      int16_t* acc = &ctx.accum.values[(size_t(y) * ctx.accum.width + x) * 4];
      for (int c = 0; c < 4; ++c) {
        const float v = p[offset[c]] / 255.f * scale;
        acc[c] = to_accum(load ? std::trunc(v) : acc[c] + std::trunc(v));
      }
    }
}

// GL_RETURN: the accumulated values times `value` into the draw buffer, through the colour mask.
void return_to_color(Context& ctx, const AccumRect& r, const raster::ColorBuffer& color, float value) {
  int offset[4];
  channel_offsets(color.format, offset);
  const float scale = value / kAccumScale;
  const std::array<bool, 4>& mask = ctx.draw_state.color_write;
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x) {
      uint8_t* p = pixel_at(color, x, y);
      const int16_t* acc = &ctx.accum.values[(size_t(y) * ctx.accum.width + x) * 4];
      for (int c = 0; c < 4; ++c)
        if (mask[c]) p[offset[c]] = static_cast<uint8_t>(std::lrint(std::clamp(acc[c] * scale, 0.f, 1.f) * 255.f));
    }
}

// GL_MULT and GL_ADD.
void scale_or_bias(Context& ctx, const AccumRect& r, float value, bool bias) {
  const float increment = std::trunc(value * kAccumScale);
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x) {
      int16_t* acc = &ctx.accum.values[(size_t(y) * ctx.accum.width + x) * 4];
      for (int c = 0; c < 4; ++c) acc[c] = to_accum(bias ? acc[c] + increment : std::trunc(acc[c] * value));
    }
}

}  // namespace

void ClearAccum(Context& ctx, GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
  const GLfloat v[4] = {r, g, b, a};
  for (int c = 0; c < 4; ++c) ctx.accum.clear_value[c] = std::isnan(v[c]) ? 0.f : std::clamp(v[c], -1.f, 1.f);
}

void Accum(Context& ctx, GLenum op, GLfloat value) {
  if (op != GL_ACCUM && op != GL_LOAD && op != GL_RETURN && op != GL_MULT && op != GL_ADD)
    return ctx.record_error(GL_INVALID_ENUM, "op is not an accumulation operation");
  if (!check_draw_framebuffer(ctx) || !check_read_framebuffer(ctx)) return;
  Drawable* draw = ctx.draw_drawable();
  if (!draw || !draw->accum)
    return ctx.record_error(GL_INVALID_OPERATION, "the draw framebuffer has no accumulation buffer");
  if (std::isnan(value)) value = 0.f;
  ctx.finish();  // the colour buffers hold every queued draw
  const AccumRect r = prepare_accum(ctx, draw->framebuffer.width, draw->framebuffer.height);
  switch (op) {
    case GL_ACCUM:
    case GL_LOAD: {
      const Drawable* read = ctx.read_drawable() ? ctx.read_drawable() : draw;
      const raster::Framebuffer& fb = read->framebuffer;
      if (!fb.color.base) return;
      const AccumRect area{r.x0, r.y0, std::min(r.x1, fb.width), std::min(r.y1, fb.height)};
      if (fb.samples > 1 && read->resolved.base) {  // a multisampled window: its resolved colour
        raster::resolve_color(fb, read->resolved);
        return accumulate(ctx, area, read->resolved, value, op == GL_LOAD);
      }
      return accumulate(ctx, area, fb.color, value, op == GL_LOAD);
    }
    case GL_RETURN:
      if (!draw->framebuffer.color.base) return;
      for (int sample = 0; sample < draw->framebuffer.samples; ++sample)  // every sample of each pixel
        return_to_color(ctx, r, raster::sample_plane(draw->framebuffer, sample).color, value);
      return;
    default: return scale_or_bias(ctx, r, value, op == GL_ADD);
  }
}

}  // namespace pineda::gl
