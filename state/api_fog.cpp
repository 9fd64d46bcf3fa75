// glFog, the current fog coordinate (glFogCoord) and its array (GL 1.4, EXT_fog_coord).
#include <algorithm>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/enum_translate.h"

namespace pineda::gl {
namespace {

// GL 1.5 section 3.10: scalar parameters, and FOG_COLOR for the vector forms only.
// `color` holds FOG_COLOR already converted to floating point.
void set_fog(Context& ctx, GLenum pname, double value, const float* color) {
  raster::Fog& fog = ctx.draw_state.fog;
  VertexExtrasState& x = ctx.extras;
  switch (pname) {
    case GL_FOG_MODE: {
      const GLenum mode = enum_from_float(value);
      if (static_cast<double>(mode) != value) return ctx.record_error(GL_INVALID_ENUM, "GL_FOG_MODE is not an enum");
      switch (mode) {
        case GL_LINEAR: fog.mode = raster::FogMode::Linear; break;
        case GL_EXP: fog.mode = raster::FogMode::Exp; break;
        case GL_EXP2: fog.mode = raster::FogMode::Exp2; break;
        default: return ctx.record_error(GL_INVALID_ENUM, "GL_FOG_MODE is not GL_LINEAR, GL_EXP or GL_EXP2");
      }
      x.fog_mode = mode;
      return;
    }
    case GL_FOG_COORD_SRC: {
      const GLenum source = enum_from_float(value);
      if (static_cast<double>(source) != value || (source != GL_FOG_COORD && source != GL_FRAGMENT_DEPTH))
        return ctx.record_error(GL_INVALID_ENUM, "GL_FOG_COORD_SRC is not GL_FOG_COORD or GL_FRAGMENT_DEPTH");
      x.fog_coord_source = source;
      return;
    }
    case GL_FOG_DENSITY:
      if (value < 0.0) return ctx.record_error(GL_INVALID_VALUE, "GL_FOG_DENSITY is negative");
      fog.density = static_cast<float>(value);
      return;
    case GL_FOG_START: fog.start = static_cast<float>(value); return;
    case GL_FOG_END: fog.end = static_cast<float>(value); return;
    case GL_FOG_INDEX: x.fog_index = static_cast<float>(value); return;
    case GL_FOG_COLOR:
      if (!color) return ctx.record_error(GL_INVALID_ENUM, "GL_FOG_COLOR takes a vector: use glFogfv or glFogiv");
      for (int i = 0; i < 4; ++i) fog.color[i] = std::clamp(color[i], 0.f, 1.f);
      return;
    default: return ctx.record_error(GL_INVALID_ENUM, "pname is not a fog parameter");
  }
}

// Integer colour components map [-2^31, 2^31 - 1] onto [-1, 1] (GL 1.5 table 2.9).
float int_color(GLint v) { return static_cast<float>((2.0 * v + 1.0) / 4294967295.0); }

void set_fog_coord(Context& ctx, double c) { ctx.extras.current_fog_coord = static_cast<float>(c); }

}  // namespace

// FOG_COLOR given to a scalar form is (param, 0, 0, 0), as in Mesa.
void Fogf(Context& ctx, GLenum pname, GLfloat param) {
  const GLfloat color[4] = {param, 0, 0, 0};
  set_fog(ctx, pname, param, color);
}
void Fogi(Context& ctx, GLenum pname, GLint param) { Fogf(ctx, pname, GLfloat(param)); }

void Fogfv(Context& ctx, GLenum pname, const GLfloat* params) {
  if (!params) return;
  set_fog(ctx, pname, params[0], pname == GL_FOG_COLOR ? params : nullptr);
}

void Fogiv(Context& ctx, GLenum pname, const GLint* params) {
  if (!params) return;
  float color[4] = {0, 0, 0, 0};
  if (pname == GL_FOG_COLOR)
    for (int i = 0; i < 4; ++i) color[i] = int_color(params[i]);
  set_fog(ctx, pname, params[0], pname == GL_FOG_COLOR ? color : nullptr);
}

void FogCoordf(Context& ctx, GLfloat c) { set_fog_coord(ctx, c); }
void FogCoordd(Context& ctx, GLdouble c) { set_fog_coord(ctx, c); }
void FogCoordfv(Context& ctx, const GLfloat* c) { if (c) set_fog_coord(ctx, c[0]); }
void FogCoorddv(Context& ctx, const GLdouble* c) { if (c) set_fog_coord(ctx, c[0]); }
void FogCoordfEXT(Context& ctx, GLfloat c) { set_fog_coord(ctx, c); }
void FogCoorddEXT(Context& ctx, GLdouble c) { set_fog_coord(ctx, c); }
void FogCoordfvEXT(Context& ctx, const GLfloat* c) { if (c) set_fog_coord(ctx, c[0]); }
void FogCoorddvEXT(Context& ctx, const GLdouble* c) { if (c) set_fog_coord(ctx, c[0]); }

}  // namespace pineda::gl
