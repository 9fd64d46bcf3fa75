// The GLfixed forms of the parameter calls (OpenGL ES 1.1, OES_fixed_point): glFogx(v),
// glLightx(v), glLightModelx(v), glMaterialx(v), glTexEnvx(v), glTexParameterx(v),
// glPointParameterx(v). A value that names an enum (GL_FOG_MODE's GL_EXP, a texture filter...)
// is passed as it is; every other value is a 16.16 number, as Mesa converts them.
#include <algorithm>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/es1/enum_valued_params.h"
#include "state/es1/fixed.h"

namespace pineda::gl {
namespace {

using es1::fog_param_is_enum;
using es1::light_model_param_is_enum;
using es1::tex_env_param_is_enum;
using es1::tex_parameter_is_enum;


float convert(GLfixed value, bool is_enum) { return is_enum ? static_cast<float>(value) : es1::from_fixed(value); }

// The values a vector call reads for `pname`, converted: at most 4.
struct Converted {
  GLfloat v[4] = {};
  const GLfloat* get() const { return v; }
};

Converted convert_vector(const GLfixed* params, GLenum pname, bool is_enum) {
  Converted out;
  const size_t n = std::min<size_t>(list_param_count(pname), 4);
  for (size_t i = 0; i < n; ++i) out.v[i] = convert(params[i], is_enum);
  return out;
}

}  // namespace

void Fogx(Context& ctx, GLenum pname, GLfixed param) { Fogf(ctx, pname, convert(param, fog_param_is_enum(pname))); }
void Fogxv(Context& ctx, GLenum pname, const GLfixed* params) {
  if (!params) return Fogfv(ctx, pname, nullptr);
  Fogfv(ctx, pname, convert_vector(params, pname, fog_param_is_enum(pname)).get());
}

void Lightx(Context& ctx, GLenum light, GLenum pname, GLfixed param) {
  Lightf(ctx, light, pname, es1::from_fixed(param));
}
void Lightxv(Context& ctx, GLenum light, GLenum pname, const GLfixed* params) {
  if (!params) return Lightfv(ctx, light, pname, nullptr);
  Lightfv(ctx, light, pname, convert_vector(params, pname, false).get());
}

void LightModelx(Context& ctx, GLenum pname, GLfixed param) {
  LightModelf(ctx, pname, convert(param, light_model_param_is_enum(pname)));
}
void LightModelxv(Context& ctx, GLenum pname, const GLfixed* params) {
  if (!params) return LightModelfv(ctx, pname, nullptr);
  LightModelfv(ctx, pname, convert_vector(params, pname, light_model_param_is_enum(pname)).get());
}

void Materialx(Context& ctx, GLenum face, GLenum pname, GLfixed param) {
  Materialf(ctx, face, pname, es1::from_fixed(param));
}
void Materialxv(Context& ctx, GLenum face, GLenum pname, const GLfixed* params) {
  if (!params) return Materialfv(ctx, face, pname, nullptr);
  Materialfv(ctx, face, pname, convert_vector(params, pname, false).get());
}

void TexEnvx(Context& ctx, GLenum target, GLenum pname, GLfixed param) {
  TexEnvf(ctx, target, pname, convert(param, tex_env_param_is_enum(pname)));
}
void TexEnvxv(Context& ctx, GLenum target, GLenum pname, const GLfixed* params) {
  if (!params) return TexEnvfv(ctx, target, pname, nullptr);
  TexEnvfv(ctx, target, pname, convert_vector(params, pname, tex_env_param_is_enum(pname)).get());
}

void TexParameterx(Context& ctx, GLenum target, GLenum pname, GLfixed param) {
  TexParameterf(ctx, target, pname, convert(param, tex_parameter_is_enum(pname)));
}
void TexParameterxv(Context& ctx, GLenum target, GLenum pname, const GLfixed* params) {
  if (!params) return TexParameterfv(ctx, target, pname, nullptr);
  TexParameterfv(ctx, target, pname, convert_vector(params, pname, tex_parameter_is_enum(pname)).get());
}

void PointParameterx(Context& ctx, GLenum pname, GLfixed param) {
  PointParameterf(ctx, pname, es1::from_fixed(param));
}
void PointParameterxv(Context& ctx, GLenum pname, const GLfixed* params) {
  if (!params) return PointParameterfv(ctx, pname, nullptr);
  PointParameterfv(ctx, pname, convert_vector(params, pname, false).get());
}

}  // namespace pineda::gl
