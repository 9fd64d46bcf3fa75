#include "state/enum_translate.h"

namespace pineda {

bool to_compare_func(GLenum e, raster::CompareFunc& out) {
  if (e < GL_NEVER || e > GL_ALWAYS) return false;
  out = static_cast<raster::CompareFunc>(e - GL_NEVER);  // GL orders them as raster does
  return true;
}

bool to_stencil_op(GLenum e, raster::StencilOp& out) {
  using S = raster::StencilOp;
  switch (e) {
    case GL_KEEP: out = S::Keep; return true;
    case GL_ZERO: out = S::Zero; return true;
    case GL_REPLACE: out = S::Replace; return true;
    case GL_INCR: out = S::Incr; return true;
    case GL_DECR: out = S::Decr; return true;
    case GL_INVERT: out = S::Invert; return true;
    case GL_INCR_WRAP: out = S::IncrWrap; return true;
    case GL_DECR_WRAP: out = S::DecrWrap; return true;
    default: return false;
  }
}

bool to_blend_factor(GLenum e, raster::BlendFactor& out) {
  using B = raster::BlendFactor;
  switch (e) {
    case GL_ZERO: out = B::Zero; return true;
    case GL_ONE: out = B::One; return true;
    case GL_SRC_COLOR: out = B::SrcColor; return true;
    case GL_ONE_MINUS_SRC_COLOR: out = B::OneMinusSrcColor; return true;
    case GL_DST_COLOR: out = B::DstColor; return true;
    case GL_ONE_MINUS_DST_COLOR: out = B::OneMinusDstColor; return true;
    case GL_SRC_ALPHA: out = B::SrcAlpha; return true;
    case GL_ONE_MINUS_SRC_ALPHA: out = B::OneMinusSrcAlpha; return true;
    case GL_DST_ALPHA: out = B::DstAlpha; return true;
    case GL_ONE_MINUS_DST_ALPHA: out = B::OneMinusDstAlpha; return true;
    case GL_CONSTANT_COLOR: out = B::ConstantColor; return true;
    case GL_ONE_MINUS_CONSTANT_COLOR: out = B::OneMinusConstantColor; return true;
    case GL_CONSTANT_ALPHA: out = B::ConstantAlpha; return true;
    case GL_ONE_MINUS_CONSTANT_ALPHA: out = B::OneMinusConstantAlpha; return true;
    case GL_SRC_ALPHA_SATURATE: out = B::SrcAlphaSaturate; return true;
    default: return false;
  }
}

bool to_blend_equation(GLenum e, raster::BlendEquation& out) {
  using E = raster::BlendEquation;
  switch (e) {
    case GL_FUNC_ADD: out = E::Add; return true;
    case GL_FUNC_SUBTRACT: out = E::Subtract; return true;
    case GL_FUNC_REVERSE_SUBTRACT: out = E::ReverseSubtract; return true;
    case GL_MIN: out = E::Min; return true;
    case GL_MAX: out = E::Max; return true;
    default: return false;
  }
}

GLenum blend_factor_enum(raster::BlendFactor f) {
  static constexpr GLenum kEnums[] = {GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR,
                                      GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA,
                                      GL_ONE_MINUS_DST_ALPHA, GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR,
                                      GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA, GL_SRC_ALPHA_SATURATE};
  return kEnums[static_cast<size_t>(f)];
}

GLenum blend_equation_enum(raster::BlendEquation e) {
  static constexpr GLenum kEnums[] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};
  return kEnums[static_cast<size_t>(e)];
}

bool to_logic_op(GLenum e, raster::LogicOp& out) {
  if (e < GL_CLEAR || e > GL_SET) return false;
  out = static_cast<raster::LogicOp>(e - GL_CLEAR);  // GL orders them as raster does
  return true;
}

bool to_polygon_mode(GLenum e, raster::PolygonMode& out) {
  switch (e) {
    case GL_POINT: out = raster::PolygonMode::Point; return true;
    case GL_LINE: out = raster::PolygonMode::Line; return true;
    case GL_FILL: out = raster::PolygonMode::Fill; return true;
    default: return false;
  }
}

bool to_primitive(GLenum e, raster::Primitive& out) {
  if (e > GL_POLYGON) return false;
  out = static_cast<raster::Primitive>(e);  // GL_POINTS..GL_POLYGON are 0..9, as in raster
  return true;
}

}  // namespace pineda
