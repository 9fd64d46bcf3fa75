// glLight, glLightModel, glMaterial, glColorMaterial and their queries.
#include <algorithm>
#include <cmath>

#include "glapi/gl_entry_points.h"
#include "state/color_material.h"
#include "state/context.h"
#include "state/pixels/pixel_state.h"

namespace pineda::gl {
namespace {

glm::vec4 vec4_of(const GLfloat* v) { return {v[0], v[1], v[2], v[3]}; }

int param_count(GLenum pname) {
  switch (pname) {
    case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_POSITION: case GL_EMISSION:
    case GL_AMBIENT_AND_DIFFUSE: case GL_LIGHT_MODEL_AMBIENT:
      return 4;
    case GL_SPOT_DIRECTION: case GL_COLOR_INDEXES: return 3;
    default: return 1;
  }
}

void light(Context& ctx, GLenum which, GLenum pname, const GLfloat* v) {
  if (which < GL_LIGHT0 || which >= GL_LIGHT0 + raster::kMaxLights)
    return ctx.record_error(GL_INVALID_ENUM, "light is not GL_LIGHTi");
  raster::Light& l = ctx.lighting.lights[which - GL_LIGHT0];
  const glm::mat4 mv(ctx.modelview.top());
  switch (pname) {
    case GL_AMBIENT: l.ambient = vec4_of(v); break;
    case GL_DIFFUSE: l.diffuse = vec4_of(v); break;
    case GL_SPECULAR: l.specular = vec4_of(v); break;
    case GL_POSITION: l.position = mv * vec4_of(v); break;  // stored in eye coordinates
    case GL_SPOT_DIRECTION: l.spot_direction = glm::mat3(mv) * glm::vec3(v[0], v[1], v[2]); break;
    case GL_SPOT_EXPONENT:
      if (v[0] < 0.f || v[0] > 128.f) return ctx.record_error(GL_INVALID_VALUE, "GL_SPOT_EXPONENT is outside [0, 128]");
      l.spot_exponent = v[0];
      break;
    case GL_SPOT_CUTOFF:
      if ((v[0] < 0.f || v[0] > 90.f) && v[0] != 180.f)
        return ctx.record_error(GL_INVALID_VALUE, "GL_SPOT_CUTOFF is outside [0, 90] and not 180");
      l.spot_cutoff = v[0];
      break;
    case GL_CONSTANT_ATTENUATION: case GL_LINEAR_ATTENUATION: case GL_QUADRATIC_ATTENUATION:
      if (v[0] < 0.f) return ctx.record_error(GL_INVALID_VALUE, "the attenuation is negative");
      (pname == GL_CONSTANT_ATTENUATION ? l.constant_attenuation
       : pname == GL_LINEAR_ATTENUATION ? l.linear_attenuation : l.quadratic_attenuation) = v[0];
      break;
    default: ctx.record_error(GL_INVALID_ENUM, "pname is not a light parameter");
  }
}

void light_model(Context& ctx, GLenum pname, const GLfloat* v) {
  switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT: ctx.lighting.model_ambient = vec4_of(v); break;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: ctx.lighting.local_viewer = v[0] != 0.f; break;
    case GL_LIGHT_MODEL_TWO_SIDE: ctx.lighting.two_side = v[0] != 0.f; break;
    case GL_LIGHT_MODEL_COLOR_CONTROL:
      if (v[0] == static_cast<GLfloat>(GL_SEPARATE_SPECULAR_COLOR)) ctx.lighting.separate_specular = true;
      else if (v[0] == static_cast<GLfloat>(GL_SINGLE_COLOR)) ctx.lighting.separate_specular = false;
      else ctx.record_error(GL_INVALID_ENUM, "param is not GL_SEPARATE_SPECULAR_COLOR or GL_SINGLE_COLOR");
      break;
    default: ctx.record_error(GL_INVALID_ENUM, "pname is not a light model parameter");
  }
}

// Inside glBegin/glEnd the vertices so far keep the material they were specified with.
void note_material_before_change(Context& ctx) {
  if (!ctx.in_begin_end || !ctx.immediate_materials.empty()) return;
  ctx.immediate_materials.push_back({0, ctx.lighting.front, ctx.lighting.back});
}

void note_material_after_change(Context& ctx) {
  if (!ctx.in_begin_end) return;
  auto& changes = ctx.immediate_materials;
  // The first entry stays the material at glBegin, which programs read (draw.cpp).
  if (changes.size() > 1 && changes.back().first == ctx.immediate.size())
    changes.back() = {ctx.immediate.size(), ctx.lighting.front, ctx.lighting.back};
  else
    changes.push_back({ctx.immediate.size(), ctx.lighting.front, ctx.lighting.back});
}

void material(Context& ctx, GLenum face, GLenum pname, const GLfloat* v) {
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK)
    return ctx.record_error(GL_INVALID_ENUM, "face is not GL_FRONT, GL_BACK or GL_FRONT_AND_BACK");
  if (pname == GL_SHININESS && (v[0] < 0.f || v[0] > 128.f))
    return ctx.record_error(GL_INVALID_VALUE, "GL_SHININESS is outside [0, 128]");
  if (pname != GL_AMBIENT && pname != GL_DIFFUSE && pname != GL_SPECULAR && pname != GL_EMISSION &&
      pname != GL_AMBIENT_AND_DIFFUSE && pname != GL_SHININESS && pname != GL_COLOR_INDEXES)
    return ctx.record_error(GL_INVALID_ENUM, "pname is not a material parameter");
  note_material_before_change(ctx);
  for (raster::Material* m : {&ctx.lighting.front, &ctx.lighting.back}) {
    if ((m == &ctx.lighting.front && face == GL_BACK) || (m == &ctx.lighting.back && face == GL_FRONT)) continue;
    switch (pname) {
      case GL_AMBIENT: m->ambient = vec4_of(v); break;
      case GL_DIFFUSE: m->diffuse = vec4_of(v); break;
      case GL_SPECULAR: m->specular = vec4_of(v); break;
      case GL_EMISSION: m->emission = vec4_of(v); break;
      case GL_AMBIENT_AND_DIFFUSE: m->ambient = m->diffuse = vec4_of(v); break;
      case GL_SHININESS: m->shininess = v[0]; break;
      case GL_COLOR_INDEXES: m->color_indexes = glm::vec3(v[0], v[1], v[2]); break;
      default: break;                // rejected above
    }
  }
  // A property that follows the colour keeps it (Mesa ignores such Material calls).
  track_color_material(ctx);
  note_material_after_change(ctx);
}

