#include "state/textures/tex_env_state.h"

namespace pineda {
namespace {

raster::CombineFunc to_func(GLenum f) {
  switch (f) {
    case GL_REPLACE: return raster::CombineFunc::Replace;
    case GL_ADD: return raster::CombineFunc::Add;
    case GL_ADD_SIGNED: return raster::CombineFunc::AddSigned;
    case GL_INTERPOLATE: return raster::CombineFunc::Interpolate;
    case GL_SUBTRACT: return raster::CombineFunc::Subtract;
    case GL_DOT3_RGB: return raster::CombineFunc::Dot3Rgb;
    case GL_DOT3_RGBA: return raster::CombineFunc::Dot3Rgba;
    default: return raster::CombineFunc::Modulate;
  }
}

raster::CombineSource to_source(GLenum s) {
  switch (s) {
    case GL_TEXTURE: return raster::CombineSource::Texture;
    case GL_CONSTANT: return raster::CombineSource::Constant;
    case GL_PRIMARY_COLOR: return raster::CombineSource::PrimaryColor;
    case GL_PREVIOUS: return raster::CombineSource::Previous;
    default: return raster::CombineSource(int(raster::CombineSource::Texture0) + int(s - GL_TEXTURE0));
  }
}

raster::CombineOperand to_operand(GLenum o) {
  switch (o) {
    case GL_ONE_MINUS_SRC_COLOR: return raster::CombineOperand::OneMinusSrcColor;
    case GL_SRC_ALPHA: return raster::CombineOperand::SrcAlpha;
    case GL_ONE_MINUS_SRC_ALPHA: return raster::CombineOperand::OneMinusSrcAlpha;
    default: return raster::CombineOperand::SrcColor;
  }
}

}  // namespace

raster::TexEnvMode raster_env_mode(const TexEnvState& env) {
  switch (env.mode) {
    case GL_REPLACE: return raster::TexEnvMode::Replace;
    case GL_DECAL: return raster::TexEnvMode::Decal;
    case GL_BLEND: return raster::TexEnvMode::Blend;
    case GL_ADD: return raster::TexEnvMode::Add;
    case GL_COMBINE: return raster::TexEnvMode::Combine;
    default: return raster::TexEnvMode::Modulate;
  }
}

raster::CombineState raster_combine(const TexEnvState& env) {
  raster::CombineState c;
  c.rgb_func = to_func(env.combine_rgb);
  c.alpha_func = to_func(env.combine_alpha);
  for (int i = 0; i < 3; ++i) {
    c.rgb_source[i] = to_source(env.source_rgb[i]);
    c.alpha_source[i] = to_source(env.source_alpha[i]);
    c.rgb_operand[i] = to_operand(env.operand_rgb[i]);
    c.alpha_operand[i] = to_operand(env.operand_alpha[i]);
  }
  c.rgb_scale = env.rgb_scale;
  c.alpha_scale = env.alpha_scale;
  return c;
}

}  // namespace pineda
