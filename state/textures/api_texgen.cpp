// glTexGen / glGetTexGen: texture coordinate generation of the active texture unit.
#include <algorithm>
#include <cmath>
#include <type_traits>

#include <glm/gtc/matrix_inverse.hpp>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/enum_translate.h"
#include "state/pixels/pixel_state.h"

namespace pineda::gl {
namespace {

TexGenCoordState* coord_state(Context& ctx, GLenum coord) {
  if (coord < GL_S || coord > GL_Q) {
    ctx.record_error(GL_INVALID_ENUM, "coord is not GL_S, GL_T, GL_R or GL_Q");
    return nullptr;
  }
  if (!ctx.fixed_function_texture_unit()) {
    ctx.record_error(GL_INVALID_OPERATION, "the active texture unit is above GL_MAX_TEXTURE_UNITS");
    return nullptr;
  }
  return &ctx.extras.texgen[ctx.active_texture][coord - GL_S];
}

bool valid_mode(GLenum coord, GLenum mode) {
  switch (mode) {
    case GL_OBJECT_LINEAR: case GL_EYE_LINEAR: return true;
    case GL_SPHERE_MAP: return coord == GL_S || coord == GL_T;
    case GL_NORMAL_MAP: case GL_REFLECTION_MAP: return coord != GL_Q;
    default: return false;
  }
}

void set_mode(Context& ctx, GLenum coord, double value) {
  TexGenCoordState* c = coord_state(ctx, coord);
  if (!c) return;
  const GLenum mode = enum_from_float(value);
  if (static_cast<double>(mode) != value || !valid_mode(coord, mode))
    return ctx.record_error(GL_INVALID_ENUM, "param is not a texture generation mode of coord");
  c->mode = mode;
}

template <typename T>
void set_vector(Context& ctx, GLenum coord, GLenum pname, const T* params) {
  TexGenCoordState* c = coord_state(ctx, coord);
  if (!c || !params) return;
  switch (pname) {
    case GL_TEXTURE_GEN_MODE: return set_mode(ctx, coord, params[0]);
    case GL_OBJECT_PLANE: c->object_plane = glm::dvec4(params[0], params[1], params[2], params[3]); return;
    case GL_EYE_PLANE: {
      // GL 1.5 section 2.11.4: (p1 p2 p3 p4) M^-1, M the modelview at the time of the call.
      const glm::dvec4 p(params[0], params[1], params[2], params[3]);
      c->eye_plane = glm::transpose(glm::inverse(ctx.modelview.top())) * p;
      return;
    }
    default: return ctx.record_error(GL_INVALID_ENUM, "pname is not a texture generation parameter");
  }
}

// A plane given to a scalar form is (param, 0, 0, 0), as in Mesa.
void set_scalar(Context& ctx, GLenum coord, GLenum pname, double param) {
  const double v[4] = {param, 0, 0, 0};
  set_vector(ctx, coord, pname, v);
}

template <typename T>
void get_vector(Context& ctx, GLenum coord, GLenum pname, T* params) {
  const TexGenCoordState* c = coord_state(ctx, coord);
  if (!c) return;
  const glm::dvec4* plane = nullptr;
  switch (pname) {
    case GL_TEXTURE_GEN_MODE:
      if (params) params[0] = static_cast<T>(c->mode);
      return;
    case GL_OBJECT_PLANE: plane = &c->object_plane; break;
    case GL_EYE_PLANE: plane = &c->eye_plane; break;
    default: return ctx.record_error(GL_INVALID_ENUM, "pname is not a texture generation parameter");
  }
  if (!params) return;
  for (int i = 0; i < 4; ++i) {
    const double v = (*plane)[i];
    // GL 1.5 section 6.1.2: floating-point state is rounded to the nearest integer.
    if constexpr (std::is_integral_v<T>)
      params[i] = round_int_param(v);
    else
      params[i] = static_cast<T>(v);
  }
}

}  // namespace

void TexGeni(Context& ctx, GLenum coord, GLenum pname, GLint param) { set_scalar(ctx, coord, pname, param); }
void TexGenf(Context& ctx, GLenum coord, GLenum pname, GLfloat param) { set_scalar(ctx, coord, pname, param); }
void TexGend(Context& ctx, GLenum coord, GLenum pname, GLdouble param) { set_scalar(ctx, coord, pname, param); }
void TexGeniv(Context& ctx, GLenum coord, GLenum pname, const GLint* params) { set_vector(ctx, coord, pname, params); }
void TexGenfv(Context& ctx, GLenum coord, GLenum pname, const GLfloat* params) { set_vector(ctx, coord, pname, params); }
void TexGendv(Context& ctx, GLenum coord, GLenum pname, const GLdouble* params) { set_vector(ctx, coord, pname, params); }
void GetTexGeniv(Context& ctx, GLenum coord, GLenum pname, GLint* params) { get_vector(ctx, coord, pname, params); }
void GetTexGenfv(Context& ctx, GLenum coord, GLenum pname, GLfloat* params) { get_vector(ctx, coord, pname, params); }
void GetTexGendv(Context& ctx, GLenum coord, GLenum pname, GLdouble* params) { get_vector(ctx, coord, pname, params); }

}  // namespace pineda::gl
