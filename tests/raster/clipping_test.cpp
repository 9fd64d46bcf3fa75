// Clipping: near/far, the guard band, w crossing zero, huge and non-finite coordinates.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>

#include "tests/raster/test_support.h"

namespace pineda::raster::test {
namespace {

constexpr int kW = 64, kH = 48;

struct Rendered {
  OwnedFramebuffer fb{kW, kH};
  Renderer r{1};
  Rendered() {
    r.set_framebuffer(fb.fb);
    clear_all(r);
  }
  void draw(Primitive mode, std::vector<ClipVertex> v, DrawState s = state_for(kW, kH)) {
    r.draw(s, mode, v);
    r.flush();
  }
  bool at(int x, int y) const { return fb.pixel(x, y)[0] != 0; }
};

ClipVertex scaled(ClipVertex v, float k) {
  for (float& c : v.clip) c *= k;
  return v;
}

TEST(Clipping, FullScreenTriangleWithHugeCoordinatesCoversEverything) {
  for (const float big : {3.f, 1e5f, 1e30f, FLT_MAX}) {
    Rendered t;
    t.draw(Primitive::Triangles, {vertex(-1, -1), vertex(big, -1), vertex(-1, big)});
    EXPECT_EQ(t.fb.count_nonzero_red(), kW * kH) << big;
  }
}

TEST(Clipping, HomogeneousScalingDoesNotChangeCoverage) {
  const ClipVertex base[3] = {vertex(-0.9f, -0.7f), vertex(0.8f, -0.2f), vertex(-0.1f, 0.9f)};
  Rendered ref;
  ref.draw(Primitive::Triangles, {base[0], base[1], base[2]});
  for (const float k : {1e-20f, 0.25f, 4.f, 1e20f}) {
    Rendered t;
    t.draw(Primitive::Triangles, {scaled(base[0], k), scaled(base[1], k), scaled(base[2], k)});
    EXPECT_EQ(t.fb.color, ref.fb.color) << k;
  }
}

TEST(Clipping, DiagonalEdgeToFltMaxStaysExact) {
  // The edge between (FLT_MAX, FLT_MAX) and (-1,-1) is the diagonal y = x of NDC; with a square
  // viewport the pixels below it (x > y) are covered.
  constexpr int kS = 32;
  OwnedFramebuffer fb(kS, kS);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  const std::vector<ClipVertex> v{vertex(-1, -1), vertex(1, -1), vertex(FLT_MAX, FLT_MAX)};
  r.draw(state_for(kS, kS), Primitive::Triangles, v);
  r.flush();
  for (int y = 0; y < kS; ++y)
    for (int x = 0; x < kS; ++x)
      // Counter-clockwise, the diagonal runs down to (-1,-1) with the interior on its right: a
      // left edge, which owns the pixel centres on it.
      ASSERT_EQ(fb.pixel(x, y)[0] != 0, x >= y) << x << "," << y;
}

TEST(Clipping, NearAndFarPlanesCutAtTheRightDepth) {
  // A quad tilted in depth: z goes from -3 (left) to +3 (right) in NDC, so only the middle
  // third (|z| <= 1, i.e. |x_ndc| <= 1/3) survives.
  Rendered t;
  t.draw(Primitive::Quads, {vertex(-1, -1, -3), vertex(1, -1, 3), vertex(1, 1, 3), vertex(-1, 1, -3)});
  for (int x = 0; x < kW; ++x) {
    const double ndc = (x + 0.5) * 2.0 / kW - 1.0;
    if (std::fabs(std::fabs(ndc) - 1.0 / 3.0) < 0.02) continue;  // on the cut itself
    EXPECT_EQ(t.at(x, kH / 2), std::fabs(ndc) < 1.0 / 3.0) << x;
  }
}

TEST(Clipping, TriangleCrossingWZeroShowsOnlyItsVisiblePart) {
  // A and B in front (w = 1), C behind the eye (w = -1) projecting to (0, -3): the visible part
  // is the wedge y >= -1, |x| <= (y + 3) / 4 in NDC.
  Rendered t;
  t.draw(Primitive::Triangles, {vertex(-0.5f, -1, 0, 1), vertex(0.5f, -1, 0, 1), vertex(0, 3, 0, -1)});
  int checked = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double xn = (x + 0.5) * 2.0 / kW - 1.0, yn = (y + 0.5) * 2.0 / kH - 1.0;
      const double d = std::fabs(xn) - (yn + 3.0) / 4.0;
      if (std::fabs(d) < 1e-3) continue;  // pixel centre on the boundary
      ASSERT_EQ(t.at(x, y), d < 0) << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, kW * kH - 64);
}

TEST(Clipping, TriangleEntirelyBehindTheEyeDrawsNothing) {
  Rendered t;
  t.draw(Primitive::Triangles, {vertex(-1, -1, 0, -1), vertex(1, -1, 0, -1), vertex(0, 1, 0, -1)});
  EXPECT_EQ(t.fb.count_nonzero_red(), 0);
  t.draw(Primitive::Triangles, {vertex(0, 0, 0, 0), vertex(1, 0, 0, 0), vertex(0, 1, 0, 0)});
  EXPECT_EQ(t.fb.count_nonzero_red(), 0);
}

TEST(Clipping, NonFiniteVerticesDropTheirPrimitiveOnly) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (const float bad : {nan, inf, -inf}) {
    Rendered t;
    ClipVertex v = vertex(0, 0);
    v.clip[1] = bad;
    // First triangle uses the bad vertex; the second (left half of the screen) is fine.
    t.draw(Primitive::Triangles, {vertex(-1, -1), vertex(1, -1), v, vertex(-1, -1), vertex(0, -1), vertex(-1, 1)});
    Rendered ref;
    ref.draw(Primitive::Triangles, {vertex(-1, -1), vertex(0, -1), vertex(-1, 1)});
    EXPECT_EQ(t.fb.color, ref.fb.color);
    EXPECT_GT(ref.fb.count_nonzero_red(), 0);
  }
}

