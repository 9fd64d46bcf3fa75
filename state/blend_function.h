// Blend factors and equations from GL enums, for glBlendFunc/glBlendEquation and their
// per-draw-buffer forms (ARB_draw_buffers_blend).
#pragma once
#include <GL/gl.h>

#include "raster/draw_state.h"

namespace pineda {

class Context;

// The four factors into `out`, or INVALID_ENUM recorded and `out` unchanged.
bool set_blend_factors(Context& ctx, GLenum src_rgb, GLenum dst_rgb, GLenum src_alpha, GLenum dst_alpha,
                       raster::BlendFunction& out);
// The two equations into `out`, or INVALID_ENUM recorded and `out` unchanged.
bool set_blend_equations(Context& ctx, GLenum mode_rgb, GLenum mode_alpha, raster::BlendFunction& out);

// Whether glGet names a factor or equation: BLEND_SRC/DST(_RGB/_ALPHA), BLEND_EQUATION_RGB/ALPHA
// (GL 1.0's BLEND_SRC and BLEND_DST name the RGB ones; Mesa answers them per draw buffer too).
bool blend_function_state(GLenum pname);
// The GL enum of that factor or equation in `f`.
GLenum blend_function_enum(const raster::BlendFunction& f, GLenum pname);

// Draw buffer `index`'s factors and equations (0: blend_state's).
raster::BlendFunction& blend_function(Context& ctx, GLuint index);

// Every draw buffer's factors (or equations) to those of `f`.
void set_every_blend_factors(Context& ctx, const raster::BlendFunction& f);
void set_every_blend_equations(Context& ctx, const raster::BlendFunction& f);

}  // namespace pineda
