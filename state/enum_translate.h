// GL enums to raster's plain enums. Each returns false for a value GL does not accept.
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

#include "raster/draw_state.h"

namespace pineda {

bool to_compare_func(GLenum e, raster::CompareFunc& out);
bool to_stencil_op(GLenum e, raster::StencilOp& out);
bool to_blend_factor(GLenum e, raster::BlendFactor& out);
bool to_blend_equation(GLenum e, raster::BlendEquation& out);
bool to_logic_op(GLenum e, raster::LogicOp& out);
bool to_polygon_mode(GLenum e, raster::PolygonMode& out);
bool to_primitive(GLenum e, raster::Primitive& out);

}  // namespace pineda
