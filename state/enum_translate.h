// GL enums to raster's plain enums. Each returns false for a value GL does not accept.
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

#include "raster/draw_state.h"

namespace pineda {

// An enum given as a float parameter (glTexGenf, glTexEnvf, glTexParameterf, glFogf), truncated
// as an integer one would be; a value no GLenum holds (negative, too large, NaN) is no enum.
inline GLenum enum_from_float(double v) {
  return v >= 0.0 && v < 4294967296.0 ? static_cast<GLenum>(v) : GLenum(0xFFFFFFFFu);
}

bool to_compare_func(GLenum e, raster::CompareFunc& out);
bool to_stencil_op(GLenum e, raster::StencilOp& out);
bool to_blend_factor(GLenum e, raster::BlendFactor& out);
bool to_blend_equation(GLenum e, raster::BlendEquation& out);
// The GL enum of a factor or equation (what glGet returns for it).
GLenum blend_factor_enum(raster::BlendFactor f);
GLenum blend_equation_enum(raster::BlendEquation e);
bool to_logic_op(GLenum e, raster::LogicOp& out);
bool to_polygon_mode(GLenum e, raster::PolygonMode& out);
bool to_primitive(GLenum e, raster::Primitive& out);

}  // namespace pineda
