#include "state/accum.h"

#include <algorithm>

#include "state/context.h"

namespace pineda {

AccumRect prepare_accum(Context& ctx, int width, int height) {
  AccumState& a = ctx.accum;
  if (a.width != width || a.height != height) {
    a.width = std::max(width, 0);
    a.height = std::max(height, 0);
    a.values.assign(size_t(a.width) * size_t(a.height) * 4, 0);
  }
  AccumRect r{0, 0, a.width, a.height};
  if (ctx.draw_state.scissor_test) {
    const raster::Rect& s = ctx.draw_state.scissor;
    r.x0 = std::clamp(s.x, 0, a.width);
    r.y0 = std::clamp(s.y, 0, a.height);
    r.x1 = int(std::clamp<int64_t>(int64_t{s.x} + s.width, r.x0, a.width));
    r.y1 = int(std::clamp<int64_t>(int64_t{s.y} + s.height, r.y0, a.height));
  }
  return r;
}

void clear_accum(Context& ctx) {
  const Drawable* d = ctx.draw_drawable();
  if (!d || !d->accum) return;
  const AccumRect r = prepare_accum(ctx, d->framebuffer.width, d->framebuffer.height);
  int16_t value[4];
  for (int c = 0; c < 4; ++c)  // Mesa's FLOAT_TO_SHORT: -1 -> -32768, 1 -> 32767
    value[c] = static_cast<int16_t>((ctx.accum.clear_value[c] * 65535.f - 1.f) / 2.f);
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x)
      std::copy(value, value + 4, &ctx.accum.values[(size_t(y) * ctx.accum.width + x) * 4]);
}

}  // namespace pineda
