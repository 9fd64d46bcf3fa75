// Slivers and degenerates: triangles of area below 1/65536 px², collinear and repeated
// vertices, each against the exact integer coverage of exact_coverage.h.
#include <cstdlib>
#include <tuple>
#include <random>
#include <string>

#include "tests/stability/case_table.h"
#include "tests/stability/exact_coverage.h"

namespace pineda::test {
namespace {

using Slivers = ExactCoverageTest;

// (c, d) with a * d - b * c = 1, for coprime a, b > 0 (extended Euclid).
std::pair<int64_t, int64_t> unit_partner(int64_t a, int64_t b) {
  int64_t r0 = a, r1 = b, s0 = 1, s1 = 0, t0 = 0, t1 = 1;
  while (r1 != 0) {
    const int64_t q = r0 / r1;
    std::tie(r0, r1) = std::pair{r1, r0 - q * r1};
    std::tie(s0, s1) = std::pair{s1, s0 - q * s1};
    std::tie(t0, t1) = std::pair{t1, t0 - q * t1};
  }
  // a * s0 + b * t0 = 1, so (c, d) = (-t0, s0).
  return {-t0, s0};
}

int64_t gcd(int64_t a, int64_t b) { return b == 0 ? a : gcd(b, a % b); }

// Long slivers of area 1/131072 px² (twice the area is one sub-pixel²), starting on pixel
// centres, in every direction: the pixels they hit are exactly the reference's.
TEST_F(Slivers, AreaBelowOneSubpixelSquaredMatchesTheExactCoverage) {
  std::mt19937 rng(2024);
  std::uniform_int_distribution<int64_t> len(256, 110 * 256), px(2, 125), py(2, 61);
  int compared = 0, hit_total = 0;
  for (int t = 0; t < 48; ++t) {
    int64_t a = len(rng), b = len(rng) / 2;
    while (gcd(a, b) != 1) ++b;
    const auto [c, d] = unit_partner(a, b);
    const int sx = t & 1 ? -1 : 1, sy = t & 2 ? -1 : 1;
    const bool swap_axes = t & 4;
    auto dir = [&](int64_t u, int64_t v) {
      return swap_axes ? SubPoint{sx * v, sy * u} : SubPoint{sx * u, sy * v};
    };
    const SubPoint p0 = centre_of(int(px(rng)), int(py(rng)));
    const SubPoint du = dir(a, b), dv = dir(c, d);
    const SubPoint p1{p0.x + du.x, p0.y + du.y}, p2{p0.x + dv.x, p0.y + dv.y};
    ASSERT_EQ(std::llabs(du.x * dv.y - dv.x * du.y), 1);
    begin_exact_counting();
    glBegin(GL_TRIANGLES);
    vertex(p0), vertex(p1), vertex(p2);
    glEnd();
    std::vector<uint8_t> expected = zero_counts();
    add_exact(expected, p0, p1, p2);
    const std::vector<uint8_t> got = hits();
    compared += mismatches(expected, got) == 0;
    hit_total += total(got);
    expect_case("sliver " + std::to_string(t) + " (twice the area 1 sub-pixel²): fragments", total(expected), total(got));
  }
  expect_case("48 slivers: pixel maps equal to the exact coverage", 48, compared);
  RecordProperty("sliver fragments", hit_total);
}

// Collinear and repeated vertices: degenerate triangles add nothing, and a quad or polygon
// with a repeated or collinear vertex covers exactly what the remaining triangle covers.
TEST_F(Slivers, CollinearAndRepeatedVerticesAddNothing) {
  const SubPoint a{10 * kSub + 128, 5 * kSub + 38}, b{100 * kSub + 4, 9 * kSub + 128}, c{40 * kSub + 200, 58 * kSub};
  const SubPoint ab_mid{(a.x + b.x) / 2, (a.y + b.y) / 2};  // exactly on ab: a.x + b.x and a.y + b.y are even
  ASSERT_EQ((a.x + b.x) % 2 + (a.y + b.y) % 2, 0);
  std::vector<uint8_t> expected = zero_counts();
  add_exact(expected, a, b, c);

  begin_exact_counting();
  glBegin(GL_QUADS);  // split (a, b, b), (a, b, c)
  vertex(a), vertex(b), vertex(b), vertex(c);
  glEnd();
  expect_case("quad with a repeated vertex: pixels off the triangle's coverage", 0, mismatches(expected, hits()));

  begin_exact_counting();
  glBegin(GL_POLYGON);  // a collinear vertex in the middle of an edge
  vertex(a), vertex(ab_mid), vertex(b), vertex(c);
  glEnd();
  expect_case("polygon with a collinear vertex: pixels off the triangle's coverage", 0, mismatches(expected, hits()));

  begin_exact_counting();
  glBegin(GL_TRIANGLE_STRIP);  // strip stitching: (a, b, c), then degenerate (b, c, c), (c, c, a)
  vertex(a), vertex(b), vertex(c), vertex(c), vertex(a);
  glEnd();
  expect_case("strip with repeated vertices: pixels off the triangle's coverage", 0, mismatches(expected, hits()));

  begin_exact_counting();
  glBegin(GL_TRIANGLES);
  vertex(a), vertex(ab_mid), vertex(b);  // collinear
  vertex(c), vertex(c), vertex(a);       // repeated
  vertex(c), vertex(c), vertex(c);       // a point
  glEnd();
  expect_case("collinear, repeated and single-point triangles: fragments", 0, total(hits()));
}

}  // namespace
}  // namespace pineda::test
