#include "raster/smooth_coverage.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pineda::raster {
namespace {

// Area of the disc (radius r, at the origin) above the line Y = b.
double disc_above(double b, double r) {
  if (b >= r) return 0.0;
  if (b <= -r) return std::numbers::pi * r * r;
  if (b < 0.0) return std::numbers::pi * r * r - disc_above(-b, r);
  return r * r * std::acos(b / r) - b * std::sqrt(r * r - b * b);
}

// Area of the disc in the quadrant X >= a, Y >= b.
double disc_quadrant(double a, double b, double r) {
  if (a < 0.0) return disc_above(b, r) - disc_quadrant(-a, b, r);
  if (b < 0.0) return disc_above(a, r) - disc_quadrant(a, -b, r);
  if (a * a + b * b >= r * r) return 0.0;
  // The integral over [a, xm] of sqrt(r^2 - x^2) - b, xm where the circle meets Y = b.
  const double xm = std::sqrt(r * r - b * b);
  auto primitive = [r](double x) { return 0.5 * (x * std::sqrt(std::max(r * r - x * x, 0.0)) + r * r * std::asin(std::min(x / r, 1.0))); };
  return primitive(xm) - primitive(a) - b * (xm - a);
}

// Area of the unit square on the inner side of a line across it: the points p with
// n . (p - centre) <= t, n a unit normal whose components' magnitudes are steep >= shallow.
// The area grows as a parabola while the line cuts a corner off, linearly while it crosses
// two opposite sides.
double square_in_half_plane(double t, double steep, double shallow) {
  const double reach = 0.5 * (steep + shallow), flat = 0.5 * (steep - shallow);
  if (t >= reach) return 1.0;
  if (t <= -reach) return 0.0;
  if (t < -flat) {
    const double s = t + reach;
    return s * s / (2.0 * steep * shallow);
  }
  if (t > flat) {
    const double s = reach - t;
    return 1.0 - s * s / (2.0 * steep * shallow);
  }
  return 0.5 + t / steep;
}

}  // namespace

double square_in_disc(double x, double y, double r) {
  // Squares wholly outside or inside the disc (most of them) need no integral.
  const double near_x = std::clamp(0.0, x, x + 1.0), near_y = std::clamp(0.0, y, y + 1.0);
  if (near_x * near_x + near_y * near_y >= r * r) return 0.0;
  const double far_x = std::max(std::fabs(x), std::fabs(x + 1.0)), far_y = std::max(std::fabs(y), std::fabs(y + 1.0));
  if (far_x * far_x + far_y * far_y <= r * r) return 1.0;
  const double area = disc_quadrant(x, y, r) - disc_quadrant(x + 1.0, y, r) - disc_quadrant(x, y + 1.0, r) +
                      disc_quadrant(x + 1.0, y + 1.0, r);
  return std::clamp(area, 0.0, 1.0);
}

LineFrame::LineFrame(const SmoothShape& line) {
  const double dx = line.x1 - line.x0, dy = line.y1 - line.y0;
  const double length = std::sqrt(dx * dx + dy * dy);
  ux = dx / length;
  uy = dy / length;
  mx = 0.5 * (line.x0 + line.x1);
  my = 0.5 * (line.y0 + line.y1);
  half_length = 0.5 * length;
  half_width = 0.5 * line.size;
  square_reach = 0.5 * (std::fabs(ux) + std::fabs(uy));
  steep = std::max(std::fabs(ux), std::fabs(uy));
  shallow = std::min(std::fabs(ux), std::fabs(uy));
}

