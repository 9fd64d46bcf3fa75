#include "state/blend_function.h"

#include "state/context.h"
#include "state/enum_translate.h"

namespace pineda {

bool set_blend_factors(Context& ctx, GLenum src_rgb, GLenum dst_rgb, GLenum src_alpha, GLenum dst_alpha,
                       raster::BlendFunction& out) {
  raster::BlendFactor sr, dr, sa, da;
  if (!to_blend_factor(src_rgb, sr) || !to_blend_factor(dst_rgb, dr) || !to_blend_factor(src_alpha, sa) ||
      !to_blend_factor(dst_alpha, da)) {
    ctx.record_error(GL_INVALID_ENUM, "a factor is not a blend factor");
    return false;
  }
  out.src_rgb = sr;
  out.dst_rgb = dr;
  out.src_alpha = sa;
  out.dst_alpha = da;
  return true;
}

bool set_blend_equations(Context& ctx, GLenum mode_rgb, GLenum mode_alpha, raster::BlendFunction& out) {
  raster::BlendEquation rgb, alpha;
  if (!to_blend_equation(mode_rgb, rgb) || !to_blend_equation(mode_alpha, alpha)) {
    ctx.record_error(GL_INVALID_ENUM, "a mode is not a blend equation");
    return false;
  }
  out.eq_rgb = rgb;
  out.eq_alpha = alpha;
  return true;
}

bool blend_function_state(GLenum target) {
  switch (target) {
    case GL_BLEND_SRC: case GL_BLEND_DST:
    case GL_BLEND_SRC_RGB: case GL_BLEND_DST_RGB: case GL_BLEND_SRC_ALPHA: case GL_BLEND_DST_ALPHA:
    case GL_BLEND_EQUATION_RGB: case GL_BLEND_EQUATION_ALPHA:
      return true;
    default:
      return false;
  }
}

GLenum blend_function_enum(const raster::BlendFunction& f, GLenum target) {
  switch (target) {
    case GL_BLEND_SRC:
    case GL_BLEND_SRC_RGB: return blend_factor_enum(f.src_rgb);
    case GL_BLEND_DST:
    case GL_BLEND_DST_RGB: return blend_factor_enum(f.dst_rgb);
    case GL_BLEND_SRC_ALPHA: return blend_factor_enum(f.src_alpha);
    case GL_BLEND_DST_ALPHA: return blend_factor_enum(f.dst_alpha);
    case GL_BLEND_EQUATION_RGB: return blend_equation_enum(f.eq_rgb);
    default: return blend_equation_enum(f.eq_alpha);
  }
}

raster::BlendFunction& blend_function(Context& ctx, GLuint index) {
  raster::DrawState& s = ctx.draw_state;
  return index == 0 ? s.blend_state : s.more_targets[index - 1].blend_function;
}

void set_every_blend_factors(Context& ctx, const raster::BlendFunction& f) {
  for (GLuint i = 0; i < GLuint(raster::kMaxColorTargets); ++i) {
    raster::BlendFunction& b = blend_function(ctx, i);
    b.src_rgb = f.src_rgb;
    b.dst_rgb = f.dst_rgb;
    b.src_alpha = f.src_alpha;
    b.dst_alpha = f.dst_alpha;
  }
}

void set_every_blend_equations(Context& ctx, const raster::BlendFunction& f) {
  for (GLuint i = 0; i < GLuint(raster::kMaxColorTargets); ++i) {
    raster::BlendFunction& b = blend_function(ctx, i);
    b.eq_rgb = f.eq_rgb;
    b.eq_alpha = f.eq_alpha;
  }
}

}  // namespace pineda
