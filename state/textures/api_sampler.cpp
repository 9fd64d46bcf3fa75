// GL_ARB_sampler_objects: sampler object names, bindings to texture units and parameters
// (textures/sampler_object.h). As in Mesa, glGenSamplers creates the objects at once.
#include <algorithm>
#include <cmath>
#include <memory>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/pixels/pixel_state.h"
#include "state/textures/sampler_object.h"
#include "state/textures/sampling_params.h"

namespace pineda::gl {
namespace {

constexpr const char* kNotASampler = "sampler is not the name of a sampler object";

SamplerObject* find_sampler(Context& ctx, GLuint name) {
  const auto it = ctx.samplers.find(name);
  return name != 0 && it != ctx.samplers.end() ? it->second.get() : nullptr;
}

// A parameter from the vector forms: v holds four values for the border colour, one otherwise.
void sampler_parameter(Context& ctx, GLuint sampler, GLenum pname, const GLfloat* v) {
  SamplerObject* object = find_sampler(ctx, sampler);
  if (!object) return ctx.record_error(GL_INVALID_OPERATION, kNotASampler);
  if (!is_sampling_param(pname)) return ctx.record_error(GL_INVALID_ENUM, "pname is not a sampler parameter");
  if (const GlError error = set_sampling_param(object->params, pname, v); error != GL_NO_ERROR) ctx.record_error(error);
}

void sampler_parameter_scalar(Context& ctx, GLuint sampler, GLenum pname, GLfloat param) {
  if (pname == GL_TEXTURE_BORDER_COLOR && find_sampler(ctx, sampler))
    return ctx.record_error(GL_INVALID_ENUM, "the border colour takes a vector: use glSamplerParameterfv or iv");
  const GLfloat v[4] = {param, 0, 0, 0};
  sampler_parameter(ctx, sampler, pname, v);
}

// `normalized`: how integer border colours are read (the iv form maps [-2^31, 2^31 - 1] onto
// [-1, 1]; the I forms take the integers as they are).
template <typename Int>
void sampler_parameter_ints(Context& ctx, GLuint sampler, GLenum pname, const Int* params, bool normalized) {
  if (!params) return;
  GLfloat v[4] = {GLfloat(params[0]), 0, 0, 0};
  if (pname == GL_TEXTURE_BORDER_COLOR)
    for (int i = 0; i < 4; ++i) v[i] = normalized ? colour_from_int_param(GLint(params[i])) : GLfloat(params[i]);
  sampler_parameter(ctx, sampler, pname, v);
}

// The parameter's values, or false after recording the error.
bool get_sampler_parameter(Context& ctx, GLuint sampler, GLenum pname, float out[4], int& count, bool& colour) {
  const SamplerObject* object = find_sampler(ctx, sampler);
  if (!object) {
    ctx.record_error(GL_INVALID_OPERATION, kNotASampler);
    return false;
  }
  if (!get_sampling_param(object->params, pname, out, count, colour)) {
    ctx.record_error(GL_INVALID_ENUM, "pname is not a sampler parameter");
    return false;
  }
  return true;
}

}  // namespace

void GenSamplers(Context& ctx, GLsizei count, GLuint* samplers) {
  if (count < 0) return ctx.record_error(GL_INVALID_VALUE, "count is negative");
  if (!samplers) return;
  GLuint next = 1;
  for (GLsizei i = 0; i < count; ++i) {
    while (ctx.samplers.count(next)) ++next;
    ctx.samplers.emplace(next, std::make_shared<SamplerObject>());
    samplers[i] = next;
  }
}

// A deleted sampler bound to units of this context is unbound from them; other contexts of
// the group keep theirs bound until they bind another.
void DeleteSamplers(Context& ctx, GLsizei count, const GLuint* samplers) {
  if (count < 0) return ctx.record_error(GL_INVALID_VALUE, "count is negative");
  if (!samplers) return;
  for (GLsizei i = 0; i < count; ++i) {
    const GLuint name = samplers[i];
    const auto it = ctx.samplers.find(name);
    if (name == 0 || it == ctx.samplers.end()) continue;
    for (TextureUnitState& unit : ctx.texture_units)
      if (unit.sampler == it->second) {
        unit.sampler.reset();
        unit.sampler_name = 0;
      }
    ctx.samplers.erase(it);
  }
}

GLboolean IsSampler(Context& ctx, GLuint sampler) { return find_sampler(ctx, sampler) ? GL_TRUE : GL_FALSE; }

void BindSampler(Context& ctx, GLuint unit, GLuint sampler) {
  if (unit >= GLuint(raster::kMaxTextureImageUnits))
    return ctx.record_error(GL_INVALID_VALUE, "unit is not below GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS");
  std::shared_ptr<SamplerObject> object;
  if (sampler != 0) {
    const auto it = ctx.samplers.find(sampler);
    if (it == ctx.samplers.end()) return ctx.record_error(GL_INVALID_OPERATION, kNotASampler);
    object = it->second;
  }
  TextureUnitState& bound = ctx.texture_units[unit];
  bound.sampler = std::move(object);
  bound.sampler_name = sampler;
}

void SamplerParameterf(Context& ctx, GLuint sampler, GLenum pname, GLfloat param) {
  sampler_parameter_scalar(ctx, sampler, pname, param);
}
void SamplerParameteri(Context& ctx, GLuint sampler, GLenum pname, GLint param) {
  sampler_parameter_scalar(ctx, sampler, pname, GLfloat(param));
}
void SamplerParameterfv(Context& ctx, GLuint sampler, GLenum pname, const GLfloat* params) {
  if (params) sampler_parameter(ctx, sampler, pname, params);
}
void SamplerParameteriv(Context& ctx, GLuint sampler, GLenum pname, const GLint* params) {
  sampler_parameter_ints(ctx, sampler, pname, params, true);
}
void SamplerParameterIiv(Context& ctx, GLuint sampler, GLenum pname, const GLint* params) {
  sampler_parameter_ints(ctx, sampler, pname, params, false);
}
void SamplerParameterIuiv(Context& ctx, GLuint sampler, GLenum pname, const GLuint* params) {
  sampler_parameter_ints(ctx, sampler, pname, params, false);
}

void GetSamplerParameterfv(Context& ctx, GLuint sampler, GLenum pname, GLfloat* params) {
  float v[4];
  int count;
  bool colour;
  if (get_sampler_parameter(ctx, sampler, pname, v, count, colour) && params) std::copy(v, v + count, params);
}
void GetSamplerParameteriv(Context& ctx, GLuint sampler, GLenum pname, GLint* params) {
  float v[4];
  int count;
  bool colour;
  if (!get_sampler_parameter(ctx, sampler, pname, v, count, colour) || !params) return;
  for (int i = 0; i < count; ++i) params[i] = colour ? colour_int_param(v[i]) : truncate_int_param(v[i]);
}
void GetSamplerParameterIiv(Context& ctx, GLuint sampler, GLenum pname, GLint* params) {
  float v[4];
  int count;
  bool colour;
  if (!get_sampler_parameter(ctx, sampler, pname, v, count, colour) || !params) return;
  for (int i = 0; i < count; ++i) params[i] = truncate_int_param(v[i]);
}
void GetSamplerParameterIuiv(Context& ctx, GLuint sampler, GLenum pname, GLuint* params) {
  float v[4];
  int count;
  bool colour;
  if (!get_sampler_parameter(ctx, sampler, pname, v, count, colour) || !params) return;
  for (int i = 0; i < count; ++i) params[i] = GLuint(std::max(truncate_int_param(v[i]), 0));
}

}  // namespace pineda::gl
