// The fill rule: edges and vertices exactly on pixel centres belong to exactly one triangle,
// for horizontal, vertical and diagonal edges, both windings, in all four quadrants.
#include <random>

#include "tests/stability/case_table.h"
#include "tests/stability/coverage_count.h"

namespace pineda::test {
namespace {

using FillRule = CoverageCountTest;

// A mesh whose vertices are pixel centres (all edges run through pixel centres), spanning
// beyond the viewport on every side, each cell split along a random diagonal and each
// triangle given a random winding.
void draw_centre_mesh(std::mt19937& rng, int w, int h, int step, double origin_x, double origin_y) {
  glBegin(GL_TRIANGLES);
  for (int j = -2; j * step <= h + 2 * step; ++j)
    for (int i = -2; i * step <= w + 2 * step; ++i) {
      const double x0 = origin_x + i * step + 0.5, y0 = origin_y + j * step + 0.5;
      const double x1 = x0 + step, y1 = y0 + step;
      const double split_a[2][3][2] = {{{x0, y0}, {x1, y0}, {x1, y1}}, {{x0, y0}, {x1, y1}, {x0, y1}}};
      const double split_b[2][3][2] = {{{x0, y0}, {x1, y0}, {x0, y1}}, {{x1, y0}, {x1, y1}, {x0, y1}}};
      for (const auto& t : (rng() & 1) ? split_a : split_b) {
        const bool reverse = rng() & 1;
        for (int k = 0; k < 3; ++k) {
          const auto& v = t[reverse ? 2 - k : k];
          glVertex2d(v[0], v[1]);
        }
      }
    }
  glEnd();
}

TEST_F(FillRule, EdgesThroughPixelCentresHitEveryPixelOnce) {
  std::mt19937 rng(9);
  for (int step : {1, 2, 5, 16}) {
    begin_counting();
    draw_centre_mesh(rng, width(), height(), step, -step, -step);
    expect_case("centre mesh, step " + std::to_string(step) + ": pixels not hit once", 0, count_not(1));
  }
}

// The same mesh with the window origin in the middle of the viewport, so that the mesh
// spans all four quadrants of eye space.
TEST_F(FillRule, AllFourQuadrants) {
  std::mt19937 rng(11);
  begin_counting();
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-width() / 2, width() / 2, -height() / 2, height() / 2, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  draw_centre_mesh(rng, width(), height(), 3, -width() / 2 - 6, -height() / 2 - 6);
  expect_case("centre mesh in four quadrants: pixels not hit once", 0, count_not(1));
}

// A lone pixel-aligned square from pixel corner to pixel corner covers exactly its pixels,
// whichever of its four corners the triangles' shared diagonal uses.
TEST_F(FillRule, PixelAlignedSquareCoversExactlyItsPixels) {
  for (bool other_diagonal : {false, true}) {
    begin_counting();
    glBegin(GL_TRIANGLES);
    if (other_diagonal) {
      glVertex2i(10, 20); glVertex2i(30, 20); glVertex2i(10, 35);
      glVertex2i(30, 20); glVertex2i(30, 35); glVertex2i(10, 35);
    } else {
      glVertex2i(10, 20); glVertex2i(30, 20); glVertex2i(30, 35);
      glVertex2i(10, 20); glVertex2i(30, 35); glVertex2i(10, 35);
    }
    glEnd();
    const std::vector<uint8_t> h = hits();
    int wrong = 0;
    for (int y = 0; y < height(); ++y)
      for (int x = 0; x < width(); ++x)
        wrong += h[size_t(y) * width() + x] != ((x >= 10 && x < 30 && y >= 20 && y < 35) ? 1 : 0);
    expect_case(std::string("rectangle split ") + (other_diagonal ? "/" : "\\") + ": pixels off [10,30)x[20,35)", 0, wrong);
  }
}

// Slivers and degenerates: zero-area and nearly zero-area triangles hit nothing or a few
// pixels, never a pixel twice; repeated and collinear vertices hit nothing.
TEST_F(FillRule, DegenerateTrianglesHitNothing) {
  begin_counting();
  glBegin(GL_TRIANGLES);
  glVertex2d(5.5, 5.5); glVertex2d(5.5, 5.5); glVertex2d(5.5, 5.5);     // one point
  glVertex2d(1.5, 1.5); glVertex2d(40.5, 40.5); glVertex2d(20.5, 20.5);  // collinear through centres
  glVertex2d(0, 10.5); glVertex2d(90, 10.5); glVertex2d(45, 10.5);       // a horizontal line through centres
  glEnd();
  expect_case("point, collinear and flat triangles: pixels hit", 0, count_not(0));
}

TEST_F(FillRule, SliverBelowOneSubpixelSquaredHitsAtMostALine) {
  begin_counting();
  glBegin(GL_TRIANGLES);
  glVertex2d(0.1, 10.3); glVertex2d(95.9, 10.3 + 1.0 / 65536); glVertex2d(50.2, 10.3 + 1.0 / 131072);
  glEnd();
  const std::vector<uint8_t> h = hits();
  int total = 0;
  for (uint8_t x : h) total += x;
  expect_case("sliver collinear after snapping: fragments", 0, total);  // after snapping to 1/256 the three vertices are collinear
}

}  // namespace
}  // namespace pineda::test
