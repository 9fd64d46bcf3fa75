// glTexEnv and glGetTexEnv: the active unit's environment mode and colour, its LOD bias, and the
// GL_COMBINE parameters (GL 1.3, ARB_texture_env_combine, _crossbar, _dot3).
#include <algorithm>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/enum_translate.h"
#include "state/pixels/pixel_state.h"
#include "state/point_sprite.h"

namespace pineda::gl {
namespace {

bool is_env_mode(GLenum m) {
  return m == GL_MODULATE || m == GL_REPLACE || m == GL_DECAL || m == GL_BLEND || m == GL_ADD || m == GL_COMBINE;
}

bool is_combine_alpha_func(GLenum f) {
  return f == GL_REPLACE || f == GL_MODULATE || f == GL_ADD || f == GL_ADD_SIGNED || f == GL_INTERPOLATE ||
         f == GL_SUBTRACT;
}
bool is_combine_rgb_func(GLenum f) { return is_combine_alpha_func(f) || f == GL_DOT3_RGB || f == GL_DOT3_RGBA; }

bool is_combine_source(GLenum s) {
  return s == GL_TEXTURE || s == GL_CONSTANT || s == GL_PRIMARY_COLOR || s == GL_PREVIOUS ||
         (s >= GL_TEXTURE0 && s < GL_TEXTURE0 + raster::kMaxTextureUnits);
}

bool is_alpha_operand(GLenum o) { return o == GL_SRC_ALPHA || o == GL_ONE_MINUS_SRC_ALPHA; }
bool is_rgb_operand(GLenum o) { return is_alpha_operand(o) || o == GL_SRC_COLOR || o == GL_ONE_MINUS_SRC_COLOR; }

// The enum-valued parameter `pname` of `env`, or null when it is not one.
GLenum* enum_param(TexEnvState& env, GLenum pname) {
  switch (pname) {
    case GL_TEXTURE_ENV_MODE: return &env.mode;
    case GL_COMBINE_RGB: return &env.combine_rgb;
    case GL_COMBINE_ALPHA: return &env.combine_alpha;
    case GL_SOURCE0_RGB: case GL_SOURCE1_RGB: case GL_SOURCE2_RGB: return &env.source_rgb[pname - GL_SOURCE0_RGB];
    case GL_SOURCE0_ALPHA: case GL_SOURCE1_ALPHA: case GL_SOURCE2_ALPHA:
      return &env.source_alpha[pname - GL_SOURCE0_ALPHA];
    case GL_OPERAND0_RGB: case GL_OPERAND1_RGB: case GL_OPERAND2_RGB: return &env.operand_rgb[pname - GL_OPERAND0_RGB];
    case GL_OPERAND0_ALPHA: case GL_OPERAND1_ALPHA: case GL_OPERAND2_ALPHA:
      return &env.operand_alpha[pname - GL_OPERAND0_ALPHA];
    default: return nullptr;
  }
}

bool valid_enum_value(GLenum pname, GLenum v) {
  switch (pname) {
    case GL_TEXTURE_ENV_MODE: return is_env_mode(v);
    case GL_COMBINE_RGB: return is_combine_rgb_func(v);
    case GL_COMBINE_ALPHA: return is_combine_alpha_func(v);
    case GL_SOURCE0_RGB: case GL_SOURCE1_RGB: case GL_SOURCE2_RGB:
    case GL_SOURCE0_ALPHA: case GL_SOURCE1_ALPHA: case GL_SOURCE2_ALPHA:
      return is_combine_source(v);
    case GL_OPERAND0_RGB: case GL_OPERAND1_RGB: case GL_OPERAND2_RGB: return is_rgb_operand(v);
    default: return is_alpha_operand(v);
  }
}

float* scale_param(TexEnvState& env, GLenum pname) {
  if (pname == GL_RGB_SCALE) return &env.rgb_scale;
  if (pname == GL_ALPHA_SCALE) return &env.alpha_scale;
  return nullptr;
}

void tex_env(Context& ctx, GLenum target, GLenum pname, const GLfloat* v) {
  if (!ctx.fixed_function_texture_unit())
    return ctx.record_error(GL_INVALID_OPERATION, "the active texture unit is above GL_MAX_TEXTURE_UNITS");
  TexEnvState& env = ctx.texture_units[ctx.active_texture].env;
  if (target == GL_TEXTURE_FILTER_CONTROL && pname == GL_TEXTURE_LOD_BIAS) {
    env.lod_bias = v[0];
    return;
  }
  if (target == GL_POINT_SPRITE) return set_point_sprite_env(ctx, pname, v[0]);
  if (target != GL_TEXTURE_ENV) return ctx.record_error(GL_INVALID_ENUM, "target is not a texture environment target");
  if (pname == GL_TEXTURE_ENV_COLOR) {
    for (int i = 0; i < 4; ++i) env.color[i] = std::clamp(v[i], 0.f, 1.f);
  } else if (GLenum* e = enum_param(env, pname)) {
    const GLenum value = enum_from_float(v[0]);
    if (!valid_enum_value(pname, value)) return ctx.record_error(GL_INVALID_ENUM, "param is not a value of pname");
    *e = value;
  } else if (float* scale = scale_param(env, pname)) {
    if (v[0] != 1.f && v[0] != 2.f && v[0] != 4.f)
      return ctx.record_error(GL_INVALID_VALUE, "the scale is not 1, 2 or 4");
    *scale = v[0];
  } else {
    ctx.record_error(GL_INVALID_ENUM, "pname is not a texture environment parameter");
  }
}

// The values of an environment parameter and how many there are; 0 (and an error) when
// it is not one.
int get_tex_env(Context& ctx, GLenum target, GLenum pname, GLfloat v[4]) {
  if (!ctx.fixed_function_texture_unit()) {
    ctx.record_error(GL_INVALID_OPERATION, "the active texture unit is above GL_MAX_TEXTURE_UNITS");
    return 0;
  }
  TexEnvState& env = ctx.texture_units[ctx.active_texture].env;
  if (target == GL_TEXTURE_FILTER_CONTROL && pname == GL_TEXTURE_LOD_BIAS) {
    v[0] = env.lod_bias;
    return 1;
  }
  if (target == GL_POINT_SPRITE) return get_point_sprite_env(ctx, pname, v[0]) ? 1 : 0;
  if (target != GL_TEXTURE_ENV) {
    ctx.record_error(GL_INVALID_ENUM, "target is not a texture environment target");
    return 0;
  }
  if (pname == GL_TEXTURE_ENV_COLOR) {
    std::copy(env.color, env.color + 4, v);
    return 4;
  }
  if (const GLenum* e = enum_param(env, pname)) {
    v[0] = GLfloat(*e);
    return 1;
  }
  if (const float* scale = scale_param(env, pname)) {
    v[0] = *scale;
    return 1;
  }
  ctx.record_error(GL_INVALID_ENUM, "pname is not a texture environment parameter");
  return 0;
}

}  // namespace

void TexEnvf(Context& ctx, GLenum target, GLenum pname, GLfloat param) {
  const GLfloat v[4] = {param, 0, 0, 0};  // a vector parameter takes (param, 0, 0, 0), as in Mesa
  tex_env(ctx, target, pname, v);
}
void TexEnvi(Context& ctx, GLenum target, GLenum pname, GLint param) { TexEnvf(ctx, target, pname, GLfloat(param)); }
void TexEnvfv(Context& ctx, GLenum target, GLenum pname, const GLfloat* params) {
  if (params) tex_env(ctx, target, pname, params);
}
void TexEnviv(Context& ctx, GLenum target, GLenum pname, const GLint* params) {
  if (!params) return;
  GLfloat v[4] = {GLfloat(params[0]), 0, 0, 0};
  if (pname == GL_TEXTURE_ENV_COLOR)
    for (int i = 0; i < 4; ++i) v[i] = colour_from_int_param(params[i]);
  tex_env(ctx, target, pname, v);
}

void GetTexEnvfv(Context& ctx, GLenum target, GLenum pname, GLfloat* params) {
  GLfloat v[4];
  const int n = get_tex_env(ctx, target, pname, v);
  if (n && params) std::copy(v, v + n, params);
}
void GetTexEnviv(Context& ctx, GLenum target, GLenum pname, GLint* params) {
  GLfloat v[4];
  const int n = get_tex_env(ctx, target, pname, v);
  if (!n || !params) return;
  if (pname == GL_TEXTURE_ENV_COLOR)
    for (int i = 0; i < 4; ++i) params[i] = colour_int_param(v[i]);
  else
    params[0] = truncate_int_param(v[0]);
}

}  // namespace pineda::gl
