// Watertightness: meshes that cover the whole viewport hit every pixel exactly once.
#include <cmath>
#include <random>

#include "tests/stability/case_table.h"
#include "tests/stability/coverage_count.h"

namespace pineda::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

class Watertight : public CoverageCountTest {
 protected:
  // A fan of `n` thin triangles around (cx, cy) whose rim lies far outside the viewport.
  void draw_fan(double cx, double cy, int n) {
    glBegin(GL_TRIANGLE_FAN);
    glVertex2d(cx, cy);
    for (int i = 0; i <= n; ++i) {
      const double a = 2 * kPi * (i % n) / n;
      glVertex2d(cx + 400 * std::cos(a), cy + 400 * std::sin(a));
    }
    glEnd();
  }
};

TEST_F(Watertight, FanAroundSubpixelCentreHitsEveryPixelOnce) {
  for (const auto& [cx, cy] : {std::pair{40.37, 33.81}, {10.001, 70.999}, {48.0, 40.0}, {47.5, 39.5}}) {
    begin_counting();
    draw_fan(cx, cy, 1000);
    expect_case("fan of 1000 around (" + case_text(cx) + ", " + case_text(cy) + "): pixels not hit once", 0, count_not(1));
  }
}

TEST_F(Watertight, FanBothWindingsHitsEveryPixelOnce) {
  begin_counting();
  glBegin(GL_TRIANGLES);  // the same fan, clockwise: culling is off, so it must still be watertight
  const int n = 1200;
  for (int i = 0; i < n; ++i) {
    const double a0 = 2 * kPi * i / n, a1 = 2 * kPi * ((i + 1) % n) / n;
    glVertex2d(31.25, 17.5);
    glVertex2d(31.25 + 400 * std::cos(a1), 17.5 + 400 * std::sin(a1));
    glVertex2d(31.25 + 400 * std::cos(a0), 17.5 + 400 * std::sin(a0));
  }
  glEnd();
  expect_case("clockwise fan of 1200: pixels not hit once", 0, count_not(1));
}

TEST_F(Watertight, JitteredGridWithBothDiagonalsHitsEveryPixelOnce) {
  std::mt19937 rng(1234);
  // At most 0.15 of a cell per axis keeps every quad convex, so neither diagonal folds.
  std::uniform_real_distribution<double> jitter(-0.15, 0.15);
  for (double cell : {1.0, 3.7, 11.3}) {
    begin_counting();
    const int nx = int(std::ceil(width() / cell)) + 3, ny = int(std::ceil(height() / cell)) + 3;
    std::vector<double> xs(nx * ny), ys(nx * ny);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const bool border = i == 0 || j == 0 || i == nx - 1 || j == ny - 1;
        xs[j * nx + i] = (i - 1) * cell + (border ? 0 : jitter(rng) * cell);
        ys[j * nx + i] = (j - 1) * cell + (border ? 0 : jitter(rng) * cell);
      }
    glBegin(GL_TRIANGLES);
    for (int j = 0; j + 1 < ny; ++j)
      for (int i = 0; i + 1 < nx; ++i) {
        const int a = j * nx + i, b = a + 1, c = a + nx + 1, d = a + nx;
        const int tri[2][3] = {{a, b, c}, {a, c, d}};
        const int alt[2][3] = {{a, b, d}, {b, c, d}};
        for (const auto& t : (rng() & 1) ? tri : alt) {
          for (int v : t) glVertex2d(xs[v], ys[v]);
        }
      }
    glEnd();
    expect_case("jittered grid, cell " + case_text(cell) + ": pixels not hit once", 0, count_not(1));
  }
}

// A square rotated in 1 degree steps: no pixel is hit twice, pixels well inside are hit
// once and pixels well outside never.
TEST_F(Watertight, RotatedQuadInOneDegreeSteps) {
  const double cx = 48.3, cy = 40.1, half = 25.0;
  for (int degrees = 0; degrees < 90; ++degrees) {
    begin_counting();
    const double a = degrees * kPi / 180, c = std::cos(a), s = std::sin(a);
    auto corner = [&](double u, double v) { glVertex2d(cx + c * u - s * v, cy + s * u + c * v); };
    glBegin(GL_QUADS);
    corner(-half, -half);
    corner(half, -half);
    corner(half, half);
    corner(-half, half);
    glEnd();
    const std::vector<uint8_t> h = hits();
    int wrong = 0;
    for (int y = 0; y < height(); ++y)
      for (int x = 0; x < width(); ++x) {
        const double px = x + 0.5 - cx, py = y + 0.5 - cy;
        const double u = c * px + s * py, v = -s * px + c * py;  // pixel centre in the quad's frame
        const double inside = half - std::max(std::abs(u), std::abs(v));
        const uint8_t got = h[size_t(y) * width() + x];
        if (got > 1 || (inside > 0.01 && got != 1) || (inside < -0.01 && got != 0)) ++wrong;
      }
    expect_case("quad rotated " + std::to_string(degrees) + " degrees: pixels wrong", 0, wrong);
  }
}

}  // namespace
}  // namespace pineda::test
