// Evaluators (GL 1.1 section 5.1): the maps glMap1/glMap2 define, the grids of glMapGrid,
// their enables, and the evaluation of a map as a Bernstein polynomial.
#pragma once
#include <GL/gl.h>

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "state/get_values.h"

namespace pineda {

constexpr int kMaxEvalOrder = 30;  // GL_MAX_EVAL_ORDER
// One map per target kind, in the order of the enums: COLOR_4, INDEX, NORMAL,
// TEXTURE_COORD_1..4, VERTEX_3, VERTEX_4.
constexpr int kEvalMapKinds = 9;
enum EvalMapKind { kEvalColor, kEvalIndex, kEvalNormal, kEvalTexCoord1, kEvalTexCoord4 = 6, kEvalVertex3, kEvalVertex4 };

// The kind of a GL_MAP1_* or GL_MAP2_* target, or -1 when it is not one.
int map1_kind(GLenum target);
int map2_kind(GLenum target);
// Components of a control point of this kind (GL 1.1 table 5.1).
int map_components(int kind);

struct EvalMap1 {
  GLint order = 1;
  double u1 = 0, u2 = 1;
  std::vector<glm::dvec4> points;  // `order` control points
};

struct EvalMap2 {
  GLint uorder = 1, vorder = 1;
  double u1 = 0, u2 = 1, v1 = 0, v2 = 1;
  std::vector<glm::dvec4> points;  // control point (i, j) at [i * vorder + j]
};

struct EvalGrid1 {
  GLint n = 1;
  double u1 = 0, u2 = 1;
};

struct EvalGrid2 {
  GLint un = 1, vn = 1;
  double u1 = 0, u2 = 1, v1 = 0, v2 = 1;
};

// What GL_EVAL_BIT saves; the maps themselves are not attribute state.
struct EvalAttribState {
  std::array<bool, kEvalMapKinds> map1_enabled{}, map2_enabled{};
  bool auto_normal = false;
  EvalGrid1 grid1;
  EvalGrid2 grid2;
};

struct EvaluatorState {
  EvaluatorState();  // every map of order 1 on [0, 1] with its kind's default control point
  EvalAttribState attribs;
  std::array<EvalMap1, kEvalMapKinds> map1;
  std::array<EvalMap2, kEvalMapKinds> map2;
};

// The map at u: sum of B_i(u') R_i with u' = (u - u1) / (u2 - u1). Components past the
// map's own are (0, 0, 0, 1).
glm::dvec4 evaluate_map1(const EvalMap1& map, int components, double u);

struct SurfacePoint {
  glm::dvec4 p;       // components past the map's own are (0, 0, 0, 1)
  glm::dvec4 dp_du;   // partial derivatives with respect to u and v (not u', v')
  glm::dvec4 dp_dv;
};
SurfacePoint evaluate_map2(const EvalMap2& map, int components, double u, double v);

// The enable bit of GL_AUTO_NORMAL or a GL_MAP1_*/GL_MAP2_* capability, or null.
bool* evaluator_capability(EvalAttribState& state, GLenum cap);

// glGet of the grids (evaluator_get.cpp).
bool query_evaluator(Context& ctx, unsigned pname, GetValues& out);

// Grid coordinate i of glMapGrid's n segments of [a1, a2]: exactly a2 when i == n.
double grid_coordinate(GLint i, GLint n, double a1, double a2);

}  // namespace pineda
