// Depth precision: with near/far ratios up to 1e7 and 16, 24 or 32-bit depth, drawing the
// same geometry again with GL_LEQUAL passes on every pixel (the pipeline is exactly
// repeatable), and a front surface hides a back one that is far enough behind.
#include <random>

#include "tests/stability/case_table.h"
#include "tests/stability/coverage_count.h"

namespace pineda::test {
namespace {

class DepthPrecision : public CoverageCountTest, public ::testing::WithParamInterface<int> {
 protected:
  SurfaceSpec spec() const override { return {96, 80, GetParam(), 8}; }

  void perspective(double near_z, double far_z) {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-near_z, near_z, -near_z, near_z, near_z, far_z);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
  }

  // A jittered mesh covering the view, its vertices at random depths in [near, far].
  void draw_mesh(unsigned seed, double near_z, double far_z) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> depth(near_z * 1.01, far_z * 0.99), jitter(-0.3, 0.3);
    const int n = 12;
    std::vector<double> zs((n + 1) * (n + 1)), js((n + 1) * (n + 1) * 2);
    for (auto& z : zs) z = depth(rng);
    for (auto& j : js) j = jitter(rng);
    auto vertex = [&](int i, int k) {
      const int idx = k * (n + 1) + i;
      const bool border = i == 0 || k == 0 || i == n || k == n;
      const double x = -1.2 + 2.4 * (i + (border ? 0 : js[2 * idx])) / n;
      const double y = -1.2 + 2.4 * (k + (border ? 0 : js[2 * idx + 1])) / n;
      const double z = zs[idx];
      glVertex3d(x * z, y * z, -z);
    };
    glBegin(GL_TRIANGLES);
    for (int k = 0; k < n; ++k)
      for (int i = 0; i < n; ++i) {
        vertex(i, k); vertex(i + 1, k); vertex(i + 1, k + 1);
        vertex(i, k); vertex(i + 1, k + 1); vertex(i, k + 1);
      }
    glEnd();
  }
};

TEST_P(DepthPrecision, CoplanarRedrawWithLequalPassesEverywhere) {
  for (double ratio : {1e2, 1e4, 1e7}) {
    begin_counting();
    glEnable(GL_DEPTH_TEST);
    const double near_z = 0.01, far_z = near_z * ratio;
    perspective(near_z, far_z);
    glDepthFunc(GL_LESS);
    draw_mesh(5, near_z, far_z);
    glStencilFunc(GL_EQUAL, 1, 0xff);  // the second pass counts only where the first one hit
    glDepthFunc(GL_LEQUAL);
    draw_mesh(5, near_z, far_z);
    glDisable(GL_DEPTH_TEST);
    expect_case("coplanar LEQUAL redraw, " + std::to_string(GetParam()) + "-bit depth, near/far " + case_text(ratio) + ": pixels not passing twice", 0, count_not(2));
  }
}

TEST_P(DepthPrecision, GreaterEqualRedrawPassesEverywhereToo) {
  begin_counting();
  glEnable(GL_DEPTH_TEST);
  perspective(0.1, 1000);
  glDepthFunc(GL_ALWAYS);
  draw_mesh(8, 0.1, 1000);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glDepthFunc(GL_GEQUAL);
  draw_mesh(8, 0.1, 1000);
  glDisable(GL_DEPTH_TEST);
  expect_case("GEQUAL redraw, " + std::to_string(GetParam()) + "-bit depth: pixels not passing twice", 0, count_not(2));
}

INSTANTIATE_TEST_SUITE_P(Bits, DepthPrecision, ::testing::Values(16, 24, 32));

}  // namespace
}  // namespace pineda::test
