#include "state/evaluators/evaluator.h"

#include <algorithm>
#include <span>

namespace pineda {
namespace {

constexpr int kComponents[kEvalMapKinds] = {4, 1, 3, 1, 2, 3, 4, 3, 4};

// GL 1.1 table 6.23: the initial control point of each kind (unused components 0, 0, 0, 1).
glm::dvec4 default_point(int kind) {
  switch (kind) {
    case kEvalColor: return {1, 1, 1, 1};
    case kEvalIndex: return {1, 0, 0, 1};
    case kEvalNormal: return {0, 0, 1, 1};
    default: return {0, 0, 0, 1};
  }
}

// The components a map does not have read as (0, 0, 0, 1).
glm::dvec4 pad(glm::dvec4 v, int components, double w) {
  const glm::dvec4 unused(0, 0, 0, w);
  for (int c = components; c < 4; ++c) v[c] = unused[c];
  return v;
}

struct CurvePoint {
  glm::dvec4 value, derivative;  // derivative with respect to t
};

// The Bezier curve of `points` (Bernstein polynomial of degree n = size - 1) at t, by de
// Casteljau's construction; its derivative is n times the difference of the last two points.
CurvePoint bezier(std::span<const glm::dvec4> points, double t) {
  std::array<glm::dvec4, kMaxEvalOrder> b;
  const size_t n = points.size() - 1;
  std::copy(points.begin(), points.end(), b.begin());
  if (n == 0) return {b[0], glm::dvec4(0.0)};
  for (size_t level = n; level > 1; --level)
    for (size_t i = 0; i < level; ++i) b[i] = (1.0 - t) * b[i] + t * b[i + 1];
  return {(1.0 - t) * b[0] + t * b[1], double(n) * (b[1] - b[0])};
}

}  // namespace

int map1_kind(GLenum target) {
  return target >= GL_MAP1_COLOR_4 && target <= GL_MAP1_VERTEX_4 ? int(target - GL_MAP1_COLOR_4) : -1;
}

int map2_kind(GLenum target) {
  return target >= GL_MAP2_COLOR_4 && target <= GL_MAP2_VERTEX_4 ? int(target - GL_MAP2_COLOR_4) : -1;
}

int map_components(int kind) { return kComponents[kind]; }

EvaluatorState::EvaluatorState() {
  for (int kind = 0; kind < kEvalMapKinds; ++kind) {
    map1[kind].points.assign(1, default_point(kind));
    map2[kind].points.assign(1, default_point(kind));
  }
}

glm::dvec4 evaluate_map1(const EvalMap1& map, int components, double u) {
  const double t = (u - map.u1) / (map.u2 - map.u1);
  return pad(bezier(map.points, t).value, components, 1.0);
}

SurfacePoint evaluate_map2(const EvalMap2& map, int components, double u, double v) {
  const double s = (u - map.u1) / (map.u2 - map.u1), t = (v - map.v1) / (map.v2 - map.v1);
  // Each row i (fixed u index) is a curve in v; their values and v-derivatives at t are the
  // control points of curves in u.
  std::array<glm::dvec4, kMaxEvalOrder> rows, row_derivatives;
  const std::span<const glm::dvec4> points(map.points);
  for (GLint i = 0; i < map.uorder; ++i) {
    const CurvePoint row = bezier(points.subspan(size_t(i) * map.vorder, map.vorder), t);
    rows[i] = row.value;
    row_derivatives[i] = row.derivative;
  }
  const CurvePoint across = bezier(std::span(rows).first(map.uorder), s);
  const glm::dvec4 along = bezier(std::span(row_derivatives).first(map.uorder), s).value;
  return {pad(across.value, components, 1.0), pad(across.derivative / (map.u2 - map.u1), components, 0.0),
          pad(along / (map.v2 - map.v1), components, 0.0)};
}

bool* evaluator_capability(EvalAttribState& state, GLenum cap) {
  if (cap == GL_AUTO_NORMAL) return &state.auto_normal;
  if (const int kind = map1_kind(cap); kind >= 0) return &state.map1_enabled[kind];
  if (const int kind = map2_kind(cap); kind >= 0) return &state.map2_enabled[kind];
  return nullptr;
}

double grid_coordinate(GLint i, GLint n, double a1, double a2) {
  if (i == n) return a2;
  return a1 + double(i) * ((a2 - a1) / double(n));
}

}  // namespace pineda
