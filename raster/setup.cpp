#include "raster/setup.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <type_traits>
#include <utility>

#include "raster/raster_limits.h"
#include "raster/sample_point.h"
#include "raster/smooth_coverage.h"

namespace pineda::raster {
namespace {

void copy_common(const SetupParams& params, PrimSetup& out) {
  out.draw = params.draw;
  out.back_facing = params.back_facing;
  for (int i = 0; i < 4; ++i) out.flat_color[i] = params.flat_color[i];
}

void constant_planes(const WinVert& v, const SetupParams& params, PrimSetup& out) {
  out.perspective = false;
  out.ref_x = static_cast<float>(v.fx);
  out.ref_y = static_cast<float>(v.fy);
  out.inv_w = {1.f, 0.f, 0.f};
  for (int k = 0; k < params.planes; ++k) out.planes[k] = {v.attr[k], 0.f, 0.f};
  for (int k = 0; k < params.varyings; ++k) params.varying_out[k] = {v.varyings[k], 0.f, 0.f};
  if (params.programmable) out.inv_w = {static_cast<float>(v.inv_w), 0.f, 0.f};
  out.z0 = v.z + params.depth_offset;
  out.dzdx = out.dzdy = 0.0;
}

// A point, every value the vertex's, over the pixels of `box` inside the clip rectangle; false
// when there are none.
bool setup_point_in(const PixelRect& box, const WinVert& v, const SetupParams& params, PrimSetup& out) {
  out.bounds = intersect(box, params.clip);
  if (out.bounds.empty()) return false;
  out.kind = CoverageKind::Point;
  copy_common(params, out);
  constant_planes(v, params, out);
  return true;
}

// Planes through the values at two or three vertices; `gradient` maps the values at the
// vertices to the per-pixel slopes.
template <typename Vertex, typename Gradient>
void interpolation_planes(const Vertex* const* v, int count, const SetupParams& params, Gradient gradient,
                          PrimSetup& out) {
  bool same_w = true;
  for (int i = 1; i < count; ++i) same_w &= v[i]->inv_w == v[0]->inv_w;
  out.perspective = !same_w;
  // Planes go through the exact (unsnapped) vertex positions, as llvmpipe's do; only coverage
  // uses the snapped ones. The reference point is the snapped first vertex: on the 1/256 grid,
  // a fragment's float offset x + 1/2 - ref_x is then exact inside the guard band (an
  // unsnapped float reference costs up to 1e-5 px, ~100 units of 32-bit depth on steep planes).
  out.ref_x = static_cast<float>(static_cast<double>(v[0]->x) / kSubpixelOne);
  out.ref_y = static_cast<float>(static_cast<double>(v[0]->y) / kSubpixelOne);
  const double shift_x = out.ref_x - v[0]->fx, shift_y = out.ref_y - v[0]->fy;
  double f[3], gx, gy;
  auto make_plane = [&]() {
    gradient(f, gx, gy);
    return Plane{static_cast<float>(f[0] + gx * shift_x + gy * shift_y), static_cast<float>(gx), static_cast<float>(gy)};
  };
  for (int i = 0; i < count; ++i) f[i] = out.perspective ? v[i]->inv_w : 1.0;
  out.inv_w = make_plane();
  if constexpr (std::is_same_v<Vertex, WinVert>) {
    for (int k = 0; k < params.planes; ++k) {
      for (int i = 0; i < count; ++i) f[i] = out.perspective ? v[i]->attr[k] * v[i]->inv_w : v[i]->attr[k];
      out.planes[k] = make_plane();
    }
  } else {
    assert(params.planes == 0);
  }
  for (int k = 0; k < params.varyings; ++k) {
    for (int i = 0; i < count; ++i) f[i] = out.perspective ? v[i]->varyings[k] * v[i]->inv_w : v[i]->varyings[k];
    params.varying_out[k] = make_plane();
  }
  if (params.programmable && !out.perspective) {  // gl_FragCoord.w: the primitive's common 1/w
    for (int i = 0; i < count; ++i) f[i] = v[i]->inv_w;
    out.inv_w = make_plane();
  }
  for (int i = 0; i < count; ++i) f[i] = v[i]->z;
  gradient(f, gx, gy);
  out.z0 = f[0] + gx * shift_x + gy * shift_y + params.depth_offset;
  out.dzdx = gx;
  out.dzdy = gy;
}

// Whether a point (in sub-pixels) lies strictly inside the diamond |x - xc| + |y - yc| < 1/2
// of the pixel whose square holds it.
bool in_diamond(int64_t x, int64_t y) {
  const int64_t fx = x & (kSubpixelOne - 1), fy = y & (kSubpixelOne - 1);
  return std::llabs(2 * fx - kSubpixelOne) + std::llabs(2 * fy - kSubpixelOne) < kSubpixelOne;
}

// Attributes vary along the major axis only: every fragment of a column (row) of a wide line
// gets the value of the line's centre there, as for a width-1 line.
void line_planes(const WinVert& a, const WinVert& b, bool x_major, const SetupParams& params, PrimSetup& out) {
  double major = x_major ? b.fx - a.fx : b.fy - a.fy;
  if (!(std::fabs(major) > 1e-9)) major = static_cast<double>(x_major ? b.x - a.x : b.y - a.y) / kSubpixelOne;
  const WinVert* v[2] = {&a, &b};
  interpolation_planes(
      v, 2, params,
      [&](const double* f, double& gx, double& gy) {
        const double g = (f[1] - f[0]) / major;
        gx = x_major ? g : 0.0;
        gy = x_major ? 0.0 : g;
      },
      out);
}

}  // namespace

int64_t signed_area2(const WinPosition& a, const WinPosition& b, const WinPosition& c) {
  return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
}

bool depth_slopes(const WinVert& a, const WinVert& b, const WinVert& c, double& dzdx, double& dzdy) {
  const double dx1 = b.fx - a.fx, dy1 = b.fy - a.fy;
  const double dx2 = c.fx - a.fx, dy2 = c.fy - a.fy;
  const double area = dx1 * dy2 - dx2 * dy1;
  if (area == 0.0) return false;
  dzdx = ((b.z - a.z) * dy2 - (c.z - a.z) * dy1) / area;
  dzdy = ((c.z - a.z) * dx1 - (b.z - a.z) * dx2) / area;
  return true;
}

template <typename Vertex>
bool setup_triangle(const Vertex& a, const Vertex& b, const Vertex& c, const SetupParams& params, PrimSetup& out) {
  const int64_t area = signed_area2(a, b, c);
  if (area == 0) return false;
  const Vertex* v[3] = {&a, &b, &c};
  if (area < 0) std::swap(v[1], v[2]);  // edges below assume counter-clockwise order

  const int64_t min_x = std::min({a.x, b.x, c.x}), max_x = std::max({a.x, b.x, c.x});
  const int64_t min_y = std::min({a.y, b.y, c.y}), max_y = std::max({a.y, b.y, c.y});
  // Pixels whose centre (x + 1/2) can lie inside the vertices' box.
  const PixelRect box{static_cast<int>(ceil_div(min_x - kSubpixelHalf, kSubpixelOne)),
                      static_cast<int>(ceil_div(min_y - kSubpixelHalf, kSubpixelOne)),
                      static_cast<int>(floor_div(max_x - kSubpixelHalf, kSubpixelOne) + 1),
                      static_cast<int>(floor_div(max_y - kSubpixelHalf, kSubpixelOne) + 1)};
  // Multisampled: pixels whose area meets the box, for samples off the centre.
  const PixelRect sample_box{static_cast<int>(floor_div(min_x, kSubpixelOne)), static_cast<int>(floor_div(min_y, kSubpixelOne)),
                             static_cast<int>(ceil_div(max_x, kSubpixelOne)), static_cast<int>(ceil_div(max_y, kSubpixelOne))};
  out.bounds = intersect(params.sample_bounds ? sample_box : box, params.clip);
  if (out.bounds.empty()) return false;

  out.kind = CoverageKind::Triangle;
  copy_common(params, out);
  for (int i = 0; i < 3; ++i) {
    const WinPosition& p = *v[i];
    const WinPosition& q = *v[(i + 1) % 3];
    const int64_t dx = q.x - p.x, dy = q.y - p.y;
    EdgeFunction& e = out.edges[i];
    e.a = -dy;
    e.b = dx;
    e.c = dy * p.x - dx * p.y;
    // Fill rule with GL's lower-left origin: left edges (going down) and bottom edges
    // (horizontal, going right) own the pixel centres on them; the others do not.
    const bool owns_boundary = dy < 0 || (dy == 0 && dx > 0);
    if (!owns_boundary) e.c -= 1;
  }

  double dx1 = v[1]->fx - v[0]->fx, dy1 = v[1]->fy - v[0]->fy;
  double dx2 = v[2]->fx - v[0]->fx, dy2 = v[2]->fy - v[0]->fy;
  if (!(std::fabs(dx1 * dy2 - dx2 * dy1) > 1e-12)) {  // degenerate before snapping: use the snapped shape
    dx1 = static_cast<double>(v[1]->x - v[0]->x) / kSubpixelOne;
    dy1 = static_cast<double>(v[1]->y - v[0]->y) / kSubpixelOne;
    dx2 = static_cast<double>(v[2]->x - v[0]->x) / kSubpixelOne;
    dy2 = static_cast<double>(v[2]->y - v[0]->y) / kSubpixelOne;
  }
  const double inv_area = 1.0 / (dx1 * dy2 - dx2 * dy1);
  interpolation_planes(
      v, 3, params,
      [&](const double* f, double& gx, double& gy) {
        gx = ((f[1] - f[0]) * dy2 - (f[2] - f[0]) * dy1) * inv_area;
        gy = ((f[2] - f[0]) * dx1 - (f[1] - f[0]) * dx2) * inv_area;
      },
      out);
  return true;
}

template bool setup_triangle(const WinVert&, const WinVert&, const WinVert&, const SetupParams&, PrimSetup&);
template bool setup_triangle(const WinPosition&, const WinPosition&, const WinPosition&, const SetupParams&, PrimSetup&);

bool setup_line(const WinVert& a, const WinVert& b, int width, const SetupParams& params, PrimSetup& out) {
  const int64_t dx = b.x - a.x, dy = b.y - a.y;
  if (dx == 0 && dy == 0) return false;
  LineCoverage& l = out.line;
  l = {a.x, a.y, b.x, b.y, width, std::llabs(dx) >= std::llabs(dy), 0, -1};
  // GL's diamond-exit rule along the major axis: the columns (rows) whose centre line the
  // segment crosses, plus the pixel whose diamond holds the first vertex (the segment leaves
  // it), minus the pixel whose diamond holds the last vertex (the segment never leaves it).
  const int64_t s0 = l.x_major ? a.x : a.y, s1 = l.x_major ? b.x : b.y;
  const bool a_in_diamond = in_diamond(a.x, a.y), b_in_diamond = in_diamond(b.x, b.y);
  const int64_t a_column = floor_div(s0, kSubpixelOne), b_column = floor_div(s1, kSubpixelOne);
  int64_t lo = ceil_div(std::min(s0, s1) - kSubpixelHalf, kSubpixelOne);
  int64_t hi = floor_div(std::max(s0, s1) - kSubpixelHalf, kSubpixelOne);
  if (s1 > s0) {
    if (a_in_diamond) lo = std::min(lo, a_column);
    if (b_in_diamond && b_column == hi) --hi;
  } else {
    if (a_in_diamond) hi = std::max(hi, a_column);
    if (b_in_diamond && b_column == lo) ++lo;
  }
  if (lo > hi) return false;
  l.major_min = static_cast<int>(lo);
  l.major_max = static_cast<int>(hi);
  const int64_t m0 = l.x_major ? std::min(a.y, b.y) : std::min(a.x, b.x);
  const int64_t m1 = l.x_major ? std::max(a.y, b.y) : std::max(a.x, b.x);
  const int64_t half = kSubpixelHalf * width;
  const int minor_lo = static_cast<int>(floor_div(m0 - half - kSubpixelOne, kSubpixelOne));
  const int minor_hi = static_cast<int>(floor_div(m1 + half, kSubpixelOne) + 1);
  const PixelRect box = l.x_major ? PixelRect{l.major_min, minor_lo, l.major_max + 1, minor_hi}
                                  : PixelRect{minor_lo, l.major_min, minor_hi, l.major_max + 1};
  out.bounds = intersect(box, params.clip);
  if (out.bounds.empty()) return false;
  out.kind = CoverageKind::Line;
  copy_common(params, out);

  line_planes(a, b, l.x_major, params, out);
  return true;
}

bool setup_smooth_line(const WinVert& a, const WinVert& b, double width, const SetupParams& params, PrimSetup& out) {
  const int64_t dx = b.x - a.x, dy = b.y - a.y;
  if (dx == 0 && dy == 0) return false;
  out.smooth = {static_cast<double>(a.x) / kSubpixelOne, static_cast<double>(a.y) / kSubpixelOne,
                static_cast<double>(b.x) / kSubpixelOne, static_cast<double>(b.y) / kSubpixelOne, width};
  out.bounds = intersect(smooth_bounds(out.smooth), params.clip);
  if (out.bounds.empty()) return false;
  out.kind = CoverageKind::Line;
  out.line = {a.x, a.y, b.x, b.y, 1, std::llabs(dx) >= std::llabs(dy), 0, -1};  // the stipple's axis
  copy_common(params, out);
  line_planes(a, b, out.line.x_major, params, out);
  return true;
}

bool setup_point(const WinVert& v, int size, const SetupParams& params, PrimSetup& out) {
  // GL's square point: centred on floor(x) + 1/2 for odd sizes, on floor(x + 1/2) for even
  // ones; both give the first pixel floor(x - (size - 1) / 2).
  const int64_t left = floor_div(v.x - (size - 1) * kSubpixelHalf, kSubpixelOne);
  const int64_t bottom = floor_div(v.y - (size - 1) * kSubpixelHalf, kSubpixelOne);
  const PixelRect box{static_cast<int>(left), static_cast<int>(bottom), static_cast<int>(left + size),
                      static_cast<int>(bottom + size)};
  return setup_point_in(box, v, params, out);
}

bool setup_sample_point(const WinVert& v, int64_t size, bool square, const SetupParams& params, PrimSetup& out) {
  out.sample_point.x = static_cast<int32_t>(v.x);
  out.sample_point.y = static_cast<int32_t>(v.y);
  out.sample_point.size = static_cast<uint32_t>(size);
  out.sample_point.square = square;
  return setup_point_in(sample_point_bounds(out.sample_point), v, params, out);
}

bool setup_smooth_point(const WinVert& v, double size, const SetupParams& params, PrimSetup& out) {
  const double x = static_cast<double>(v.x) / kSubpixelOne, y = static_cast<double>(v.y) / kSubpixelOne;
  out.smooth = {x, y, x, y, size};
  return setup_point_in(smooth_bounds(out.smooth), v, params, out);
}

}  // namespace pineda::raster
