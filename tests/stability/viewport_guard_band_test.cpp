// Viewports from 1x1 to the largest GL_MAX_VIEWPORT_DIMS allows, and the largest triangles
// the guard band rasterizes without clipping: exact coverage against exact_coverage.h.
#include <GL/gl.h>

#include <string>

#include "tests/stability/case_table.h"
#include "tests/stability/exact_coverage.h"

namespace pineda::test {
namespace {

using Viewports = ExactCoverageTest;

struct ViewportCase {
  int x, y, w, h;
};

// NDC coordinate k / 1024 maps to window vp + (k / 1024 + 1) * size / 2: with k a multiple of
// 8 that is a whole number of sub-pixels for any size (size * (k + 1024) / 8 sub-pixels).
int64_t window_sub(int origin, int size, int k) { return origin * kSub + int64_t{size} * (k + 1024) / 8; }

TEST_F(Viewports, FromOneByOneToTheMaximumCoverExactly) {
  GLint max_dims[2] = {0, 0};
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, max_dims);
  ASSERT_GE(max_dims[0], 4096);
  const ViewportCase cases[] = {{5, 7, 1, 1},     {60, 30, 2, 3},   {3, 4, 17, 13},  {0, 0, 128, 64},
                                {-9, -5, 150, 77}, {-1000, -2000, max_dims[0], max_dims[1]},
                                {-max_dims[0] + 100, -max_dims[1] + 40, max_dims[0], max_dims[1]}};
  // A triangle with vertices at NDC multiples of 8/1024, and the full NDC square.
  const int tri[3][2] = {{-1016, -984}, {1008, -200}, {-96, 1000}};
  for (const ViewportCase& v : cases) {
    begin_exact_counting();
    glViewport(v.x, v.y, v.w, v.h);
    glBegin(GL_TRIANGLES);
    for (const auto& p : tri) glVertex2f(p[0] / 1024.f, p[1] / 1024.f);
    glEnd();
    SubPoint s[3];
    for (int i = 0; i < 3; ++i) s[i] = {window_sub(v.x, v.w, tri[i][0]), window_sub(v.y, v.h, tri[i][1])};
    std::vector<uint8_t> expected = zero_counts();
    // The viewport also bounds what is drawn (the triangle is inside NDC, so it does anyway).
    add_exact(expected, s[0], s[1], s[2]);
    const std::string name = "viewport " + std::to_string(v.w) + "x" + std::to_string(v.h) + " at (" +
                             std::to_string(v.x) + "," + std::to_string(v.y) + ")";
    expect_case(name + ", triangle: pixels off the exact coverage", 0, mismatches(expected, hits()));

    begin_exact_counting();
    glViewport(v.x, v.y, v.w, v.h);
    glRectf(-1, -1, 1, 1);
    int wrong = 0;
    const std::vector<uint8_t> h = hits();
    for (int y = 0; y < height(); ++y)
      for (int x = 0; x < width(); ++x) {
        const bool inside = x >= v.x && x < v.x + v.w && y >= v.y && y < v.y + v.h;
        wrong += h[size_t(y) * width() + x] != (inside ? 1 : 0);
      }
    expect_case(name + ", full NDC square: pixels not hit exactly inside the viewport", 0, wrong);
  }
  glViewport(0, 0, width(), height());
}

using GuardBand = ExactCoverageTest;

// Triangles whose vertices reach the guard band's edge (+-32768 px, inclusive) are rasterized
// directly, with exact edge functions: their coverage is the exact one.
TEST_F(GuardBand, LargestTrianglesInsideTheBandCoverExactly) {
  constexpr int64_t kBand = 32768 * kSub;
  const SubPoint sets[][3] = {
      {{-kBand, -kBand}, {kBand, -kBand + 40 * kSub + 3}, {64 * kSub + 1, kBand}},
      {{-kBand, kBand}, {kBand, kBand - 1}, {-kBand + 5, -kBand}},  // an edge just above y = 32767.996
      {{-kBand, 20 * kSub + 128}, {kBand, 40 * kSub + 128}, {kBand, -kBand}},  // edges through centres
      {{-kBand + 1, -kBand + 3}, {kBand - 7, 31 * kSub + 1}, {-kBand + 11, kBand - 13}},
  };
  int index = 0;
  for (const auto& t : sets) {
    begin_exact_counting();
    glBegin(GL_TRIANGLES);
    vertex(t[0]), vertex(t[1]), vertex(t[2]);
    glEnd();
    std::vector<uint8_t> expected = zero_counts();
    add_exact(expected, t[0], t[1], t[2]);
    expect_case("guard-band triangle " + std::to_string(index++) + " (" + std::to_string(total(expected)) +
                    " pixels): pixels off the exact coverage",
                0, mismatches(expected, hits()));
  }
}

}  // namespace
}  // namespace pineda::test
