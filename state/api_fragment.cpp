// Per-fragment operation state: alpha, depth, blend, logic op, masks, scissor.
#include <algorithm>

#include "glapi/gl_entry_points.h"
#include "state/blend_function.h"
#include "state/context.h"
#include "state/enum_translate.h"

namespace pineda::gl {
namespace {
float clamp01(float v) { return v > 0.f ? (v < 1.f ? v : 1.f) : 0.f; }  // NaN -> 0
}

void AlphaFunc(Context& ctx, GLenum func, GLfloat ref) {
  raster::CompareFunc f;
  if (!to_compare_func(func, f)) return ctx.record_error(GL_INVALID_ENUM, "func is not a comparison function");
  ctx.alpha_func = func;
  ctx.draw_state.alpha_func = f;
  ctx.draw_state.alpha_ref = clamp01(ref);
}

void DepthFunc(Context& ctx, GLenum func) {
  raster::CompareFunc f;
  if (!to_compare_func(func, f)) return ctx.record_error(GL_INVALID_ENUM, "func is not a comparison function");
  ctx.depth_func = func;
  ctx.draw_state.depth_func = f;
}

void DepthMask(Context& ctx, GLboolean flag) { ctx.draw_state.depth_write = flag != GL_FALSE; }

// glStencilFunc, glStencilOp and glStencilMask: api_stencil.cpp (per face).

// glBlendFunc and glBlendEquation set every draw buffer's (ARB_draw_buffers_blend; the
// indexed forms one buffer's: api_draw_buffers_blend.cpp).
void BlendFuncSeparate(Context& ctx, GLenum src_rgb, GLenum dst_rgb, GLenum src_alpha, GLenum dst_alpha) {
  raster::BlendFunction f = ctx.draw_state.blend_state;
  if (!set_blend_factors(ctx, src_rgb, dst_rgb, src_alpha, dst_alpha, f)) return;
  set_every_blend_factors(ctx, f);
}

void BlendFunc(Context& ctx, GLenum src, GLenum dst) { BlendFuncSeparate(ctx, src, dst, src, dst); }

void BlendEquationSeparate(Context& ctx, GLenum mode_rgb, GLenum mode_alpha) {
  raster::BlendFunction f = ctx.draw_state.blend_state;
  if (!set_blend_equations(ctx, mode_rgb, mode_alpha, f)) return;
  set_every_blend_equations(ctx, f);
}

void BlendEquation(Context& ctx, GLenum mode) { BlendEquationSeparate(ctx, mode, mode); }

void BlendColor(Context& ctx, GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
  float* c = ctx.draw_state.blend_state.color;
  c[0] = clamp01(r);
  c[1] = clamp01(g);
  c[2] = clamp01(b);
  c[3] = clamp01(a);
}

void LogicOp(Context& ctx, GLenum opcode) {
  raster::LogicOp op;
  if (!to_logic_op(opcode, op)) return ctx.record_error(GL_INVALID_ENUM, "opcode is not a logic operation");
  ctx.logic_op = opcode;
  ctx.draw_state.logic_op = op;
}

// Every draw buffer's mask (GL 3.0 4.2.2; EXT_draw_buffers2 sets them one at a time).
void ColorMask(Context& ctx, GLboolean r, GLboolean g, GLboolean b, GLboolean a) {
  ctx.draw_state.color_write = {r != GL_FALSE, g != GL_FALSE, b != GL_FALSE, a != GL_FALSE};
  for (raster::DrawState::TargetWrite& t : ctx.draw_state.more_targets) t.color_write = ctx.draw_state.color_write;
}

void Scissor(Context& ctx, GLint x, GLint y, GLsizei width, GLsizei height) {
  if (width < 0 || height < 0) return ctx.record_error(GL_INVALID_VALUE, "width or height is negative");
  ctx.draw_state.scissor = {x, y, width, height};
}

}  // namespace pineda::gl

// The EXT names of the blend extensions Pineda advertises.
namespace pineda::gl {
void BlendColorEXT(Context& ctx, GLfloat r, GLfloat g, GLfloat b, GLfloat a) { BlendColor(ctx, r, g, b, a); }
void BlendEquationEXT(Context& ctx, GLenum mode) { BlendEquation(ctx, mode); }
void BlendEquationSeparateEXT(Context& ctx, GLenum rgb, GLenum alpha) { BlendEquationSeparate(ctx, rgb, alpha); }
void BlendFuncSeparateEXT(Context& ctx, GLenum sr, GLenum dr, GLenum sa, GLenum da) {
  BlendFuncSeparate(ctx, sr, dr, sa, da);
}
}  // namespace pineda::gl
