#include "state/point_parameters.h"

#include "glapi/gl_entry_points.h"
#include "state/context.h"

namespace pineda {

bool query_point_parameters(Context& ctx, unsigned pname, GetValues& out) {
  const raster::PointParameters& p = ctx.draw_state.point_params;
  switch (pname) {
    case GL_POINT_SIZE_MIN: out = get_floats({p.size_min}); return true;
    case GL_POINT_SIZE_MAX: out = get_floats({p.size_max}); return true;
    case GL_POINT_FADE_THRESHOLD_SIZE: out = get_floats({p.fade_threshold}); return true;
    case GL_POINT_DISTANCE_ATTENUATION:
      out = get_floats({p.attenuation[0], p.attenuation[1], p.attenuation[2]});
      return true;
    case GL_POINT_SPRITE_COORD_ORIGIN:
      out = get_enums({double(p.sprite.origin_lower_left ? GL_LOWER_LEFT : GL_UPPER_LEFT)});
      return true;
    default: return false;
  }
}

void snapshot_point_parameters(const Context& ctx, raster::Transform& t) {
  const raster::DrawState& s = ctx.draw_state;
  t.extras.point_attenuation = s.point_params.per_vertex();
  t.extras.point = s.point_params;
  t.extras.point_size = s.point_size;
}

}  // namespace pineda

namespace pineda::gl {

// `v` holds 3 values for GL_POINT_DISTANCE_ATTENUATION, 1 otherwise.
void PointParameterfv(Context& ctx, GLenum pname, const GLfloat* v) {
  if (!v) return;
  raster::PointParameters& p = ctx.draw_state.point_params;
  switch (pname) {
    case GL_POINT_SIZE_MIN:
    case GL_POINT_SIZE_MAX:
    case GL_POINT_FADE_THRESHOLD_SIZE:
      if (!(v[0] >= 0.f)) return ctx.record_error(GL_INVALID_VALUE, "the size or threshold is negative");
      (pname == GL_POINT_SIZE_MIN ? p.size_min : pname == GL_POINT_SIZE_MAX ? p.size_max : p.fade_threshold) = v[0];
      return;
    case GL_POINT_DISTANCE_ATTENUATION:
      for (int i = 0; i < 3; ++i) p.attenuation[i] = v[i];
      return;
    case GL_POINT_SPRITE_COORD_ORIGIN:  // GL 2.0 point sprites
      if (v[0] != GLfloat(GL_LOWER_LEFT) && v[0] != GLfloat(GL_UPPER_LEFT))
        return ctx.record_error(GL_INVALID_VALUE, "GL_POINT_SPRITE_COORD_ORIGIN is not GL_LOWER_LEFT or GL_UPPER_LEFT");
      p.sprite.origin_lower_left = v[0] == GLfloat(GL_LOWER_LEFT);
      return;
    default:
      return ctx.record_error(GL_INVALID_ENUM, "pname is not a point parameter");
  }
}

// The scalar forms pass (param, 0, 0), so that DISTANCE_ATTENUATION takes (param, 0, 0) as in Mesa.
void PointParameterf(Context& ctx, GLenum pname, GLfloat param) {
  const GLfloat v[3] = {param, 0.f, 0.f};
  PointParameterfv(ctx, pname, v);
}
void PointParameteri(Context& ctx, GLenum pname, GLint param) { PointParameterf(ctx, pname, GLfloat(param)); }
void PointParameteriv(Context& ctx, GLenum pname, const GLint* params) {
  if (!params) return;
  GLfloat v[3] = {GLfloat(params[0]), 0.f, 0.f};
  if (pname == GL_POINT_DISTANCE_ATTENUATION)
    for (int i = 1; i < 3; ++i) v[i] = GLfloat(params[i]);
  PointParameterfv(ctx, pname, v);
}
void PointParameterfARB(Context& ctx, GLenum pname, GLfloat param) { PointParameterf(ctx, pname, param); }
void PointParameterfvARB(Context& ctx, GLenum pname, const GLfloat* params) { PointParameterfv(ctx, pname, params); }
void PointParameterfEXT(Context& ctx, GLenum pname, GLfloat param) { PointParameterf(ctx, pname, param); }
void PointParameterfvEXT(Context& ctx, GLenum pname, const GLfloat* params) { PointParameterfv(ctx, pname, params); }

}  // namespace pineda::gl