double square_in_rectangle(double x, double y, const LineFrame& line) {
  const double ux = line.ux, uy = line.uy, mx = line.mx, my = line.my;
  // The square's corners relative to the middle of the line, clipped (Sutherland-Hodgman) to
  // |along| <= length / 2 and |across| <= width / 2 in the line's frame.
  double px[8] = {x - mx, x + 1 - mx, x + 1 - mx, x - mx}, py[8] = {y - my, y - my, y + 1 - my, y + 1 - my};
  int n = 4;
  const double half[2] = {line.half_length, line.half_width};
  // Most squares lie wholly inside or outside the rectangle; the square's centre in the line's
  // frame tells, with a margin far above the rounding of the clipping below so that the answer
  // is the one clipping would give: 0, or the square's own area.
  const double margin = 1e-6;
  const double cx = x + 0.5 - mx, cy = y + 0.5 - my;
  const double along_signed = cx * ux + cy * uy, across_signed = cx * uy - cy * ux;
  const double along = std::fabs(along_signed), across = std::fabs(across_signed);
  if (along - line.square_reach > half[0] + margin || across - line.square_reach > half[1] + margin) return 0.0;
  const bool along_inside = along + line.square_reach + margin <= half[0];
  const bool across_inside = across + line.square_reach + margin <= half[1];
  const bool inside = along_inside && across_inside;
  // A square that only one side of the rectangle cuts (the nearer of two opposite sides, when
  // the other holds the square whole as the other pair does): the area in closed form. Not for
  // a square the side barely touches: there clipping decides whether any area is left (and so
  // whether the pixel is drawn), as it always has.
  const double holds = line.square_reach + margin;  // a side this far past the centre holds the square
  const double touches = 1e-5 - line.square_reach;  // less room than this inside the side: clipping
  if (along_inside && !inside && half[1] >= holds && half[1] - across > touches)
    return std::clamp(square_in_half_plane(half[1] - across, line.steep, line.shallow), 0.0, 1.0);
  if (across_inside && !inside && half[0] >= holds && half[0] - along > touches)
    return std::clamp(square_in_half_plane(half[0] - along, line.steep, line.shallow), 0.0, 1.0);
  for (int plane = 0; plane < 4 && n > 0 && !inside; ++plane) {
    // Keep s * (the coordinate along axis a) <= half[a].
    const bool along = plane < 2;
    const double s = plane & 1 ? -1.0 : 1.0, limit = half[along ? 0 : 1];
    auto value = [&](int i) { return s * (along ? px[i] * ux + py[i] * uy : px[i] * uy - py[i] * ux) - limit; };
    // A polygon wholly inside the plane is kept as it is, one wholly outside is gone: most
    // squares are inside or outside the line, and only those across an edge are clipped.
    double v[8];
    int outside = 0;
    for (int i = 0; i < n; ++i) outside += (v[i] = value(i)) > 0.0;
    if (outside == 0) continue;
    if (outside == n) return 0.0;
    double qx[8], qy[8];
    int m = 0;
    for (int i = 0; i < n; ++i) {
      const int j = (i + 1) % n;
      const double vi = v[i], vj = v[j];
      if (vi <= 0.0) {
        qx[m] = px[i];
        qy[m++] = py[i];
      }
      if ((vi < 0.0 && vj > 0.0) || (vi > 0.0 && vj < 0.0)) {
        const double t = vi / (vi - vj);
        qx[m] = px[i] + t * (px[j] - px[i]);
        qy[m++] = py[i] + t * (py[j] - py[i]);
      }
    }
    n = m;
    for (int i = 0; i < n; ++i) {
      px[i] = qx[i];
      py[i] = qy[i];
    }
  }
  double twice_area = 0.0;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    twice_area += px[i] * py[j] - px[j] * py[i];
  }
  return std::clamp(0.5 * twice_area, 0.0, 1.0);
}

// A point has no line frame: a unit line stands in (a zero-length one would divide by zero).
SmoothCoverage::SmoothCoverage(const PrimSetup& p)
    : shape_(p.smooth), point_(p.kind == CoverageKind::Point), line_(point_ ? SmoothShape{0, 0, 1, 0, 0} : p.smooth) {}

double SmoothCoverage::at(int x, int y) const {
  if (point_) return square_in_disc(x - shape_.x0, y - shape_.y0, 0.5 * shape_.size);
  return square_in_rectangle(x, y, line_);
}

void smooth_quad_coverage(const PrimSetup& p, int x, int y, unsigned mask, float out[4]) {
  const SmoothCoverage coverage(p);
  for (int i = 0; i < 4; ++i)
    out[i] = mask >> i & 1 ? static_cast<float>(coverage.at(x + (i & 1), y + (i >> 1))) : 1.f;
}

PixelRect smooth_bounds(const SmoothShape& s) {
  // The shape grown by half a pixel holds every pixel centre whose square it touches.
  double reach_x = 0.5 * s.size + 0.5, reach_y = reach_x;
  double min_x = std::min(s.x0, s.x1), max_x = std::max(s.x0, s.x1);
  double min_y = std::min(s.y0, s.y1), max_y = std::max(s.y0, s.y1);
  if (s.x0 != s.x1 || s.y0 != s.y1) {  // a line also reaches half a pixel past its ends
    reach_x += 0.5;
    reach_y += 0.5;
  }
  min_x -= reach_x;
  max_x += reach_x;
  min_y -= reach_y;
  max_y += reach_y;
  const double limit = 1e9;  // window positions stay far inside; this keeps the casts defined
  auto lo = [&](double v) { return static_cast<int>(std::floor(std::clamp(v - 0.5, -limit, limit))); };
  auto hi = [&](double v) { return static_cast<int>(std::floor(std::clamp(v - 0.5, -limit, limit))) + 1; };
  return {lo(min_x), lo(min_y), hi(max_x), hi(max_y)};
}

void smooth_row_span(const SmoothShape& s, int y, int& x0, int& x1) {
  const double dy = s.y1 - s.y0;
  if (std::fabs(dy) < 1.0) return;  // flat lines (and points) keep their bounding box
  const double dx = s.x1 - s.x0;
  // A pixel whose centre is farther than w/2 + sqrt(2)/2 from the line's axis misses it.
  const double reach = (0.5 * s.size + 0.70711) * std::sqrt(dx * dx + dy * dy) / std::fabs(dy);
  const double axis_x = s.x0 + (y + 0.5 - s.y0) * dx / dy;
  x0 = std::max(x0, static_cast<int>(std::floor(std::max(axis_x - reach - 0.5, -1e9))));
  x1 = std::min(x1, static_cast<int>(std::ceil(std::min(axis_x + reach + 0.5, 1e9))));
}

}  // namespace pineda::raster
