// glUniform* and glGetUniform* (GL 2.0 2.15.3, 6.1.14; GL 2.1's non-square matrices): values
// go into the program in use; its draws copy them.
#include <algorithm>
#include <cmath>
#include <vector>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/buffers/pixel_buffer.h"
#include "state/programs/program_lookup.h"
#include "state/programs/sampler_units.h"

namespace pineda::gl {
namespace {

enum class Source { Float, Int };

bool is_sampler(shader::BaseType b) { return b >= shader::BaseType::Sampler1D; }

// The uniform element at `location` of the program in use, after GL's checks; null when the
// call does nothing (an error is recorded unless the location is -1).
const shader::Uniform* target(Context& ctx, GLint location, GLsizei count, LinkedProgram*& exec, int& element) {
  exec = ctx.programs.current_exec.get();
  if (!exec) {
    ctx.record_error(GL_INVALID_OPERATION, "no program is current");
    return nullptr;
  }
  if (count < 0) {
    ctx.record_error(GL_INVALID_VALUE, "count is negative");
    return nullptr;
  }
  if (location == -1) return nullptr;
  if (location < 0 || static_cast<size_t>(location) >= exec->uniforms.locations.size()) {
    ctx.record_error(GL_INVALID_OPERATION, "location is not a uniform location of the current program");
    return nullptr;
  }
  const UniformLocation& l = exec->uniforms.locations[static_cast<size_t>(location)];
  const shader::Uniform& u = exec->uniforms.active[static_cast<size_t>(l.uniform)];
  if (count > 1 && u.array_size <= 1) {
    ctx.record_error(GL_INVALID_OPERATION, "count is above 1 and the uniform is not an array");
    return nullptr;
  }
  element = l.element;
  return &u;
}

// Elements `count` from `element` on, cut at the end of the array.
int elements_to_write(const shader::Uniform& u, int element, GLsizei count) {
  return std::max(0, std::min<int>(count, std::max(u.array_size, 1) - element));
}

template <typename T>
void set_vector(Context& ctx, GLint location, GLsizei count, int components, Source source, const T* v) {
  LinkedProgram* exec;
  int element;
  const shader::Uniform* u = target(ctx, location, count, exec, element);
  if (!u) return;
  const shader::Type& t = u->type;
  bool ok = t.columns == 1 && t.rows == components;
  if (t.base == shader::BaseType::Float) ok &= source == Source::Float;
  else if (t.base == shader::BaseType::Int) ok &= source == Source::Int;
  else if (is_sampler(t.base)) ok &= source == Source::Int && components == 1;
  if (!ok) return ctx.record_error(GL_INVALID_OPERATION, "the call's type or size does not match the uniform's");
  const int n = elements_to_write(*u, element, count);
  if (n > 0 && !v) return;
  if (is_sampler(t.base))
    for (int i = 0; i < n; ++i)
      if (v[i] < 0 || v[i] >= raster::kMaxTextureImageUnits)
        return ctx.record_error(GL_INVALID_VALUE, "a sampler value is not a texture image unit");
  for (int e = 0; e < n; ++e) {
    const size_t at = static_cast<size_t>(u->offset + (element + e) * u->stride);
    if (at + components > exec->values.size()) return;
    for (int c = 0; c < components; ++c) {
      const T x = v[e * components + c];
      exec->values[at + c] = t.base == shader::BaseType::Bool ? (x != T(0) ? 1.f : 0.f) : static_cast<float>(x);
    }
  }
  if (is_sampler(t.base)) exec->sampler_conflict = sampler_unit_conflict(*exec);
}

void set_matrix(Context& ctx, GLint location, GLsizei count, int columns, int rows, GLboolean transpose,
                const GLfloat* v) {
  LinkedProgram* exec;
  int element;
  const shader::Uniform* u = target(ctx, location, count, exec, element);
  if (!u) return;
  const shader::Type& t = u->type;
  if (t.base != shader::BaseType::Float || t.columns != columns || t.rows != rows)
    return ctx.record_error(GL_INVALID_OPERATION, "the uniform is not a matrix of the call's size");
  if (ctx.attribs().gles && transpose)
    return ctx.record_error(GL_INVALID_VALUE, "transpose is not GL_FALSE in OpenGL ES");
  const int n = elements_to_write(*u, element, count);
  if (n > 0 && !v) return;
  const int size = columns * rows;
  for (int e = 0; e < n; ++e) {
    const size_t at = static_cast<size_t>(u->offset + (element + e) * u->stride);
    if (at + size > exec->values.size()) return;
    const GLfloat* m = v + e * size;
    for (int c = 0; c < columns; ++c)
      for (int r = 0; r < rows; ++r) exec->values[at + c * rows + r] = transpose ? m[r * columns + c] : m[c * rows + r];
  }
}

// The element at `location` of a linked program, for glGetUniform*.
const shader::Uniform* query_target(Context& ctx, GLuint program, GLint location, const LinkedProgram*& exec,
                                    int& element) {
  ProgramObject* p = program_or_error(ctx, program);
  if (!p) return nullptr;
  exec = p->executable.get();
  if (!p->link_status || !exec) {
    ctx.record_error(GL_INVALID_OPERATION, "the program is not linked");
    return nullptr;
  }
  if (location < 0 || static_cast<size_t>(location) >= exec->uniforms.locations.size()) {
    ctx.record_error(GL_INVALID_OPERATION, "location is not a uniform location of the program");
    return nullptr;
  }
  const UniformLocation& l = exec->uniforms.locations[static_cast<size_t>(location)];
  element = l.element;
  return &exec->uniforms.active[static_cast<size_t>(l.uniform)];
}

// `client_bytes`: how much memory `params` holds (glGetnUniform*vARB).
template <typename T, typename Convert>
void get_uniform(Context& ctx, GLuint program, GLint location, T* params, Convert convert,
                 size_t client_bytes = SIZE_MAX) {
  const LinkedProgram* exec;
  int element;
  const shader::Uniform* u = query_target(ctx, program, location, exec, element);
  if (!u) return;
  const int n = u->type.components();
  if (size_t(n) * sizeof(T) > client_bytes)
    return ctx.record_error(GL_INVALID_OPERATION, "the value does not fit in bufSize bytes");
  if (!params) return;
  const size_t at = static_cast<size_t>(u->offset + element * u->stride);
  for (int i = 0; i < n; ++i) params[i] = at + i < exec->values.size() ? convert(exec->values[at + i]) : T(0);
}

// Uniform*v in a display list: the values are copied now (GL 1.1 5.4).
template <typename T, typename Call>
void compile_vector(Context& ctx, GLsizei count, int components, const T* v, Call call) {
  std::vector<T> copy;
  if (v && count > 0) copy.assign(v, v + static_cast<size_t>(count) * components);
  ctx.record_list_command([copy = std::move(copy), call](Context& list_ctx) {
    if (list_ctx.inside_begin_end())
      return list_ctx.record_error(GL_INVALID_OPERATION, "called between glBegin and glEnd");
    call(list_ctx, copy.empty() ? nullptr : copy.data());
  });
}

GLint uniform_as_int(float v) {
  if (!(v == v)) return GLint(0);
  return static_cast<GLint>(std::clamp<double>(std::nearbyint(v), -2147483648.0, 2147483647.0));
}

}  // namespace

#define PINEDA_UNIFORM(N, suffix, T, source)                                                              \
  void Uniform##N##suffix##v(Context& ctx, GLint location, GLsizei count, const T* value) {                \
    set_vector(ctx, location, count, N, source, value);                                                   \
  }                                                                                                       \
  void compile_Uniform##N##suffix##v(Context& ctx, GLint location, GLsizei count, const T* value) {        \
    compile_vector(ctx, count, N, value,                                                                  \
                   [location, count](Context& c, const T* v) { Uniform##N##suffix##v(c, location, count, v); }); \
  }
PINEDA_UNIFORM(1, f, GLfloat, Source::Float)
PINEDA_UNIFORM(2, f, GLfloat, Source::Float)
PINEDA_UNIFORM(3, f, GLfloat, Source::Float)
PINEDA_UNIFORM(4, f, GLfloat, Source::Float)
PINEDA_UNIFORM(1, i, GLint, Source::Int)
PINEDA_UNIFORM(2, i, GLint, Source::Int)
PINEDA_UNIFORM(3, i, GLint, Source::Int)
PINEDA_UNIFORM(4, i, GLint, Source::Int)
#undef PINEDA_UNIFORM

void Uniform1f(Context& ctx, GLint location, GLfloat x) {
  const GLfloat v[] = {x};
  set_vector(ctx, location, 1, 1, Source::Float, v);
}
void Uniform2f(Context& ctx, GLint location, GLfloat x, GLfloat y) {
  const GLfloat v[] = {x, y};
  set_vector(ctx, location, 1, 2, Source::Float, v);
}
void Uniform3f(Context& ctx, GLint location, GLfloat x, GLfloat y, GLfloat z) {
  const GLfloat v[] = {x, y, z};
  set_vector(ctx, location, 1, 3, Source::Float, v);
}
void Uniform4f(Context& ctx, GLint location, GLfloat x, GLfloat y, GLfloat z, GLfloat w) {
  const GLfloat v[] = {x, y, z, w};
  set_vector(ctx, location, 1, 4, Source::Float, v);
}
void Uniform1i(Context& ctx, GLint location, GLint x) {
  const GLint v[] = {x};
  set_vector(ctx, location, 1, 1, Source::Int, v);
}
void Uniform2i(Context& ctx, GLint location, GLint x, GLint y) {
  const GLint v[] = {x, y};
  set_vector(ctx, location, 1, 2, Source::Int, v);
}
void Uniform3i(Context& ctx, GLint location, GLint x, GLint y, GLint z) {
  const GLint v[] = {x, y, z};
  set_vector(ctx, location, 1, 3, Source::Int, v);
}
void Uniform4i(Context& ctx, GLint location, GLint x, GLint y, GLint z, GLint w) {
  const GLint v[] = {x, y, z, w};
  set_vector(ctx, location, 1, 4, Source::Int, v);
}

#define PINEDA_UNIFORM_MATRIX(name, C, R)                                                                     \
  void UniformMatrix##name##fv(Context& ctx, GLint location, GLsizei count, GLboolean transpose,              \
                               const GLfloat* value) {                                                       \
    set_matrix(ctx, location, count, C, R, transpose, value);                                                 \
  }                                                                                                           \
  void compile_UniformMatrix##name##fv(Context& ctx, GLint location, GLsizei count, GLboolean transpose,      \
                                       const GLfloat* value) {                                               \
    compile_vector(ctx, count, C * R, value, [location, count, transpose](Context& c, const GLfloat* v) {     \
      UniformMatrix##name##fv(c, location, count, transpose, v);                                              \
    });                                                                                                       \
  }