TEST(Clipping, NanColoursAndTexcoordsDoNotCrash) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  Rendered t;
  auto tex = std::make_shared<TextureImage>();
  tex->levels.push_back({2, 2, {0xff0000ffu, 0xff00ff00u, 0xffff0000u, 0xffffffffu}});
  DrawState s = state_for(kW, kH);
  s.texture_units[0].image = tex;
  s.texture_units[0].sampler.min_filter = TexFilter::LinearMipmapLinear;
  std::vector<ClipVertex> v{vertex(-1, -1), vertex(1, -1), vertex(0, 1)};
  for (auto& p : v) {
    p.color[0] = nan;
    p.texcoord[0][0] = nan;
    p.texcoord[0][1] = 1e30f;
  }
  v[1].texcoord[0][3] = 0.f;
  t.draw(Primitive::Triangles, v, s);
  SUCCEED();
}

TEST(Clipping, HugeViewportWithSmallFramebufferStaysInBounds) {
  OwnedFramebuffer fb(5, 3);
  Renderer r(2);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  DrawState s;
  s.viewport = {-8000, -8000, 16384, 16384, 0, 1};
  s.scissor_test = true;
  s.scissor = {-100, 1, 1000000, 1};
  r.draw(s, Primitive::Triangles, std::vector<ClipVertex>{vertex(-1, -1), vertex(1, -1), vertex(-1, 1)});
  r.draw(s, Primitive::Lines, std::vector<ClipVertex>{vertex(-1, -1), vertex(1, 1)});
  r.flush();
  // Only row 1 is inside the scissor; the viewport's lower-left triangle covers it.
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) EXPECT_EQ(fb.pixel(x, y)[0] != 0, y == 1) << x << "," << y;
}

TEST(Clipping, EmptyAndNullFramebuffersAreHarmless) {
  Renderer r(2);
  Framebuffer empty;
  r.set_framebuffer(empty);
  clear_all(r);
  r.draw(state_for(10, 10), Primitive::Triangles, std::vector<ClipVertex>{vertex(-1, -1), vertex(1, -1), vertex(-1, 1)});
  r.flush();
  Framebuffer no_memory;
  no_memory.width = 100;
  no_memory.height = 100;
  r.set_framebuffer(no_memory);
  clear_all(r);
  r.draw(state_for(100, 100), Primitive::Triangles, std::vector<ClipVertex>{vertex(-1, -1), vertex(1, -1), vertex(-1, 1)});
  r.flush();
  SUCCEED();
}

TEST(Clipping, IndexPastTheEndDropsItsPrimitive) {
  Rendered t;
  const std::vector<ClipVertex> v{vertex(-1, -1), vertex(1, -1), vertex(-1, 1), vertex(1, 1)};
  const std::vector<uint32_t> idx{0, 1, 7, 1, 3, 2};
  t.r.draw(state_for(kW, kH), Primitive::Triangles, v, idx);
  t.r.flush();
  EXPECT_FALSE(t.at(0, 0));
  EXPECT_TRUE(t.at(kW - 1, kH - 1));
  for (Primitive m : {Primitive::Points, Primitive::Lines, Primitive::LineLoop, Primitive::LineStrip,
                      Primitive::TriangleStrip, Primitive::TriangleFan, Primitive::Quads, Primitive::QuadStrip,
                      Primitive::Polygon}) {
    const std::vector<uint32_t> bad{0, 1, 4000000000u, 2, 3, 99};
    t.r.draw(state_for(kW, kH), m, v, bad);
  }
  t.r.flush();
}

}  // namespace
}  // namespace pineda::raster::test

namespace pineda::raster::test {
namespace {

TEST(Clipping, GuardBandClippedEdgeFollowsTheExactLine) {
  // The hypotenuse from (1e4, -1) to (-1, 1) in NDC starts ~320k px right of the window, far
  // outside the guard band; after clipping the edge must still be the same line.
  OwnedFramebuffer fb(kW, kH);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  r.draw(state_for(kW, kH), Primitive::Triangles, std::vector<ClipVertex>{vertex(-1, -1), vertex(1e4f, -1), vertex(-1, 1)});
  r.flush();
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double xn = (x + 0.5) * 2.0 / kW - 1.0, yn = (y + 0.5) * 2.0 / kH - 1.0;
      const double d = yn - (-1.0 + 2.0 * (1e4 - xn) / (1e4 + 1.0));  // < 0: below the edge
      if (std::fabs(d) < 1e-4) continue;
      ASSERT_EQ(fb.pixel(x, y)[0] != 0, d < 0) << x << "," << y;
    }
}

TEST(Clipping, ViewportBoundsTheFragmentsOfPrimitivesInsideTheGuardBand) {
  OwnedFramebuffer fb(kW, kH);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  DrawState s = state_for(kW, kH);
  s.viewport = {10, 12, 20, 16, 0, 1};
  r.draw(s, Primitive::Triangles, std::vector<ClipVertex>{vertex(-1.5f, -1.5f), vertex(5, -1.5f), vertex(-1.5f, 5)});
  s.point_size = 9;
  r.draw(s, Primitive::Points, std::vector<ClipVertex>{vertex(1, 1)});
  r.flush();
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      ASSERT_EQ(fb.pixel(x, y)[0] != 0, x >= 10 && x < 30 && y >= 12 && y < 28) << x << "," << y;
}

}  // namespace
}  // namespace pineda::raster::test
