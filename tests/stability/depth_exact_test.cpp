// Depth against exact values: the interpolated depth of a receding plane is within one unit
// of the exact window depth for 16, 24 and 32-bit buffers and near/far ratios up to 1e7, and
// polygon offset at steep slopes moves depth by exactly factor * max slope + units.
#include <GL/gl.h>

#include <cmath>
#include <string>
#include <vector>

#include "tests/stability/case_table.h"
#include "tests/stability/coverage_count.h"
#include "tests/stability/perspective_plane.h"

namespace pineda::test {
namespace {

class DepthExact : public CoverageCountTest, public ::testing::WithParamInterface<int> {
 protected:
  SurfaceSpec spec() const override { return {128, 64, GetParam(), 8}; }
  double depth_units() const { return GetParam() >= 32 ? 4294967295.0 : std::ldexp(1.0, GetParam()) - 1; }

  // The depth buffer in depth-buffer units, bottom row first.
  std::vector<double> read_depth() {
    std::vector<GLuint> raw(size_t(width()) * height());
    glReadPixels(0, 0, width(), height(), GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, raw.data());
    std::vector<double> out(raw.size());
    // GL_UNSIGNED_INT is the [0, 1] value times 2^32 - 1; back to the buffer's own units.
    for (size_t i = 0; i < raw.size(); ++i) out[i] = std::nearbyint(raw[i] / 4294967295.0 * depth_units());
    return out;
  }

  void identity_matrices() {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
  }
};

TEST_P(DepthExact, InterpolatedDepthWithinOneUnitOfExact) {
  for (double ratio : {1e2, 1e4, 1e7}) {
    const double n = 0.01, f = n * ratio;
    const auto q = receding_plane(n, f);
    identity_matrices();
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glBegin(GL_TRIANGLES);
    for (int i : {0, 1, 2, 0, 2, 3}) glVertex4f(q[i].x, q[i].y, q[i].z, q[i].w);
    glEnd();
    glDisable(GL_DEPTH_TEST);
    const std::vector<double> got = read_depth();
    const ClipVertex4* tris[2][3] = {{&q[0], &q[1], &q[2]}, {&q[0], &q[2], &q[3]}};
    double max_error = 0;
    int checked = 0;
    for (int y = 0; y < height(); ++y)
      for (int x = 0; x < width(); ++x) {
        const double px = x + 0.5, py = y + 0.5;
        // Near the shared diagonal the float vertices leave the two planes a hair apart:
        // either triangle's value is exact for the pixel it covers.
        double best = 1e300;
        for (const auto& t : tris) {
          const Weights w = screen_weights(*t[0], *t[1], *t[2], width(), height(), px, py);
          if (!w.inside(1e-6L)) continue;
          const long double z = std::clamp(window_depth(t, w), 0.0L, 1.0L) * depth_units();
          best = std::min(best, double(std::fabs((long double)got[size_t(y) * width() + x] - z)));
        }
        if (best == 1e300) continue;
        ++checked;
        max_error = std::max(max_error, best);
      }
    const std::string name = std::to_string(GetParam()) + "-bit depth, near/far " + case_text(ratio);
    expect_case(name + ": pixels checked", width() * height(), checked);
    expect_case_at_most(name + ": max |depth - exact| in units", 1.0, max_error);
  }
}

// A plane steep in x (1/256 or 1/8192 of the depth range per pixel): drawn again
// with glPolygonOffset(factor, units) its depth moves by factor * |dz/dx| + 2 * units (one unit,
// the smallest resolvable difference, is two depth steps, as llvmpipe's), and with a
// negative offset it passes GL_LESS everywhere, with a positive one nowhere.
TEST_P(DepthExact, PolygonOffsetAtSteepSlopes) {
  for (double per_pixel_share : {1.0 / 256, 1.0 / 8192}) {
    const double slope = per_pixel_share * depth_units();  // units per pixel, in x
    // z_window = 0.25 + share * x_window: NDC z = 2 z_window - 1 at NDC x = +-1.
    const double z_left = 2 * 0.25 - 1, z_right = 2 * (0.25 + per_pixel_share * width()) - 1;
    auto draw = [&] {
      glBegin(GL_QUADS);
      glVertex3d(-1, -1, z_left), glVertex3d(1, -1, z_right), glVertex3d(1, 1, z_right), glVertex3d(-1, 1, z_left);
      glEnd();
    };
    for (const auto& [factor, units] : {std::pair{1.0, 0.0}, {2.0, 3.0}, {0.5, 100.0}}) {
      begin_counting();
      identity_matrices();
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_ALWAYS);
      draw();
      const std::vector<double> base = read_depth();
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(float(factor), float(units));
      draw();
      const std::vector<double> offset = read_depth();
      const double expected = factor * slope + 2 * units;
      double max_error = 0;
      for (size_t i = 0; i < base.size(); ++i) max_error = std::max(max_error, std::fabs(offset[i] - base[i] - expected));
      const std::string name = std::to_string(GetParam()) + "-bit depth, slope " + case_text(slope) + " units/px, offset(" +
                               case_text(factor) + ", " + case_text(units) + ")";
      expect_case_at_most(name + ": max |moved - (factor * slope + 2 units)|", 1.0, max_error);

      // The base plane again, then both offset copies with GL_LESS; the stencil counts passes.
      glClear(GL_STENCIL_BUFFER_BIT);
      glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
      glPolygonOffset(0, 0);
      glDepthFunc(GL_ALWAYS);
      draw();
      glDepthFunc(GL_LESS);
      glDepthMask(GL_FALSE);
      glPolygonOffset(float(-factor), float(-units));
      draw();
      glPolygonOffset(float(factor), float(units));
      draw();
      glDepthMask(GL_TRUE);
      glDisable(GL_POLYGON_OFFSET_FILL);
      glDisable(GL_DEPTH_TEST);
      // 1 (ALWAYS) + 1 (pulled forward) + 0 (pushed back).
      expect_case(name + ": pixels where only the forward copy passed GL_LESS", width() * height(),
                  width() * height() - count_not(2));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Bits, DepthExact, ::testing::Values(16, 24, 32));

}  // namespace
}  // namespace pineda::test
