#include "state/evaluators/evaluator_vertex.h"

#include "state/context.h"
#include "state/current_vertex.h"

namespace pineda {
namespace {

// The map of the highest-numbered enabled kind in [first, last], or -1 (GL 1.1 5.1: of
// VERTEX_3/VERTEX_4 and of the four texture coordinate maps only the largest is evaluated).
int highest_enabled(const std::array<bool, kEvalMapKinds>& enabled, int first, int last) {
  for (int kind = last; kind >= first; --kind)
    if (enabled[kind]) return kind;
  return -1;
}

void copy4(const glm::dvec4& from, float* to, int count) {
  for (int c = 0; c < count; ++c) to[c] = static_cast<float>(from[c]);
}

// The attributes a map of `kind` gives the vertex. The colour index has no place in an RGBA
// vertex: MAP*_INDEX is evaluated into nothing, as glIndex would be.
template <typename Evaluate>
void apply_maps(const std::array<bool, kEvalMapKinds>& enabled, Evaluate evaluate, raster::VertexInput& v) {
  if (enabled[kEvalColor]) copy4(evaluate(kEvalColor), v.color, 4);
  if (enabled[kEvalNormal]) copy4(evaluate(kEvalNormal), v.normal, 3);
  if (const int tex = highest_enabled(enabled, kEvalTexCoord1, kEvalTexCoord4); tex >= 0)
    copy4(evaluate(tex), v.texcoord[0], 4);
}

void emit(Context& ctx, const glm::dvec4& position, const raster::VertexInput& attributes) {
  raster::VertexInput v = attributes;
  copy4(position, v.position, 4);
  ctx.immediate.push_back(v);
}

// GL 1.1 5.1: n = (dp/du x dp/dv) / |dp/du x dp/dv|, from the position (x, y, z), or from
// (x/w, y/w, z/w) for a 4-component map: its derivatives are (d(x) w - x d(w)) / w^2, and
// the positive factor 1/w^2 does not change the normalized cross product.
glm::dvec3 analytic_normal(const SurfacePoint& s, bool homogeneous) {
  glm::dvec3 du(s.dp_du), dv(s.dp_dv);
  if (homogeneous) {
    du = du * s.p.w - glm::dvec3(s.p) * s.dp_du.w;
    dv = dv * s.p.w - glm::dvec3(s.p) * s.dp_dv.w;
  }
  const glm::dvec3 m = glm::cross(du, dv);
  const double length = glm::length(m);
  return length > 0.0 ? m / length : m;
}

}  // namespace

void eval_coord1(Context& ctx, double u) {
  const EvalAttribState& a = ctx.eval.attribs;
  const int vertex = highest_enabled(a.map1_enabled, kEvalVertex3, kEvalVertex4);
  if (vertex < 0 || !ctx.in_begin_end) return;
  raster::VertexInput v = current_vertex(ctx, 0, 0, 0, 1);
  apply_maps(a.map1_enabled, [&](int kind) { return evaluate_map1(ctx.eval.map1[kind], map_components(kind), u); }, v);
  emit(ctx, evaluate_map1(ctx.eval.map1[vertex], map_components(vertex), u), v);
}

void eval_coord2(Context& ctx, double u, double v) {
  const EvalAttribState& a = ctx.eval.attribs;
  const int vertex = highest_enabled(a.map2_enabled, kEvalVertex3, kEvalVertex4);
  if (vertex < 0 || !ctx.in_begin_end) return;
  raster::VertexInput out = current_vertex(ctx, 0, 0, 0, 1);
  auto evaluate = [&](int kind) { return evaluate_map2(ctx.eval.map2[kind], map_components(kind), u, v).p; };
  apply_maps(a.map2_enabled, evaluate, out);
  const SurfacePoint position = evaluate_map2(ctx.eval.map2[vertex], map_components(vertex), u, v);
  if (a.auto_normal) {  // replaces MAP2_NORMAL's normal
    const glm::dvec3 n = analytic_normal(position, vertex == kEvalVertex4);
    copy4(glm::dvec4(n, 0.0), out.normal, 3);
  }
  emit(ctx, position.p, out);
}

}  // namespace pineda
