// The reference mode (PINEDA_REFERENCE=1, read when a context is created): per-pixel double
// precision edge functions must keep the fill rule's guarantees (every pixel of a fan once),
// and for vertices on the sub-pixel grid its coverage equals the exact integer coverage.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>
#include <cstdlib>
#include <random>
#include <string>

#include "tests/stability/case_table.h"
#include "tests/stability/exact_coverage.h"

namespace pineda::test {
namespace {

class ReferenceMode : public ExactCoverageTest {
 protected:
  void SetUp() override {
    setenv("PINEDA_REFERENCE", "1", 1);
    ExactCoverageTest::SetUp();
    unsetenv("PINEDA_REFERENCE");
  }
};

TEST_F(ReferenceMode, FanOfThinTrianglesHitsEveryPixelOnce) {
  for (const auto& [cx, cy] : {std::pair{40.37, 33.81}, {64.0, 32.0}, {63.5, 31.5}}) {
    begin_counting();
    glBegin(GL_TRIANGLE_FAN);
    glVertex2d(cx, cy);
    const int n = 1000;
    for (int i = 0; i <= n; ++i) {
      const double a = 2 * 3.14159265358979323846 * (i % n) / n;
      glVertex2d(cx + 400 * std::cos(a), cy + 400 * std::sin(a));
    }
    glEnd();
    expect_case("reference mode, fan of 1000 around (" + case_text(cx) + ", " + case_text(cy) + "): pixels not hit once",
                0, count_not(1));
  }
}

TEST_F(ReferenceMode, GridVerticesGiveTheExactCoverage) {
  std::mt19937 rng(31);
  std::uniform_int_distribution<int64_t> coord(-20 * kSub, 150 * kSub);
  int equal = 0;
  for (int t = 0; t < 40; ++t) {
    const SubPoint a{coord(rng), coord(rng) / 2}, b{coord(rng), coord(rng) / 2}, c{coord(rng), coord(rng) / 2};
    begin_exact_counting();
    glBegin(GL_TRIANGLES);
    vertex(a), vertex(b), vertex(c);
    glEnd();
    std::vector<uint8_t> expected = zero_counts();
    add_exact(expected, a, b, c);
    equal += mismatches(expected, hits()) == 0;
  }
  expect_case("reference mode, 40 random grid triangles: pixel maps equal to the exact coverage", 40, equal);
}

// Occlusion queries count the reference path's fragments: triangles (a 20x10 rectangle is
// 200) and lines (a 30-pixel horizontal line), with depth rejecting a second copy.
TEST_F(ReferenceMode, OcclusionQueryCountsReferenceFragments) {
  pixel_projection();
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  GLuint q = 0;
  glGenQueries(1, &q);
  glBeginQuery(GL_SAMPLES_PASSED, q);
  glRecti(10, 10, 30, 20);
  glRecti(10, 10, 30, 20);  // same depth, GL_LESS: rejected
  glBegin(GL_LINES);
  glVertex2f(40, 40.5f), glVertex2f(70, 40.5f);
  glEnd();
  glEndQuery(GL_SAMPLES_PASSED);
  GLuint passed = 0;
  glGetQueryObjectuiv(q, GL_QUERY_RESULT, &passed);
  glDeleteQueries(1, &q);
  glDisable(GL_DEPTH_TEST);
  expect_case("reference mode, occlusion query: samples passed", 230u, passed);
}

}  // namespace
}  // namespace pineda::test
