// Coordinates far outside the viewport, vertices behind the eye, NaN and infinity: the
// visible part is exactly the analytic coverage and nothing else is drawn.
#include <cfloat>
#include <cmath>
#include <limits>
#include <random>

#include "tests/stability/case_table.h"
#include "tests/stability/coverage_count.h"

namespace pineda::test {
namespace {

using ExtremeCoordinates = CoverageCountTest;

// Two triangles share the vertical edge x = 20.5 (through pixel centres) and reach out to
// `far` in every other direction: every pixel is hit once, the columns left of the edge by
// the left triangle.
TEST_F(ExtremeCoordinates, HugeTrianglesShareAnEdgeExactly) {
  for (double far : {1e4, 1e6, 1e8, 1e30, double(FLT_MAX)}) {
    begin_counting();
    glBegin(GL_TRIANGLES);
    glVertex2d(20.5, -far);
    glVertex2d(20.5, far);
    glVertex2d(-far, 0);
    glEnd();
    std::vector<uint8_t> left = hits();
    glBegin(GL_TRIANGLES);
    glVertex2d(20.5, far);
    glVertex2d(20.5, -far);
    glVertex2d(far, 0);
    glEnd();
    expect_case("shared edge, far " + case_text(far) + ": pixels not hit once", 0, count_not(1));
    int wrong = 0;
    for (int y = 0; y < height(); ++y)
      for (int x = 0; x < width(); ++x) {
        if (x == 20) continue;  // on the shared edge: the fill rule picks one side
        wrong += left[size_t(y) * width() + x] != (x < 20 ? 1 : 0);
      }
    expect_case("shared edge, far " + case_text(far) + ": pixels on the wrong side", 0, wrong);
  }
}

// Homogeneous triangles with vertices behind the eye (w < 0): a pixel centre (X, Y) in NDC is
// covered when (X, Y, 1) is a positive combination of the vertices' (x, y, w).
TEST_F(ExtremeCoordinates, TrianglesCrossingWZeroMatchTheAnalyticCoverage) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> coord(-3, 3), wdist(-1.5, 2);
  int checked = 0;
  for (int t = 0; t < 40; ++t) {
    double v[3][3];
    for (auto& p : v) p[0] = coord(rng), p[1] = coord(rng), p[2] = wdist(rng);
    if (v[0][2] > 0 && v[1][2] > 0 && v[2][2] > 0) v[t % 3][2] = -0.5;  // always cross w = 0
    begin_counting();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glBegin(GL_TRIANGLES);
    for (auto& p : v) glVertex4d(p[0], p[1], 0.0, p[2]);
    glEnd();
    const std::vector<uint8_t> h = hits();
    // Cramer's rule on the columns (x, y, w) of the three vertices.
    auto det3 = [](const double m[3][3]) {
      return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    double m[3][3];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m[r][c] = v[c][r];
    const double d = det3(m);
    if (std::abs(d) < 1e-6) continue;
    int wrong = 0;
    for (int y = 0; y < height(); ++y)
      for (int x = 0; x < width(); ++x) {
        const double target[3] = {2 * (x + 0.5) / width() - 1, 2 * (y + 0.5) / height() - 1, 1};
        double lambda[3], min_margin = 1e9;
        bool inside = true;
        for (int c = 0; c < 3; ++c) {
          double mc[3][3];
          for (int r = 0; r < 3; ++r)
            for (int k = 0; k < 3; ++k) mc[r][k] = k == c ? target[r] : m[r][k];
          lambda[c] = det3(mc) / d;
          inside = inside && lambda[c] > 0;
          min_margin = std::min(min_margin, std::abs(lambda[c]));
        }
        if (min_margin < 1e-3) continue;  // too close to an edge for a float reference
        ++checked;
        wrong += h[size_t(y) * width() + x] != (inside ? 1 : 0);
      }
    expect_case("crossing w = 0, triangle " + std::to_string(t) + ": pixels off the analytic coverage", 0, wrong);
  }
  EXPECT_GT(checked, 40 * 1000);  // the reference decided enough pixels
}

// w of 1e-30 and denormals: the vertex is at a huge distance; nothing crashes and the
// visible part is a half-plane through the other two vertices.
TEST_F(ExtremeCoordinates, TinyWIsAFarAwayVertex) {
  for (float w : {1e-30f, 1e-40f /* denormal */, FLT_MIN}) {
    begin_counting();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glBegin(GL_TRIANGLES);
    glVertex4f(0.0f, -1.0f, 0.0f, 1.0f);  // the edge x = 0 in NDC: window x = 48
    glVertex4f(0.0f, 1.0f, 0.0f, 1.0f);
    glVertex4f(-1.0f, 0.0f, 0.0f, w);  // x / w: minus a huge number
    glEnd();
    const std::vector<uint8_t> h = hits();
    int wrong = 0;
    for (int y = 0; y < height(); ++y)
      for (int x = 0; x < width(); ++x)
        if (x != 47 && x != 48) wrong += h[size_t(y) * width() + x] != (x < 47 ? 1 : 0);
    expect_case("w = " + case_text(w) + ": pixels off the half-plane", 0, wrong);
  }
}

TEST_F(ExtremeCoordinates, NanOrInfinityDropsOnlyThatPrimitive) {
  const float bad[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                       -std::numeric_limits<float>::infinity()};
  for (float b : bad)
    for (int component = 0; component < 4; ++component) {
      begin_counting();
      float v[4] = {10, 10, 0, 1};
      v[component] = b;
      glBegin(GL_TRIANGLES);
      glVertex4fv(v);
      glVertex4f(90, 10, 0, 1);
      glVertex4f(50, 70, 0, 1);
      glVertex4f(0, 0, 0, 1);  // an ordinary triangle in the same draw still renders
      glVertex4f(10, 0, 0, 1);
      glVertex4f(0, 10, 0, 1);
      glEnd();
      const std::vector<uint8_t> h = hits();
      int total = 0;
      for (uint8_t x : h) total += x;
      // The right isosceles triangle of legs 10: 45 centres strictly inside; the 10 centres on
      // its hypotenuse lie on a right edge, which the top-left rule leaves out.
      expect_case("position component " + std::to_string(component) + " = " + case_text(b) + ": fragments (only the good triangle)", 45, total);
      EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    }
}

}  // namespace
}  // namespace pineda::test
