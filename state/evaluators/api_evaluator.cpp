// Evaluator commands (GL 1.1 section 5.1): glMap1/glMap2 (compiled with a copy of their
// control points), glMapGrid, glEvalCoord, glEvalPoint and glEvalMesh.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/evaluators/evaluator.h"
#include "state/evaluators/evaluator_vertex.h"

namespace pineda::gl {
namespace {

// An evaluated mesh is bounded so that bad arguments cannot exhaust memory or time:
// a larger one records GL_OUT_OF_MEMORY and draws nothing.
constexpr int64_t kMaxMeshPrimitiveVertices = int64_t(1) << 20;
constexpr int64_t kMaxMeshVertices = int64_t(1) << 24;

// glMap's argument errors, in Mesa's order; the active texture unit is checked when it runs.
GlError map1_error(GLenum target, double u1, double u2, GLint stride, GLint order, const void* points) {
  if (u1 == u2) return {GL_INVALID_VALUE, "u1 equals u2"};
  if (order < 1 || order > kMaxEvalOrder) return {GL_INVALID_VALUE, "order is less than 1 or above GL_MAX_EVAL_ORDER"};
  if (!points) return {GL_INVALID_VALUE, "points is null"};
  const int kind = map1_kind(target);
  if (kind < 0) return {GL_INVALID_ENUM, "target is not a one-dimensional map"};
  if (stride < map_components(kind)) return {GL_INVALID_VALUE, "stride is less than the target's components"};
  return GL_NO_ERROR;
}

GlError map2_error(GLenum target, double u1, double u2, GLint ustride, GLint uorder, double v1, double v2,
                   GLint vstride, GLint vorder, const void* points) {
  if (u1 == u2 || v1 == v2) return {GL_INVALID_VALUE, "u1 equals u2 or v1 equals v2"};
  if (uorder < 1 || uorder > kMaxEvalOrder || vorder < 1 || vorder > kMaxEvalOrder)
    return {GL_INVALID_VALUE, "uorder or vorder is less than 1 or above GL_MAX_EVAL_ORDER"};
  if (!points) return {GL_INVALID_VALUE, "points is null"};
  const int kind = map2_kind(target);
  if (kind < 0) return {GL_INVALID_ENUM, "target is not a two-dimensional map"};
  const int k = map_components(kind);
  if (ustride < k || vstride < k) return {GL_INVALID_VALUE, "ustride or vstride is less than the target's components"};
  return GL_NO_ERROR;
}

// Control point i, j of the application's array (j = 0 for glMap1), copied now.
template <typename T>
std::vector<glm::dvec4> copy_points(const T* points, int components, GLint ustride, GLint uorder, GLint vstride,
                                    GLint vorder) {
  std::vector<glm::dvec4> out(size_t(uorder) * vorder, glm::dvec4(0, 0, 0, 1));
  for (GLint i = 0; i < uorder; ++i)
    for (GLint j = 0; j < vorder; ++j) {
      const T* p = points + ptrdiff_t(i) * ustride + ptrdiff_t(j) * vstride;
      for (int c = 0; c < components; ++c) out[size_t(i) * vorder + j][c] = static_cast<double>(p[c]);
    }
  return out;
}

// GL 1.3 (ARB_multitexture): maps are defined only while texture unit 0 is active.
bool map_allowed(Context& ctx) {
  if (ctx.active_texture == 0) return true;
  ctx.record_error(GL_INVALID_OPERATION, "the active texture unit is not unit 0");
  return false;
}

template <typename T>
void map1(Context& ctx, GLenum target, double u1, double u2, GLint stride, GLint order, const T* points) {
  if (const GlError error = map1_error(target, u1, u2, stride, order, points)) return ctx.record_error(error);
  if (!map_allowed(ctx)) return;
  const int kind = map1_kind(target);
  ctx.eval.map1[kind] = {order, u1, u2, copy_points(points, map_components(kind), stride, order, 0, 1)};
}

template <typename T>
void compile_map1(Context& ctx, GLenum target, double u1, double u2, GLint stride, GLint order, const T* points) {
  const GlError error = map1_error(target, u1, u2, stride, order, points);
  EvalMap1 map;
  if (!error) map = {order, u1, u2, copy_points(points, map_components(map1_kind(target)), stride, order, 0, 1)};
  ctx.record_list_command([error, target, map = std::move(map)](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION, "called between glBegin and glEnd");
    if (error) return c.record_error(error);
    if (map_allowed(c)) c.eval.map1[map1_kind(target)] = map;
  });
}

template <typename T>
EvalMap2 make_map2(GLenum target, double u1, double u2, GLint ustride, GLint uorder, double v1, double v2,
                   GLint vstride, GLint vorder, const T* points) {
  const int k = map_components(map2_kind(target));
  return {uorder, vorder, u1, u2, v1, v2, copy_points(points, k, ustride, uorder, vstride, vorder)};
}

template <typename T>
void map2(Context& ctx, GLenum target, double u1, double u2, GLint ustride, GLint uorder, double v1, double v2,
          GLint vstride, GLint vorder, const T* points) {
  if (const GlError error = map2_error(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points))
    return ctx.record_error(error);
  if (!map_allowed(ctx)) return;
  ctx.eval.map2[map2_kind(target)] = make_map2(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}

template <typename T>
void compile_map2(Context& ctx, GLenum target, double u1, double u2, GLint ustride, GLint uorder, double v1,
                  double v2, GLint vstride, GLint vorder, const T* points) {
  const GlError error = map2_error(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
  EvalMap2 map;
  if (!error) map = make_map2(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
  ctx.record_list_command([error, target, map = std::move(map)](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION, "called between glBegin and glEnd");
    if (error) return c.record_error(error);
    if (map_allowed(c)) c.eval.map2[map2_kind(target)] = map;
  });
}

void map_grid1(Context& ctx, GLint un, double u1, double u2) {
  if (un < 1) return ctx.record_error(GL_INVALID_VALUE, "un is less than 1");
  ctx.eval.attribs.grid1 = {un, u1, u2};
}

void map_grid2(Context& ctx, GLint un, double u1, double u2, GLint vn, double v1, double v2) {
  if (un < 1 || vn < 1) return ctx.record_error(GL_INVALID_VALUE, "un or vn is less than 1");
  ctx.eval.attribs.grid2 = {un, vn, u1, u2, v1, v2};
}

double grid_u1(const Context& ctx, GLint i) {
  const EvalGrid1& g = ctx.eval.attribs.grid1;
  return grid_coordinate(i, g.n, g.u1, g.u2);
}

void eval_point2(Context& ctx, GLint i, GLint j) {
  const EvalGrid2& g = ctx.eval.attribs.grid2;
  eval_coord2(ctx, grid_coordinate(i, g.un, g.u1, g.u2), grid_coordinate(j, g.vn, g.v1, g.v2));
}

bool vertex_map_enabled(const std::array<bool, kEvalMapKinds>& enabled) {
  return enabled[kEvalVertex3] || enabled[kEvalVertex4];
}

bool mesh_fits(Context& ctx, int64_t longest_primitive, int64_t total) {
  if (longest_primitive <= kMaxMeshPrimitiveVertices && total <= kMaxMeshVertices) return true;
  ctx.record_error(GL_OUT_OF_MEMORY, "the mesh has too many vertices");
  return false;
}

}  // namespace

void Map1f(Context& ctx, GLenum target, GLfloat u1, GLfloat u2, GLint stride, GLint order, const GLfloat* points) {
  map1(ctx, target, u1, u2, stride, order, points);
}
void Map1d(Context& ctx, GLenum target, GLdouble u1, GLdouble u2, GLint stride, GLint order, const GLdouble* points) {
  map1(ctx, target, u1, u2, stride, order, points);
}
void compile_Map1f(Context& ctx, GLenum target, GLfloat u1, GLfloat u2, GLint stride, GLint order,
                   const GLfloat* points) {
  compile_map1(ctx, target, u1, u2, stride, order, points);
}
void compile_Map1d(Context& ctx, GLenum target, GLdouble u1, GLdouble u2, GLint stride, GLint order,
                   const GLdouble* points) {
  compile_map1(ctx, target, u1, u2, stride, order, points);
}

void Map2f(Context& ctx, GLenum target, GLfloat u1, GLfloat u2, GLint ustride, GLint uorder, GLfloat v1, GLfloat v2,
           GLint vstride, GLint vorder, const GLfloat* points) {
  map2(ctx, target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}
void Map2d(Context& ctx, GLenum target, GLdouble u1, GLdouble u2, GLint ustride, GLint uorder, GLdouble v1,
           GLdouble v2, GLint vstride, GLint vorder, const GLdouble* points) {
  map2(ctx, target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}
void compile_Map2f(Context& ctx, GLenum target, GLfloat u1, GLfloat u2, GLint ustride, GLint uorder, GLfloat v1,
                   GLfloat v2, GLint vstride, GLint vorder, const GLfloat* points) {
  compile_map2(ctx, target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}
void compile_Map2d(Context& ctx, GLenum target, GLdouble u1, GLdouble u2, GLint ustride, GLint uorder,
                   GLdouble v1, GLdouble v2, GLint vstride, GLint vorder, const GLdouble* points) {
  compile_map2(ctx, target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}

void MapGrid1f(Context& ctx, GLint un, GLfloat u1, GLfloat u2) { map_grid1(ctx, un, u1, u2); }
void MapGrid1d(Context& ctx, GLint un, GLdouble u1, GLdouble u2) { map_grid1(ctx, un, u1, u2); }
void MapGrid2f(Context& ctx, GLint un, GLfloat u1, GLfloat u2, GLint vn, GLfloat v1, GLfloat v2) {
  map_grid2(ctx, un, u1, u2, vn, v1, v2);
}
void MapGrid2d(Context& ctx, GLint un, GLdouble u1, GLdouble u2, GLint vn, GLdouble v1, GLdouble v2) {
  map_grid2(ctx, un, u1, u2, vn, v1, v2);
}

void EvalCoord1f(Context& ctx, GLfloat u) { eval_coord1(ctx, u); }
void EvalCoord1d(Context& ctx, GLdouble u) { eval_coord1(ctx, u); }
void EvalCoord1fv(Context& ctx, const GLfloat* u) {
  if (u) eval_coord1(ctx, u[0]);
}
void EvalCoord1dv(Context& ctx, const GLdouble* u) {
  if (u) eval_coord1(ctx, u[0]);
}
void EvalCoord2f(Context& ctx, GLfloat u, GLfloat v) { eval_coord2(ctx, u, v); }
void EvalCoord2d(Context& ctx, GLdouble u, GLdouble v) { eval_coord2(ctx, u, v); }
void EvalCoord2fv(Context& ctx, const GLfloat* u) {
  if (u) eval_coord2(ctx, u[0], u[1]);
}
void EvalCoord2dv(Context& ctx, const GLdouble* u) {
  if (u) eval_coord2(ctx, u[0], u[1]);
}

void EvalPoint1(Context& ctx, GLint i) { eval_coord1(ctx, grid_u1(ctx, i)); }
void EvalPoint2(Context& ctx, GLint i, GLint j) { eval_point2(ctx, i, j); }

// GL 1.1 5.1: Begin(POINTS or LINE_STRIP), EvalPoint1 for i1..i2, End.
void EvalMesh1(Context& ctx, GLenum mode, GLint i1, GLint i2) {
  if (mode != GL_POINT && mode != GL_LINE) return ctx.record_error(GL_INVALID_ENUM, "mode is not GL_POINT or GL_LINE");
  if (!vertex_map_enabled(ctx.eval.attribs.map1_enabled) || i2 < i1) return;
  const int64_t count = int64_t(i2) - i1 + 1;
  if (!mesh_fits(ctx, count, count)) return;
  Begin(ctx, mode == GL_POINT ? GL_POINTS : GL_LINE_STRIP);
  for (int64_t i = i1; i <= i2; ++i) eval_coord1(ctx, grid_u1(ctx, GLint(i)));
  End(ctx);
}

// GL 1.1 5.1: FILL is a QUAD_STRIP per row j (vertices (i, j), (i, j + 1)); LINE a LINE_STRIP
// per row and per column; POINT one POINTS primitive, row by row.
void EvalMesh2(Context& ctx, GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2) {
  if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL)
    return ctx.record_error(GL_INVALID_ENUM, "mode is not GL_POINT, GL_LINE or GL_FILL");
  if (!vertex_map_enabled(ctx.eval.attribs.map2_enabled) || i2 < i1 || j2 < j1) return;
  const int64_t columns = int64_t(i2) - i1 + 1, rows = int64_t(j2) - j1 + 1;
  if (!mesh_fits(ctx, std::max(columns, rows), std::max(columns, rows))) return;  // keeps the products below exact
  const int64_t longest = mode == GL_POINT ? columns * rows : mode == GL_FILL ? 2 * columns : std::max(columns, rows);
  if (!mesh_fits(ctx, longest, 2 * columns * rows)) return;
  if (mode == GL_FILL) {
    for (int64_t j = j1; j < j2; ++j) {
      Begin(ctx, GL_QUAD_STRIP);
      for (int64_t i = i1; i <= i2; ++i) {
        eval_point2(ctx, GLint(i), GLint(j));
        eval_point2(ctx, GLint(i), GLint(j + 1));
      }
      End(ctx);
    }
  } else if (mode == GL_LINE) {
    for (int64_t j = j1; j <= j2; ++j) {
      Begin(ctx, GL_LINE_STRIP);
      for (int64_t i = i1; i <= i2; ++i) eval_point2(ctx, GLint(i), GLint(j));
      End(ctx);
    }
    for (int64_t i = i1; i <= i2; ++i) {
      Begin(ctx, GL_LINE_STRIP);
      for (int64_t j = j1; j <= j2; ++j) eval_point2(ctx, GLint(i), GLint(j));
      End(ctx);
    }
  } else {
    Begin(ctx, GL_POINTS);
    for (int64_t j = j1; j <= j2; ++j)
      for (int64_t i = i1; i <= i2; ++i) eval_point2(ctx, GLint(i), GLint(j));
    End(ctx);
  }
}

}  // namespace pineda::gl
