// glGetMap and the evaluator values of glGet (GL 1.1 section 6.1.8, table 6.23).
#include <algorithm>
#include <cmath>
#include <vector>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/evaluators/evaluator.h"
#include "state/buffers/pixel_buffer.h"

namespace pineda {

bool query_evaluator(Context& ctx, unsigned pname, GetValues& out) {
  const EvalAttribState& a = ctx.eval.attribs;
  switch (pname) {
    case GL_MAP1_GRID_DOMAIN: out = get_floats({a.grid1.u1, a.grid1.u2}); return true;
    case GL_MAP1_GRID_SEGMENTS: out = get_ints({double(a.grid1.n)}); return true;
    case GL_MAP2_GRID_DOMAIN: out = get_floats({a.grid2.u1, a.grid2.u2, a.grid2.v1, a.grid2.v2}); return true;
    case GL_MAP2_GRID_SEGMENTS: out = get_ints({double(a.grid2.un), double(a.grid2.vn)}); return true;
    default: return false;
  }
}

}  // namespace pineda

namespace pineda::gl {
namespace {

void append_points(const std::vector<glm::dvec4>& points, int components, std::vector<double>& out) {
  for (const glm::dvec4& p : points)
    for (int c = 0; c < components; ++c) out.push_back(p[c]);
}

// The values of `query` for `target`; false (GL_INVALID_ENUM) when either is not one.
bool map_values(const Context& ctx, GLenum target, GLenum query, std::vector<double>& out) {
  if (const int kind = map1_kind(target); kind >= 0) {
    const EvalMap1& m = ctx.eval.map1[kind];
    switch (query) {
      case GL_COEFF: append_points(m.points, map_components(kind), out); return true;
      case GL_ORDER: out = {double(m.order)}; return true;
      case GL_DOMAIN: out = {m.u1, m.u2}; return true;
      default: return false;
    }
  }
  if (const int kind = map2_kind(target); kind >= 0) {
    const EvalMap2& m = ctx.eval.map2[kind];
    switch (query) {
      case GL_COEFF: append_points(m.points, map_components(kind), out); return true;
      case GL_ORDER: out = {double(m.uorder), double(m.vorder)}; return true;
      case GL_DOMAIN: out = {m.u1, m.u2, m.v1, m.v2}; return true;
      default: return false;
    }
  }
  return false;
}

// `client_bytes`: how much memory `v` holds (glGetnMap*vARB).
template <typename T, typename Convert>
void get_map(Context& ctx, GLenum target, GLenum query, T* v, Convert convert, size_t client_bytes = SIZE_MAX) {
  std::vector<double> values;
  if (!map_values(ctx, target, query, values))
    return ctx.record_error(GL_INVALID_ENUM, "target is not a map or query is not GL_COEFF, GL_ORDER or GL_DOMAIN");
  if (values.size() * sizeof(T) > client_bytes)
    return ctx.record_error(GL_INVALID_OPERATION, "the values do not fit in bufSize bytes");
  if (!v) return;
  for (size_t i = 0; i < values.size(); ++i) v[i] = convert(values[i]);
}

// Floating-point state read as integers rounds to the nearest (GL 1.1 6.1.2).
GLint round_to_int(double v) {
  if (std::isnan(v)) return 0;
  return static_cast<GLint>(std::lround(std::clamp(v, -2147483648.0, 2147483647.0)));
}

}  // namespace

void GetMapdv(Context& ctx, GLenum target, GLenum query, GLdouble* v) {
  get_map(ctx, target, query, v, [](double x) { return x; });
}
void GetMapfv(Context& ctx, GLenum target, GLenum query, GLfloat* v) {
  get_map(ctx, target, query, v, [](double x) { return static_cast<GLfloat>(x); });
}
void GetMapiv(Context& ctx, GLenum target, GLenum query, GLint* v) { get_map(ctx, target, query, v, round_to_int); }

void GetnMapdvARB(Context& ctx, GLenum target, GLenum query, GLsizei buf_size, GLdouble* v) {
  get_map(ctx, target, query, v, [](double x) { return x; }, client_buffer_bytes(buf_size));
}
void GetnMapfvARB(Context& ctx, GLenum target, GLenum query, GLsizei buf_size, GLfloat* v) {
  get_map(ctx, target, query, v, [](double x) { return static_cast<GLfloat>(x); }, client_buffer_bytes(buf_size));
}
void GetnMapivARB(Context& ctx, GLenum target, GLenum query, GLsizei buf_size, GLint* v) {
  get_map(ctx, target, query, v, round_to_int, client_buffer_bytes(buf_size));
}

}  // namespace pineda::gl
