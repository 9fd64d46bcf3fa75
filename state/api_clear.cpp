// glClear and the clear values.
#include <algorithm>

#include "glapi/gl_entry_points.h"
#include "state/accum.h"
#include "state/context.h"

namespace pineda::gl {
namespace {
float clamp01(float v) { return v > 0.f ? (v < 1.f ? v : 1.f) : 0.f; }  // NaN -> 0
}

void Clear(Context& ctx, GLbitfield mask) {
  if (mask & ~(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT)) {
    ctx.record_error(GL_INVALID_VALUE, "mask has bits other than the four buffer bits");
    return;
  }
  if (!check_draw_framebuffer(ctx) || !ctx.draw_drawable()) return;
  if (mask & GL_ACCUM_BUFFER_BIT) clear_accum(ctx);
  raster::ClearState clear;
  clear.color = mask & GL_COLOR_BUFFER_BIT;
  clear.depth = mask & GL_DEPTH_BUFFER_BIT;
  clear.stencil = mask & GL_STENCIL_BUFFER_BIT;
  std::copy(ctx.clear_color, ctx.clear_color + 4, clear.color_value);
  clear.depth_value = ctx.clear_depth;
  clear.stencil_value = ctx.clear_stencil;
  clear.color_write = ctx.draw_state.color_write;
  for (size_t i = 0; i < clear.more_color_write.size(); ++i)
    clear.more_color_write[i] = ctx.draw_state.more_targets[i].color_write;
  clear.stencil_write_mask = static_cast<uint8_t>(ctx.stencil_write_mask);
  clear.depth_write = ctx.draw_state.depth_write;
  clear.scissor_test = ctx.draw_state.scissor_test;
  clear.scissor = ctx.draw_state.scissor;
  ctx.render_to_draw_buffers([&] { ctx.renderer().clear(clear); });
}

void ClearColor(Context& ctx, GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
  ctx.clear_color[0] = clamp01(r);
  ctx.clear_color[1] = clamp01(g);
  ctx.clear_color[2] = clamp01(b);
  ctx.clear_color[3] = clamp01(a);
}

void ClearDepth(Context& ctx, GLdouble depth) { ctx.clear_depth = depth > 0.0 ? (depth < 1.0 ? depth : 1.0) : 0.0; }

void ClearStencil(Context& ctx, GLint s) { ctx.clear_stencil = s; }

}  // namespace pineda::gl