template <typename T>
void to_floats(GLenum pname, const T* params, GLfloat out[4], bool colour) {
  const int n = param_count(pname);
  for (int i = 0; i < n; ++i)
    out[i] = colour ? colour_from_int_param(params[i]) : GLfloat(params[i]);
}

bool is_colour_param(GLenum pname) {
  return pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR || pname == GL_EMISSION ||
         pname == GL_AMBIENT_AND_DIFFUSE || pname == GL_LIGHT_MODEL_AMBIENT;
}

}  // namespace

// The scalar forms take a vector parameter as (param, 0, 0, 0), as Mesa does (the GL 1.x
// spec gives no error for it, and programs and piglit rely on it).
void Lightf(Context& ctx, GLenum l, GLenum pname, GLfloat param) {
  const GLfloat v[4] = {param, 0, 0, 0};
  light(ctx, l, pname, v);
}
void Lighti(Context& ctx, GLenum l, GLenum pname, GLint param) { Lightf(ctx, l, pname, GLfloat(param)); }
void Lightfv(Context& ctx, GLenum l, GLenum pname, const GLfloat* params) {
  if (params) light(ctx, l, pname, params);
}
void Lightiv(Context& ctx, GLenum l, GLenum pname, const GLint* params) {
  if (!params) return;
  GLfloat v[4] = {};
  to_floats(pname, params, v, is_colour_param(pname));
  light(ctx, l, pname, v);
}

void LightModelf(Context& ctx, GLenum pname, GLfloat param) {
  const GLfloat v[4] = {param, 0, 0, 0};
  light_model(ctx, pname, v);
}
void LightModeli(Context& ctx, GLenum pname, GLint param) { LightModelf(ctx, pname, GLfloat(param)); }
void LightModelfv(Context& ctx, GLenum pname, const GLfloat* params) {
  if (params) light_model(ctx, pname, params);
}
void LightModeliv(Context& ctx, GLenum pname, const GLint* params) {
  if (!params) return;
  GLfloat v[4] = {};
  to_floats(pname, params, v, is_colour_param(pname));
  light_model(ctx, pname, v);
}

void Materialf(Context& ctx, GLenum face, GLenum pname, GLfloat param) {
  const GLfloat v[4] = {param, 0, 0, 0};
  material(ctx, face, pname, v);
}
void Materiali(Context& ctx, GLenum face, GLenum pname, GLint param) { Materialf(ctx, face, pname, GLfloat(param)); }
void Materialfv(Context& ctx, GLenum face, GLenum pname, const GLfloat* params) {
  if (params) material(ctx, face, pname, params);
}
void Materialiv(Context& ctx, GLenum face, GLenum pname, const GLint* params) {
  if (!params) return;
  GLfloat v[4] = {};
  to_floats(pname, params, v, is_colour_param(pname));
  material(ctx, face, pname, v);
}

