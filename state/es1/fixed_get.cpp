// The GLfixed queries of OpenGL ES 1.1: glGetFixedv and the GLfixed forms of glGetLight,
// glGetMaterial, glGetTexEnv and glGetTexParameter, converted as Mesa converts them: numbers
// to 16.16 (truncated, saturated), enum values as they are, booleans to 0 or 1.0.
#include <algorithm>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/es1/enum_valued_params.h"
#include "state/es1/fixed.h"
#include "state/get_values.h"

namespace pineda::gl {
namespace {

// Runs a float query into a local array and converts what it wrote; leaves `params` alone
// when the query failed.
template <typename Query>
void get_converted(Context& ctx, GLenum pname, GLfixed* params, bool is_enum, Query query) {
  GLfloat values[4] = {};
  const uint64_t errors = ctx.errors_recorded();
  query(values);
  if (!params || ctx.errors_recorded() != errors) return;
  const size_t n = std::min<size_t>(list_param_count(pname), 4);
  for (size_t i = 0; i < n; ++i)
    params[i] = is_enum ? static_cast<GLfixed>(values[i]) : es1::to_fixed(values[i]);
}

}  // namespace

void GetFixedv(Context& ctx, GLenum pname, GLfixed* params) {
  GetValues values;
  if (!query_get_values(ctx, pname, values)) return ctx.record_error(GL_INVALID_ENUM, "pname is not a state variable");
  if (!params) return;
  for (size_t i = 0; i < values.v.size(); ++i) {
    const double v = values.v[i];
    switch (values.kind) {
      case GetKind::Enum: params[i] = static_cast<GLfixed>(v); break;
      case GetKind::Bool: params[i] = v != 0.0 ? 65536 : 0; break;
      case GetKind::Int: params[i] = es1::int_to_fixed(static_cast<long long>(v)); break;
      case GetKind::Float: case GetKind::Color: params[i] = es1::to_fixed(v); break;
    }
  }
}

void GetLightxv(Context& ctx, GLenum light, GLenum pname, GLfixed* params) {
  get_converted(ctx, pname, params, false, [&](GLfloat* v) { GetLightfv(ctx, light, pname, v); });
}

void GetMaterialxv(Context& ctx, GLenum face, GLenum pname, GLfixed* params) {
  get_converted(ctx, pname, params, false, [&](GLfloat* v) { GetMaterialfv(ctx, face, pname, v); });
}

void GetTexEnvxv(Context& ctx, GLenum target, GLenum pname, GLfixed* params) {
  get_converted(ctx, pname, params, es1::tex_env_param_is_enum(pname), [&](GLfloat* v) { GetTexEnvfv(ctx, target, pname, v); });
}

void GetTexParameterxv(Context& ctx, GLenum target, GLenum pname, GLfixed* params) {
  get_converted(ctx, pname, params, es1::tex_parameter_is_enum(pname), [&](GLfloat* v) { GetTexParameterfv(ctx, target, pname, v); });
}

}  // namespace pineda::gl