PINEDA_UNIFORM_MATRIX(2, 2, 2)
PINEDA_UNIFORM_MATRIX(3, 3, 3)
PINEDA_UNIFORM_MATRIX(4, 4, 4)
PINEDA_UNIFORM_MATRIX(2x3, 2, 3)
PINEDA_UNIFORM_MATRIX(3x2, 3, 2)
PINEDA_UNIFORM_MATRIX(2x4, 2, 4)
PINEDA_UNIFORM_MATRIX(4x2, 4, 2)
PINEDA_UNIFORM_MATRIX(3x4, 3, 4)
PINEDA_UNIFORM_MATRIX(4x3, 4, 3)
#undef PINEDA_UNIFORM_MATRIX

void GetUniformfv(Context& ctx, GLuint program, GLint location, GLfloat* params) {
  get_uniform(ctx, program, location, params, [](float v) { return v; });
}

void GetUniformiv(Context& ctx, GLuint program, GLint location, GLint* params) {
  get_uniform(ctx, program, location, params, uniform_as_int);
}

void GetnUniformfvARB(Context& ctx, GLuint program, GLint location, GLsizei buf_size, GLfloat* params) {
  get_uniform(ctx, program, location, params, [](float v) { return v; }, client_buffer_bytes(buf_size));
}

void GetnUniformivARB(Context& ctx, GLuint program, GLint location, GLsizei buf_size, GLint* params) {
  get_uniform(ctx, program, location, params, uniform_as_int, client_buffer_bytes(buf_size));
}

// GL_KHR_robustness's: Pineda has no unsigned uniforms; the others convert as to int, then
// keep their bits (as Mesa).
void GetnUniformuiv(Context& ctx, GLuint program, GLint location, GLsizei buf_size, GLuint* params) {
  get_uniform(ctx, program, location, params, [](float v) { return static_cast<GLuint>(uniform_as_int(v)); },
              client_buffer_bytes(buf_size));
}

}  // namespace pineda::gl
