// Lines (diamond-exit rule, wide lines, interpolation) and points (sizes, centring).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tests/raster/test_support.h"

namespace pineda::raster::test {
namespace {

constexpr int kS = 32;

struct Counter {
  OwnedFramebuffer fb{kS, kS};
  Renderer r{1};
  Counter() {
    r.set_framebuffer(fb.fb);
    clear_all(r);
  }
  // Additive blending of 1/255 per fragment.
  void draw(Primitive mode, std::vector<ClipVertex> v, float width = 1.f, float size = 1.f) {
    DrawState s = state_for(kS, kS);
    s.blend = true;
    s.blend_state.src_rgb = s.blend_state.dst_rgb = BlendFactor::One;
    s.line_width = width;
    s.point_size = size;
    for (auto& p : v) p.color[0] = 1.f / 255.f;
    r.draw(s, mode, v);
    r.flush();
  }
  int at(int x, int y) const { return fb.pixel(x, y)[0]; }
  int total() const {
    int n = 0;
    for (int y = 0; y < kS; ++y)
      for (int x = 0; x < kS; ++x) n += at(x, y);
    return n;
  }
};

ClipVertex wv(double x, double y) { return window_vertex(x, y, kS, kS); }

TEST(Lines, HalfOpenAlongTheMajorAxis) {
  Counter c;
  c.draw(Primitive::Lines, {wv(2, 5.5), wv(12, 5.5)});
  EXPECT_EQ(c.total(), 10);
  for (int x = 2; x < 12; ++x) EXPECT_EQ(c.at(x, 5), 1) << x;
}

TEST(Lines, DiamondExitRuleAtTheEndpoints) {
  // Starts inside pixel 6's diamond, past its centre: the line leaves that diamond, so pixel 6
  // is drawn. Ends inside pixel 20's diamond, past its centre: never leaves it, not drawn.
  Counter c;
  c.draw(Primitive::Lines, {wv(6.7, 5.6), wv(20.6, 5.6)});
  EXPECT_EQ(c.total(), 14);
  EXPECT_EQ(c.at(6, 5), 1);
  EXPECT_EQ(c.at(19, 5), 1);
  EXPECT_EQ(c.at(20, 5), 0);
  // The same span outside the diamonds (near the pixel corners): half-open by centres.
  Counter d;
  d.draw(Primitive::Lines, {wv(6.7, 5.05), wv(20.6, 5.05)});
  EXPECT_EQ(d.total(), 14);
  EXPECT_EQ(d.at(6, 5), 0);
  EXPECT_EQ(d.at(20, 5), 1);
}

TEST(Lines, WideLinesAreClippedBeforeWidening) {
  // A y-major line running just right of the window: clipped away before it is widened, so its
  // 5-pixel span never reaches into the last column.
  Counter c;
  c.draw(Primitive::Lines, {wv(33.2, 2), wv(33.4, 30)}, 5.f);
  EXPECT_EQ(c.total(), 0);
}

TEST(Lines, ClosedLoopDrawsEveryPixelOnce) {
  Counter c;
  c.draw(Primitive::LineLoop, {wv(2.5, 2.5), wv(12.5, 2.5), wv(12.5, 12.5), wv(2.5, 12.5)});
  EXPECT_EQ(c.total(), 40);
  for (int i = 0; i < 10; ++i) {
    EXPECT_EQ(c.at(2 + i, 2), 1);   // bottom, going right
    EXPECT_EQ(c.at(12, 2 + i), 1);  // right, going up
    EXPECT_EQ(c.at(3 + i, 12), 1);  // top, going left
    EXPECT_EQ(c.at(2, 3 + i), 1);   // left, going down
  }
}

TEST(Lines, DiagonalStripHasOnePixelPerColumn) {
  Counter c;
  c.draw(Primitive::LineStrip, {wv(1.2, 1.7), wv(20.2, 9.1), wv(29.9, 30.3)});
  // First segment x-major over columns with centres in [1.2, 20.2): 1..19; second y-major over
  // rows with centres in [9.1, 30.3): 9..29.
  EXPECT_EQ(c.total(), 19 + 21);
  int max = 0;
  for (int y = 0; y < kS; ++y)
    for (int x = 0; x < kS; ++x) max = std::max(max, c.at(x, y));
  EXPECT_EQ(max, 1);
}

// One-pixel lines in 24 directions from the middle of a 200x200 framebuffer, across 64x64 tiles
// and both ways along each axis: one pixel per column (row) whose centre the line passes, each
// within half a pixel of the line there. (Their quads go to the fragment routine quad row by
// quad row as the line passes them: tile_raster.cpp's QuadRowCollector.)
TEST(Lines, OnePixelLinesAcrossTilesInEveryDirection) {
  constexpr int kSize = 200;
  for (int k = 0; k < 24; ++k) {
    const double angle = 2 * 3.14159265358979 * (k + 0.3) / 24;
    // Ends near pixel corners, inside no pixel's diamond: the columns are the half-open range.
    const double x0 = 100.05, y0 = 100.05;
    const double x1 = std::floor(100 + 90 * std::cos(angle)) + 0.05, y1 = std::floor(100 + 90 * std::sin(angle)) + 0.05;
    OwnedFramebuffer fb(kSize, kSize);
    Renderer r{1};
    r.set_framebuffer(fb.fb);
    clear_all(r);
    r.draw(state_for(kSize, kSize), Primitive::Lines,
           std::vector<ClipVertex>{window_vertex(x0, y0, kSize, kSize), window_vertex(x1, y1, kSize, kSize)});
    r.flush();
    const bool x_major = std::fabs(x1 - x0) >= std::fabs(y1 - y0);
    const double a0 = x_major ? x0 : y0, a1 = x_major ? x1 : y1, b0 = x_major ? y0 : x0, b1 = x_major ? y1 : x1;
    int expected = 0;
    for (int m = 0; m < kSize; ++m) {
      const double c = m + 0.5;
      if (c < std::min(a0, a1) || c >= std::max(a0, a1)) continue;
      ++expected;
      const double minor = b0 + (c - a0) * (b1 - b0) / (a1 - a0);
      int found = 0;
      for (int n = 0; n < kSize; ++n) {
        if (!(x_major ? fb.pixel(m, n) : fb.pixel(n, m))[0]) continue;
        ++found;
        EXPECT_LE(std::fabs(n + 0.5 - minor), 0.5 + 1.0 / 128) << "direction " << k << ", at " << m;
      }
      EXPECT_EQ(found, 1) << "direction " << k << ", at " << m;
    }
    EXPECT_EQ(fb.count_nonzero_red(), expected) << "direction " << k;
    EXPECT_GT(expected, 60) << "direction " << k;
  }
}

TEST(Lines, WideLinesAreSpansAcrossTheMajorAxis) {
  Counter c;
  c.draw(Primitive::Lines, {wv(4, 10.5), wv(14, 10.5)}, 3.f);
  EXPECT_EQ(c.total(), 30);
  for (int x = 4; x < 14; ++x)
    for (int y = 9; y <= 11; ++y) EXPECT_EQ(c.at(x, y), 1);
  Counter v;
  v.draw(Primitive::Lines, {wv(10.2, 3), wv(10.2, 13)}, 2.f);  // y-major, width 2: columns 9, 10
  EXPECT_EQ(v.total(), 20);
  EXPECT_EQ(v.at(9, 5), 1);
  EXPECT_EQ(v.at(10, 5), 1);
}

TEST(Lines, ColoursInterpolateAlongTheLine) {
  OwnedFramebuffer fb(256, 1);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  std::vector<ClipVertex> v{vertex(-1, 0), vertex(1, 0)};
  v[0].color[0] = 0.f;
  v[1].color[0] = 1.f;
  r.draw(state_for(256, 1), Primitive::Lines, v);
  r.flush();
  for (int x = 0; x < 256; ++x) ASSERT_EQ(fb.pixel(x, 0)[0], static_cast<int>((x + 0.5) / 256 * 255 + 0.5)) << x;
}

TEST(Points, SizesAndCentres) {
  Counter one;
  one.draw(Primitive::Points, {wv(5.3, 7.8)});
  EXPECT_EQ(one.total(), 1);
  EXPECT_EQ(one.at(5, 7), 1);
  Counter two;  // even: centred on (5, 8), the nearest pixel corner
  two.draw(Primitive::Points, {wv(5.3, 7.8)}, 1.f, 2.f);
  EXPECT_EQ(two.total(), 4);
  for (int y = 7; y <= 8; ++y)
    for (int x = 4; x <= 5; ++x) EXPECT_EQ(two.at(x, y), 1);
  Counter three;  // odd: centred on the pixel (5, 7)
  three.draw(Primitive::Points, {wv(5.3, 7.8)}, 1.f, 2.6f);
  EXPECT_EQ(three.total(), 9);
  for (int y = 6; y <= 8; ++y)
    for (int x = 4; x <= 6; ++x) EXPECT_EQ(three.at(x, y), 1);
}

TEST(Points, OutsideTheClipVolumeAreDropped) {
  Counter c;
  c.draw(Primitive::Points, {vertex(1.5f, 0), vertex(0, 0, 2), vertex(0, 0, 0, -1), vertex(0.01f, 0.01f)}, 1, 5);
  EXPECT_EQ(c.total(), 25);
}

}  // namespace
}  // namespace pineda::raster::test
