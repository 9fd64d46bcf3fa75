// Antialiased points and lines: the area coverage functions, and the alpha they give fragments.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>

#include "raster/smooth_coverage.h"
#include "tests/raster/test_support.h"

namespace pineda::raster::test {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(SquareInRectangle, KnownAreas) {
  const SmoothShape horizontal{0, 0, 10, 0, 1};
  EXPECT_NEAR(square_in_rectangle(2, -0.5, horizontal), 1.0, 1e-12);
  EXPECT_NEAR(square_in_rectangle(2, 0, horizontal), 0.5, 1e-12);
  EXPECT_NEAR(square_in_rectangle(-0.5, -0.5, horizontal), 0.5, 1e-12);  // the end halves it
  EXPECT_NEAR(square_in_rectangle(-0.25, -0.5, horizontal), 0.75, 1e-12);
  EXPECT_EQ(square_in_rectangle(2, 0.5, horizontal), 0.0);
  // Along a diagonal: a band sqrt(2) wide holds the whole square; sqrt(2)/2 leaves out two
  // corner triangles of area 1/8.
  const SmoothShape wide{0, 0, 10, 10, std::sqrt(2.0)}, narrow{0, 0, 10, 10, std::sqrt(0.5)};
  EXPECT_NEAR(square_in_rectangle(4, 4, wide), 1.0, 1e-12);
  EXPECT_NEAR(square_in_rectangle(4, 4, narrow), 0.75, 1e-12);
  EXPECT_NEAR(square_in_rectangle(5, 4, narrow), 0.125, 1e-12);
  // A band |x - y| <= 1.5 (one side cuts the square, the other holds it): a corner triangle
  // with legs 1/2 in, then out; and a side through two corners halves the square.
  const SmoothShape band{0, 0, 10, 10, 1.5 * std::sqrt(2.0)}, band2{0, 0, 10, 10, 2.0 * std::sqrt(2.0)};
  EXPECT_NEAR(square_in_rectangle(6, 4, band), 0.125, 1e-12);
  EXPECT_NEAR(square_in_rectangle(5, 4, band), 0.875, 1e-12);
  EXPECT_NEAR(square_in_rectangle(3, 5, band), 0.125, 1e-12);  // the other side
  EXPECT_NEAR(square_in_rectangle(4, 5, band), 0.875, 1e-12);
  EXPECT_NEAR(square_in_rectangle(6, 4, band2), 0.5, 1e-12);
  EXPECT_NEAR(square_in_rectangle(7, 4, band2), 0.0, 1e-12);  // the side touches a corner only
  // A shallow line 3 wide along y = x / 4: its upper side y = x / 4 + k crosses the left and
  // right sides of the square [16, 17] x [y, y + 1], so the area below it is its mean height.
  const double k = 1.5 * std::sqrt(17.0) / 4.0;
  const SmoothShape shallow{0, 0, 40, 10, 3.0};
  const double y_low = std::floor(16.5 / 4 + k);
  EXPECT_NEAR(square_in_rectangle(16, y_low, shallow), 16.5 / 4 + k - y_low, 1e-12);
}

TEST(SquareInDisc, KnownAreas) {
  EXPECT_NEAR(square_in_disc(-0.5, -0.5, 0.5), kPi / 4, 1e-12);  // the inscribed disc
  EXPECT_NEAR(square_in_disc(0.0, 0.0, 1.0), kPi / 4, 1e-12);    // a quarter of the unit disc
  EXPECT_NEAR(square_in_disc(-1.0, 0.0, 1.0), kPi / 4, 1e-12);
  EXPECT_NEAR(square_in_disc(-0.5, -0.5, std::sqrt(0.5)), 1.0, 1e-12);  // the circumscribed disc
  EXPECT_EQ(square_in_disc(1.0, 0.0, 1.0), 0.0);
  EXPECT_EQ(square_in_disc(5.0, 5.0, 2.0), 0.0);
}

TEST(SquareInDisc, PixelsSumToTheDiscArea) {
  for (double r : {0.5, 1.0, 1.25, 2.0, 3.5, 4.0, 10.0}) {
    const double cx = 0.3, cy = -0.2;
    double sum = 0.0;
    for (int y = -12; y < 12; ++y)
      for (int x = -12; x < 12; ++x) sum += square_in_disc(x - cx, y - cy, r);
    EXPECT_NEAR(sum, kPi * r * r, 1e-9) << r;
  }
}

constexpr int kS = 32;
ClipVertex wv(double x, double y) { return window_vertex(x, y, kS, kS); }

// Draws white with alpha 1 and no blending: each fragment's alpha is its coverage.
struct AlphaImage {
  OwnedFramebuffer fb{kS, kS};
  Renderer r{1};
  AlphaImage() {
    r.set_framebuffer(fb.fb);
    clear_all(r);
  }
  void draw(Primitive mode, std::vector<ClipVertex> v, float size) {
    DrawState s = state_for(kS, kS);
    s.line_smooth = s.point_smooth = true;
    s.line_width = s.point_size = size;
    r.draw(s, mode, v);
    r.flush();
  }
  int alpha(int x, int y) const { return fb.pixel(x, y)[3]; }
  int drawn() const {
    int n = 0;
    for (int y = 0; y < kS; ++y)
      for (int x = 0; x < kS; ++x) n += fb.pixel(x, y)[0] != 0;
    return n;
  }
};

TEST(SmoothLines, WidthTwoOnAPixelBoundaryCoversTwoRows) {
  AlphaImage img;
  img.draw(Primitive::Lines, {wv(2, 8), wv(12, 8)}, 2.f);
  for (int x = 2; x < 12; ++x) {
    EXPECT_EQ(img.alpha(x, 7), 255) << x;
    EXPECT_EQ(img.alpha(x, 8), 255) << x;
  }
  EXPECT_EQ(img.drawn(), 20);
}

TEST(SmoothLines, WidthOneAndAHalfOnAPixelCentre) {
  // Rows 7 and 9 lie a quarter pixel inside the line: 0.25 * 255 = 63.75.
  AlphaImage img;
  img.draw(Primitive::Lines, {wv(2, 8.5), wv(12, 8.5)}, 1.5f);
  for (int x = 2; x < 12; ++x) {
    EXPECT_EQ(img.alpha(x, 8), 255) << x;
    EXPECT_EQ(img.alpha(x, 7), 64) << x;
    EXPECT_EQ(img.alpha(x, 9), 64) << x;
  }
  EXPECT_EQ(img.drawn(), 30);
}

TEST(SmoothLines, WidthOneAndAHalfOffCentreGivesAHalfRow) {
  AlphaImage img;
  img.draw(Primitive::Lines, {wv(2, 8.25), wv(12, 8.25)}, 1.5f);
  for (int x = 2; x < 12; ++x) {
    EXPECT_EQ(img.alpha(x, 8), 255) << x;
    EXPECT_EQ(img.alpha(x, 7), 128) << x;  // 127.5 rounds to even
  }
  EXPECT_EQ(img.drawn(), 20);
}

TEST(SmoothLines, EndsCutThroughPixels) {
  // Ends at x = 2.25 and 12.5: pixel 2 is three quarters covered, pixel 12 half.
  AlphaImage img;
  img.draw(Primitive::Lines, {wv(2.25, 8.5), wv(12.5, 8.5)}, 1.f);
  EXPECT_EQ(img.alpha(2, 8), 191);
  for (int x = 3; x < 12; ++x) EXPECT_EQ(img.alpha(x, 8), 255) << x;
  EXPECT_EQ(img.alpha(12, 8), 128);
  EXPECT_EQ(img.drawn(), 11);
}

TEST(SmoothLines, VerticalMatchesHorizontal) {
  AlphaImage h, v;
  h.draw(Primitive::Lines, {wv(3.3, 9.6), wv(21.7, 9.6)}, 2.5f);
  v.draw(Primitive::Lines, {wv(9.6, 3.3), wv(9.6, 21.7)}, 2.5f);
  for (int a = 0; a < kS; ++a)
    for (int b = 0; b < kS; ++b) ASSERT_EQ(h.alpha(a, b), v.alpha(b, a)) << a << "," << b;
}

TEST(SmoothLines, DiagonalIsSymmetricAboutItself) {
  AlphaImage img;
  img.draw(Primitive::Lines, {wv(4, 4), wv(24, 24)}, 2.5f);
  for (int y = 0; y < kS; ++y)
    for (int x = 0; x < kS; ++x) ASSERT_EQ(img.alpha(x, y), img.alpha(y, x)) << x << "," << y;
  EXPECT_EQ(img.alpha(14, 14), 255);
}

TEST(SmoothLines, CoverageSumsToTheRectangleArea) {
  for (auto [x0, y0, x1, y1] : {std::array<double, 4>{3.3, 9.6, 21.7, 9.6}, std::array<double, 4>{4, 4, 24, 24},
                                std::array<double, 4>{3.1, 5.2, 25.7, 14.9}}) {
    for (double w : {1.0, 1.5, 2.5}) {
      PrimSetup p;
      p.kind = CoverageKind::Line;
      p.smooth = {x0, y0, x1, y1, w};
      double sum = 0.0;
      for (int y = -5; y < 40; ++y)
        for (int x = -5; x < 40; ++x) sum += smooth_coverage(p, x, y);
      const double area = w * std::hypot(x1 - x0, y1 - y0);
      EXPECT_NEAR(sum, area, 1e-9) << x0 << " " << y0 << " width " << w;
    }
  }
}

TEST(SmoothPoints, SizeOneAtAPixelCentreIsItsInscribedDisc) {
  AlphaImage img;
  img.draw(Primitive::Points, {wv(8.5, 8.5)}, 1.f);
  EXPECT_EQ(img.alpha(8, 8), 200);  // pi/4 * 255 = 200.28
  EXPECT_EQ(img.drawn(), 1);
}

TEST(SmoothPoints, SizeTwoAtACornerGivesFourQuarterDiscs) {
  AlphaImage img;
  img.draw(Primitive::Points, {wv(8, 8)}, 2.f);
  for (int y = 7; y < 9; ++y)
    for (int x = 7; x < 9; ++x) EXPECT_EQ(img.alpha(x, y), 200) << x << "," << y;
  EXPECT_EQ(img.drawn(), 4);
}

TEST(SmoothPoints, SizeThreeIsSymmetric) {
  AlphaImage img;
  img.draw(Primitive::Points, {wv(8.5, 8.5)}, 3.f);
  EXPECT_EQ(img.alpha(8, 8), 255);
  // Edge neighbours: the disc of radius 1.5 covers the square [0.5, 1.5] x [-0.5, 0.5] in
  // 0.9717 of its area; diagonal ones [0.5, 1.5]^2 in 0.5454.
  for (auto [x, y] : {std::pair{7, 8}, std::pair{9, 8}, std::pair{8, 7}, std::pair{8, 9}})
    EXPECT_EQ(img.alpha(x, y), static_cast<int>(std::lround(square_in_disc(0.5, -0.5, 1.5) * 255))) << x << "," << y;
  for (auto [x, y] : {std::pair{7, 7}, std::pair{9, 7}, std::pair{7, 9}, std::pair{9, 9}})
    EXPECT_EQ(img.alpha(x, y), static_cast<int>(std::lround(square_in_disc(0.5, 0.5, 1.5) * 255))) << x << "," << y;
  EXPECT_EQ(img.alpha(9, 8), 248);
  EXPECT_EQ(img.alpha(9, 9), 139);
  EXPECT_EQ(img.drawn(), 9);
}

TEST(SmoothPoints, AlphaSumsToTheDiscArea) {
  // Each pixel's alpha rounds its coverage to 1/255: the sum is within half of that per pixel.
  for (float size : {1.f, 2.f, 2.5f, 3.f, 4.f, 5.5f, 8.f}) {
    AlphaImage img;
    img.draw(Primitive::Points, {wv(13.3, 14.8)}, size);
    double sum = 0.0;
    for (int y = 0; y < kS; ++y)
      for (int x = 0; x < kS; ++x) sum += img.alpha(x, y) / 255.0;
    const double r = size / 2.0;
    EXPECT_NEAR(sum, kPi * r * r, img.drawn() * 0.5 / 255.0) << size;
  }
}

// A scene over several tiles: smooth lines of three widths and points of sizes 1 to 8, blended.
std::vector<uint8_t> blended_scene(int threads) {
  constexpr int kW = 200, kH = 150;
  OwnedFramebuffer fb(kW, kH);
  Renderer r(threads);
  r.set_framebuffer(fb.fb);
  clear_all(r, 0.1f);
  DrawState s = state_for(kW, kH);
  s.line_smooth = s.point_smooth = true;
  s.blend = true;
  s.blend_state.src_rgb = s.blend_state.src_alpha = BlendFactor::SrcAlpha;
  s.blend_state.dst_rgb = s.blend_state.dst_alpha = BlendFactor::OneMinusSrcAlpha;
  auto at = [](double x, double y) { return window_vertex(x, y, kW, kH); };
  const float widths[] = {1.f, 1.5f, 2.5f};
  for (int i = 0; i < 24; ++i) {
    s.line_width = widths[i % 3];
    const double a = i * 0.2618;
    const std::vector<ClipVertex> line = {at(100.3, 75.1), at(100.3 + 90 * std::cos(a), 75.1 + 70 * std::sin(a))};
    r.draw(s, Primitive::Lines, line);
  }
  for (int size = 1; size <= 8; ++size) {
    s.point_size = static_cast<float>(size);
    const std::vector<ClipVertex> points = {at(20.0 + 21.3 * size, 12.4), at(61.7 + 3.1 * size, 60.5 + 9.2 * size)};
    r.draw(s, Primitive::Points, points);
  }
  r.flush();
  return fb.color;
}

TEST(SmoothPrimitives, SameImageForOneAndTwoThreads) {
  const std::vector<uint8_t> one = blended_scene(1), two = blended_scene(2);
  EXPECT_EQ(one, two);
  int coloured = 0;
  for (size_t i = 0; i < one.size(); i += 4) coloured += one[i + 1] != 0;
  EXPECT_GT(coloured, 2000);
}

TEST(SmoothPrimitives, SameImageOnTheBaselineSimdPath) {
  const std::vector<uint8_t> best = blended_scene(2);
  setenv("PINEDA_SIMD", "baseline", 1);
  const std::vector<uint8_t> baseline = blended_scene(2);
  unsetenv("PINEDA_SIMD");
  EXPECT_EQ(best, baseline);
}

// The reference mode shades in double: single fragments get the same alpha; blending 24
// overlapping lines in double drifts from the 8-bit blend by at most 2 steps.
TEST(SmoothPrimitives, ReferenceModeGivesTheSameCoverage) {
  auto draw = [] {
    AlphaImage img;
    img.draw(Primitive::Lines, {wv(3.1, 5.2), wv(25.7, 14.9)}, 2.5f);
    img.draw(Primitive::Points, {wv(20.3, 24.6)}, 5.5f);
    return img.fb.color;
  };
  const std::vector<uint8_t> fast = draw();
  setenv("PINEDA_REFERENCE", "1", 1);
  const std::vector<uint8_t> reference = draw();
  const std::vector<uint8_t> reference_blended = blended_scene(1);
  unsetenv("PINEDA_REFERENCE");
  EXPECT_EQ(fast, reference);
  const std::vector<uint8_t> fast_blended = blended_scene(2);
  int max_diff = 0;
  for (size_t i = 0; i < fast_blended.size(); ++i)
    max_diff = std::max(max_diff, std::abs(fast_blended[i] - reference_blended[i]));
  EXPECT_LE(max_diff, 2);
}

}  // namespace
}  // namespace pineda::raster::test
