// A receding plane in perspective, given directly in clip coordinates (floats, identity
// matrices), and the exact window-space values at pixel centres computed from those floats in
// long double: the reference for depth and attribute interpolation.
#pragma once
#include <GL/gl.h>

#include <array>
#include <cmath>

namespace pineda::test {

struct ClipVertex4 {
  float x, y, z, w;
};

// The trapezoid of a glFrustum(-n, n, -n, n, n, f) view looking at a floor-like plane: its
// near edge at eye depth 1.5 n, its far edge at 0.8 f, both 1.2 times wider than the view.
inline std::array<ClipVertex4, 4> receding_plane(double n, double f) {
  const double d0 = 1.5 * n, d1 = 0.8 * f;
  auto clip = [&](double xe, double ye, double ze) {
    const double zc = -(f + n) / (f - n) * ze - 2 * f * n / (f - n);
    return ClipVertex4{float(xe), float(ye), float(zc), float(-ze)};
  };
  return {clip(-1.2 * d0, -1.2 * d0, -d0), clip(1.2 * d0, -1.2 * d0, -d0), clip(1.2 * d1, 1.2 * d1, -d1),
          clip(-1.2 * d1, 1.2 * d1, -d1)};
}

// Screen-space barycentric weights of a pixel centre in triangle (a, b, c) of the plane, and
// whether all are >= -slack.
struct Weights {
  long double l[3];
  bool inside(long double slack) const { return l[0] >= -slack && l[1] >= -slack && l[2] >= -slack; }
};

inline Weights screen_weights(const ClipVertex4& a, const ClipVertex4& b, const ClipVertex4& c, int width,
                              int height, double px, double py) {
  auto wx = [&](const ClipVertex4& v) { return ((long double)v.x / v.w + 1) * width / 2; };
  auto wy = [&](const ClipVertex4& v) { return ((long double)v.y / v.w + 1) * height / 2; };
  const long double ax = wx(a), ay = wy(a), bx = wx(b), by = wy(b), cx = wx(c), cy = wy(c);
  const long double area = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
  Weights w;
  w.l[1] = ((px - ax) * (cy - ay) - (cx - ax) * (py - ay)) / area;
  w.l[2] = ((bx - ax) * (py - ay) - (px - ax) * (by - ay)) / area;
  w.l[0] = 1 - w.l[1] - w.l[2];
  return w;
}

// Window depth in [0, 1]: linear in screen space.
inline long double window_depth(const ClipVertex4* const* v, const Weights& w) {
  long double z = 0;
  for (int i = 0; i < 3; ++i) z += w.l[i] * (((long double)v[i]->z / v[i]->w + 1) / 2);
  return z;
}

// A per-vertex attribute, perspective-correct: sum(l a / w) / sum(l / w).
inline long double perspective_value(const ClipVertex4* const* v, const Weights& w, const double a[3]) {
  long double num = 0, den = 0;
  for (int i = 0; i < 3; ++i) {
    num += w.l[i] * a[i] / v[i]->w;
    den += w.l[i] / v[i]->w;
  }
  return num / den;
}

}  // namespace pineda::test
