#include "raster/rectangle_pair.h"

#include <algorithm>

#include "raster/raster_limits.h"

namespace pineda::raster {

bool rectangle_corner(const WinPosition& a, const WinPosition& b, const WinPosition& c, int& corner, int64_t& x0,
                      int64_t& y0, int64_t& x1, int64_t& y1) {
  const WinPosition* v[3] = {&a, &b, &c};
  for (int i = 0; i < 3; ++i) {
    const WinPosition& r = *v[i];
    const WinPosition& p = *v[(i + 1) % 3];
    const WinPosition& q = *v[(i + 2) % 3];
    // r's right angle: one neighbour along x (same y), the other along y (same x).
    const WinPosition* along_x = p.y == r.y ? &p : q.y == r.y ? &q : nullptr;
    const WinPosition* along_y = p.x == r.x ? &p : q.x == r.x ? &q : nullptr;
    if (!along_x || !along_y || along_x == along_y || along_x->x == r.x || along_y->y == r.y) continue;
    corner = i;
    x0 = std::min(r.x, along_x->x);
    x1 = std::max(r.x, along_x->x);
    y0 = std::min(r.y, along_y->y);
    y1 = std::max(r.y, along_y->y);
    return true;
  }
  return false;
}

namespace {

bool same_position(const WinPosition& a, const WinPosition& b) {
  return a.x == b.x && a.y == b.y && a.fx == b.fx && a.fy == b.fy && a.z == b.z && a.inv_w == b.inv_w;
}

bool same_values(const float* a, const float* b, int count) {
  for (int k = 0; k < count; ++k)
    if (!(a[k] == b[k])) return false;
  return true;
}

}  // namespace

bool completes_rectangle(const RectangleHalf& half, const float* const (&half_values)[3],
                         const WinPosition* const (&v)[3], const float* const (&values)[3], int count) {
  int corner = 0;
  int64_t x0, y0, x1, y1;
  if (!rectangle_corner(*v[0], *v[1], *v[2], corner, x0, y0, x1, y1)) return false;
  if (x0 != half.x0 || y0 != half.y0 || x1 != half.x1 || y1 != half.y1) return false;
  const WinPosition& c = half.v[half.corner];
  const WinPosition& d = *v[corner];
  if (d.x == c.x || d.y == c.y) return false;  // the right angles must be opposite
  // The half's other vertices: p beside its corner along x, q along y; v's must be the same two.
  const int pi = half.v[(half.corner + 1) % 3].y == c.y ? (half.corner + 1) % 3 : (half.corner + 2) % 3;
  const int qi = 3 - half.corner - pi;
  const WinPosition &p = half.v[pi], &q = half.v[qi];
  const int vp = v[(corner + 1) % 3]->y == p.y ? (corner + 1) % 3 : (corner + 2) % 3;
  const int vq = 3 - corner - vp;
  if (!same_position(*v[vp], p) || !same_position(*v[vq], q)) return false;
  if (!same_values(values[vp], half_values[pi], count) || !same_values(values[vq], half_values[qi], count)) return false;
  // A rectangle before snapping too, with one depth and one 1/w.
  if (!(c.fx == q.fx && c.fy == p.fy && d.fx == p.fx && d.fy == q.fy)) return false;
  if (!(c.z == p.z && c.z == q.z && c.z == d.z && c.inv_w == p.inv_w && c.inv_w == q.inv_w && c.inv_w == d.inv_w))
    return false;
  // On one plane: the same change along x on both rows, along y on both columns.
  const float *fc = half_values[half.corner], *fp = half_values[pi], *fq = half_values[qi], *fd = values[corner];
  for (int k = 0; k < count; ++k)
    if (!(fp[k] - fc[k] == fd[k] - fq[k] && fq[k] - fc[k] == fd[k] - fp[k])) return false;
  return true;
}

void make_rectangle(const RectangleHalf& half, const PixelRect& clip, PrimSetup& prim) {
  // Centres x + 1/2 in [x0, x1): the left and bottom sides own the centres on them (setup_triangle).
  const PixelRect pixels{static_cast<int>(ceil_div(half.x0 - kSubpixelHalf, kSubpixelOne)),
                         static_cast<int>(ceil_div(half.y0 - kSubpixelHalf, kSubpixelOne)),
                         static_cast<int>(ceil_div(half.x1 - kSubpixelHalf, kSubpixelOne)),
                         static_cast<int>(ceil_div(half.y1 - kSubpixelHalf, kSubpixelOne))};
  prim.bounds = intersect(pixels, clip);
  for (EdgeFunction& e : prim.edges) e = EdgeFunction{0, 0, 0};
}

}  // namespace pineda::raster
