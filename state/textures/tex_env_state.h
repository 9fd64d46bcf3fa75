// A texture unit's environment as the application set it (GL enums, for glGetTexEnv and
// glPushAttrib), and its translation for the rasterizer.
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

#include "raster/texture.h"

namespace pineda {

struct TexEnvState {
  GLenum mode = GL_MODULATE;
  float color[4] = {0, 0, 0, 0};
  // GL_COMBINE
  GLenum combine_rgb = GL_MODULATE, combine_alpha = GL_MODULATE;
  GLenum source_rgb[3] = {GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  GLenum source_alpha[3] = {GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
  GLenum operand_rgb[3] = {GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA};
  GLenum operand_alpha[3] = {GL_SRC_ALPHA, GL_SRC_ALPHA, GL_SRC_ALPHA};
  float rgb_scale = 1.f, alpha_scale = 1.f;
  float lod_bias = 0.f;  // GL_TEXTURE_FILTER_CONTROL
};

// GL 1.4: the largest |bias| a level-of-detail sum keeps.
constexpr float kMaxTextureLodBias = 16.f;

raster::TexEnvMode raster_env_mode(const TexEnvState& env);
raster::CombineState raster_combine(const TexEnvState& env);

}  // namespace pineda