void ColorMaterial(Context& ctx, GLenum face, GLenum mode) {
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK)
    return ctx.record_error(GL_INVALID_ENUM, "face is not GL_FRONT, GL_BACK or GL_FRONT_AND_BACK");
  if (mode != GL_EMISSION && mode != GL_AMBIENT && mode != GL_DIFFUSE && mode != GL_SPECULAR &&
      mode != GL_AMBIENT_AND_DIFFUSE)
    return ctx.record_error(GL_INVALID_ENUM, "mode is not a material colour");
  ctx.color_material_face = face;
  ctx.color_material_mode = mode;
  raster::ColorMaterial& cm = ctx.lighting.color_material;
  cm.front = face != GL_BACK;
  cm.back = face != GL_FRONT;
  cm.ambient = mode == GL_AMBIENT || mode == GL_AMBIENT_AND_DIFFUSE;
  cm.diffuse = mode == GL_DIFFUSE || mode == GL_AMBIENT_AND_DIFFUSE;
  cm.specular = mode == GL_SPECULAR;
  cm.emission = mode == GL_EMISSION;
  track_color_material(ctx);
}

namespace {

// The value of a light parameter; false (with GL_INVALID_ENUM recorded) when there is none.
bool light_value(Context& ctx, GLenum which, GLenum pname, glm::vec4& v) {
  if (which < GL_LIGHT0 || which >= GL_LIGHT0 + raster::kMaxLights) {
    ctx.record_error(GL_INVALID_ENUM, "light is not GL_LIGHTi");
    return false;
  }
  const raster::Light& l = ctx.lighting.lights[which - GL_LIGHT0];
  v = glm::vec4(0);
  switch (pname) {
    case GL_AMBIENT: v = l.ambient; break;
    case GL_DIFFUSE: v = l.diffuse; break;
    case GL_SPECULAR: v = l.specular; break;
    case GL_POSITION: v = l.position; break;
    case GL_SPOT_DIRECTION: v = glm::vec4(l.spot_direction, 0); break;
    case GL_SPOT_EXPONENT: v.x = l.spot_exponent; break;
    case GL_SPOT_CUTOFF: v.x = l.spot_cutoff; break;
    case GL_CONSTANT_ATTENUATION: v.x = l.constant_attenuation; break;
    case GL_LINEAR_ATTENUATION: v.x = l.linear_attenuation; break;
    case GL_QUADRATIC_ATTENUATION: v.x = l.quadratic_attenuation; break;
    default: ctx.record_error(GL_INVALID_ENUM, "pname is not a light parameter"); return false;
  }
  return true;
}

// The value of a material parameter; false (with GL_INVALID_ENUM recorded) when there is none.
bool material_value(Context& ctx, GLenum face, GLenum pname, glm::vec4& v) {
  if (face != GL_FRONT && face != GL_BACK) {
    ctx.record_error(GL_INVALID_ENUM, "face is not GL_FRONT or GL_BACK");
    return false;
  }
  const raster::Material& m = face == GL_FRONT ? ctx.lighting.front : ctx.lighting.back;
  v = glm::vec4(0);
  switch (pname) {
    case GL_AMBIENT: v = m.ambient; break;
    case GL_DIFFUSE: v = m.diffuse; break;
    case GL_SPECULAR: v = m.specular; break;
    case GL_EMISSION: v = m.emission; break;
    case GL_SHININESS: v.x = m.shininess; break;
    case GL_COLOR_INDEXES: v = glm::vec4(m.color_indexes, 0.f); break;
    default: ctx.record_error(GL_INVALID_ENUM, "pname is not a material parameter"); return false;
  }
  return true;
}

// GL 1.1 spec 6.1.2: colours map [-1, 1] onto the integer range; other values round.
void to_ints(GLenum pname, const glm::vec4& v, GLint* out) {
  const bool colour = is_colour_param(pname);
  for (int i = 0; i < param_count(pname); ++i)
    out[i] = colour ? colour_int_param(v[i]) : round_int_param(v[i]);
}

}  // namespace

void GetLightfv(Context& ctx, GLenum which, GLenum pname, GLfloat* params) {
  glm::vec4 v;
  if (!light_value(ctx, which, pname, v) || !params) return;
  for (int i = 0; i < param_count(pname); ++i) params[i] = v[i];
}

void GetLightiv(Context& ctx, GLenum which, GLenum pname, GLint* params) {
  glm::vec4 v;
  if (light_value(ctx, which, pname, v) && params) to_ints(pname, v, params);
}

void GetMaterialfv(Context& ctx, GLenum face, GLenum pname, GLfloat* params) {
  glm::vec4 v;
  if (!material_value(ctx, face, pname, v) || !params) return;
  for (int i = 0; i < param_count(pname); ++i) params[i] = v[i];
}

void GetMaterialiv(Context& ctx, GLenum face, GLenum pname, GLint* params) {
  glm::vec4 v;
  if (material_value(ctx, face, pname, v) && params) to_ints(pname, v, params);
}

}  // namespace pineda::gl

