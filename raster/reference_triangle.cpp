#include "raster/reference_triangle.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "raster/fragment_extras.h"
#include "raster/reference_fragment.h"

namespace pineda::raster {
namespace {

// E(x, y) for the directed edge p -> q: positive on its left. It is always computed from the
// same (lexicographically smaller) end point, so the two triangles sharing an edge get values
// that are exact negatives of each other and a pixel centre cannot fall in both or neither.
struct ReferenceEdge {
  double x0, y0, dx, dy;
  bool negate;
  bool owns_boundary;
  double at(double x, double y) const {
    const double e = (x - x0) * dy - (y - y0) * dx;
    return negate ? e : -e;
  }
  bool inside(double x, double y) const {
    const double e = at(x, y);
    return e > 0.0 || (e == 0.0 && owns_boundary);
  }
};

ReferenceEdge make_edge(const WinVert& p, const WinVert& q) {
  const bool p_first = p.fx < q.fx || (p.fx == q.fx && p.fy < q.fy);
  const WinVert& s = p_first ? p : q;
  const WinVert& t = p_first ? q : p;
  // (x - s.x) * (t.y - s.y) - (y - s.y) * (t.x - s.x) is negative left of s -> t.
  ReferenceEdge e{s.fx, s.fy, t.fx - s.fx, t.fy - s.fy, !p_first, false};
  // The same rule as the fixed-point setup for GL's lower-left origin: edges going down (left
  // edges of a counter-clockwise triangle) and horizontal edges going right own their centres.
  const double dx = q.fx - p.fx, dy = q.fy - p.fy;
  e.owns_boundary = dy < 0 || (dy == 0 && dx > 0);
  return e;
}

}  // namespace

uint64_t reference_triangle(const WinVert& a, const WinVert& b, const WinVert& c, const SetupParams& params,
                            const DrawRecord& draw, const Framebuffer& fb) {
  const WinVert* v[3] = {&a, &b, &c};
  const double area = (b.fx - a.fx) * (c.fy - a.fy) - (c.fx - a.fx) * (b.fy - a.fy);
  if (!(std::fabs(area) > 0.0) || !std::isfinite(area)) return 0;
  if (area < 0) std::swap(v[1], v[2]);  // counter-clockwise from here on
  const double abs_area = std::fabs(area);
  // edge[i] is opposite vertex i: its value over the area is vertex i's barycentric weight.
  const ReferenceEdge edge[3] = {make_edge(*v[1], *v[2]), make_edge(*v[2], *v[0]), make_edge(*v[0], *v[1])};

  const double min_x = std::min({a.fx, b.fx, c.fx}), max_x = std::max({a.fx, b.fx, c.fx});
  const double min_y = std::min({a.fy, b.fy, c.fy}), max_y = std::max({a.fy, b.fy, c.fy});
  // Pixels whose centre can be inside the box, limited to the clip rectangle; even-aligned so
  // that quads match the fast path's (texture level of detail comes from the same neighbours).
  const int x0 = static_cast<int>(std::max<double>(params.clip.x0, std::ceil(min_x - 0.5))) & ~1;
  const int y0 = static_cast<int>(std::max<double>(params.clip.y0, std::ceil(min_y - 0.5))) & ~1;
  const int x1 = static_cast<int>(std::min<double>(params.clip.x1, std::floor(max_x - 0.5) + 1));
  const int y1 = static_cast<int>(std::min<double>(params.clip.y1, std::floor(max_y - 0.5) + 1));
  const bool perspective = !(v[0]->inv_w == v[1]->inv_w && v[1]->inv_w == v[2]->inv_w);

  PrimSetup stipple_prim;  // the polygon stipple needs only the primitive's kind
  stipple_prim.kind = CoverageKind::Triangle;
  uint64_t passed = 0;
  for (int qy = y0; qy < y1; qy += 2)
    for (int qx = x0; qx < x1; qx += 2) {
      ReferenceQuad quad;
      quad.x = qx;
      quad.y = qy;
      double weight[4][3];
      for (int i = 0; i < 4; ++i) {
        const int px = qx + (i & 1), py = qy + (i >> 1);
        const double cx = px + 0.5, cy = py + 0.5;
        bool in = px >= params.clip.x0 && px < params.clip.x1 && py >= params.clip.y0 && py < params.clip.y1;
        for (int e = 0; e < 3; ++e) {
          in = in && edge[e].inside(cx, cy);
          weight[i][e] = edge[e].at(cx, cy) / abs_area;
        }
        if (in) quad.mask |= 1u << i;
      }
      if (draw.key.extras) quad.mask &= stipple_mask(draw, stipple_prim, qx, qy);
      if (!quad.mask) continue;
      for (int i = 0; i < 4; ++i) {
        const double* l = weight[i];
        quad.z[i] = l[0] * v[0]->z + l[1] * v[1]->z + l[2] * v[2]->z + params.depth_offset;
        const double one_over_w =
            perspective ? l[0] * v[0]->inv_w + l[1] * v[1]->inv_w + l[2] * v[2]->inv_w : 1.0;
        for (int k = 0; k < params.planes; ++k) {
          double sum = 0.0;
          for (int j = 0; j < 3; ++j) sum += l[j] * v[j]->attr[k] * (perspective ? v[j]->inv_w : 1.0);
          quad.attr[k][i] = sum / one_over_w;
        }
      }
      passed += reference_shade_quad(draw, params.back_facing, params.flat_color, fb, quad);
    }
  if (passed && draw.state.sample_counter) draw.state.sample_counter->passed.fetch_add(passed);
  return passed;
}

}  // namespace pineda::raster
