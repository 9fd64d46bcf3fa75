// An independent, exact coverage reference for the stability tests, and a fixture that
// draws in exact window coordinates.
//
// Vertices are given in sub-pixels (1/256 px, the rasterizer's grid), so no rounding happens
// on the way: on a 128x64 surface with identity matrices, NDC = X / 64 - 1 is exact in float
// for |X| <= 32768. A pixel centre is covered when it is strictly inside all three edges, or
// on an edge that GL's lower-left-origin fill rule gives to the triangle (left edges and
// bottom edges), computed here with int64 cross products.
#pragma once
#include <GL/gl.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "tests/stability/coverage_count.h"

namespace pineda::test {

struct SubPoint {
  int64_t x = 0, y = 0;  // sub-pixels
};

constexpr int64_t kSub = 256;

inline SubPoint centre_of(int px, int py) { return {px * kSub + kSub / 2, py * kSub + kSub / 2}; }

// Whether the triangle owns the centre of pixel (px, py).
inline bool exact_covers(SubPoint a, SubPoint b, SubPoint c, int px, int py) {
  const int64_t area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  if (area == 0) return false;
  if (area < 0) std::swap(b, c);
  const SubPoint p = centre_of(px, py);
  const SubPoint v[3] = {a, b, c};
  for (int i = 0; i < 3; ++i) {
    const SubPoint s = v[i], t = v[(i + 1) % 3];
    const int64_t dx = t.x - s.x, dy = t.y - s.y;
    const int64_t e = dx * (p.y - s.y) - dy * (p.x - s.x);  // > 0 left of s -> t (inside)
    const bool owned = dy < 0 || (dy == 0 && dx > 0);
    if (e < 0 || (e == 0 && !owned)) return false;
  }
  return true;
}

class ExactCoverageTest : public CoverageCountTest {
 protected:
  SurfaceSpec spec() const override { return {128, 64, 24, 8}; }

  // Counting as in CoverageCountTest, with identity matrices (vertices are given in NDC).
  void begin_exact_counting() {
    begin_counting();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
  }

  // A vertex at window position p (sub-pixels) for the full-surface viewport.
  void vertex(SubPoint p) {
    glVertex2f(static_cast<float>(double(p.x) / (kSub * width() / 2) - 1.0),
               static_cast<float>(double(p.y) / (kSub * height() / 2) - 1.0));
  }

  // Adds the triangles' exact coverage to `counts` (one entry per pixel, bottom row first).
  void add_exact(std::vector<uint8_t>& counts, SubPoint a, SubPoint b, SubPoint c) const {
    for (int y = 0; y < height(); ++y)
      for (int x = 0; x < width(); ++x) counts[size_t(y) * width() + x] += exact_covers(a, b, c, x, y);
  }

  std::vector<uint8_t> zero_counts() const { return std::vector<uint8_t>(size_t(width()) * height(), 0); }

  static int mismatches(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    int n = 0;
    for (size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
    return n;
  }
  static int total(const std::vector<uint8_t>& h) {
    int n = 0;
    for (uint8_t v : h) n += v;
    return n;
  }
};

}  // namespace pineda::test
