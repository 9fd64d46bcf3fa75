// Triangle coverage against a brute-force integer reference, and the fill rule on meshes.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "tests/raster/test_support.h"

namespace pineda::raster::test {
namespace {

constexpr int kSize = 256;  // a power of two: window <-> NDC conversions are exact

std::vector<uint8_t> reference_coverage(const int64_t x[3], const int64_t y[3]) {
  return reference_triangle_coverage(x, y, kSize);
}

std::vector<uint8_t> render_coverage(const int64_t x[3], const int64_t y[3], int threads = 1) {
  OwnedFramebuffer fb(kSize, kSize);
  Renderer r(threads);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  ClipVertex v[3];
  for (int i = 0; i < 3; ++i) v[i] = window_vertex(x[i] / 256.0, y[i] / 256.0, kSize, kSize);
  r.draw(state_for(kSize, kSize), Primitive::Triangles, v);
  r.flush();
  std::vector<uint8_t> out(kSize * kSize);
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) out[j * kSize + i] = fb.pixel(i, j)[0] != 0;
  return out;
}

TEST(Coverage, RandomTrianglesMatchReferenceExactly) {
  std::mt19937 rng(1234);
  for (int iter = 0; iter < 1000; ++iter) {
    // A mix of large, small, thin and off-grid triangles, some reaching past the edges.
    const int span = iter % 3 == 0 ? 300 * 256 : (iter % 3 == 1 ? 40 * 256 : 6 * 256);
    std::uniform_int_distribution<int64_t> base(-20 * 256, 276 * 256), off(-span, span);
    int64_t x[3], y[3];
    x[0] = base(rng);
    y[0] = base(rng);
    for (int i = 1; i < 3; ++i) {
      x[i] = x[0] + off(rng);
      y[i] = y[0] + off(rng);
    }
    if (iter % 5 == 0) {  // vertices on pixel centres and edges exactly
      for (int i = 0; i < 3; ++i) {
        x[i] = (x[i] / 128) * 128;
        y[i] = (y[i] / 128) * 128;
      }
    }
    // Inside the window the NDC values are exact: keep within [-256, 512] px.
    ASSERT_EQ(render_coverage(x, y), reference_coverage(x, y)) << "triangle " << iter;
  }
}

TEST(Coverage, AxisAlignedEdgesThroughPixelCentres) {
  // A right triangle whose legs run through pixel centres: the left and bottom legs own them.
  const int64_t x[3] = {10 * 256 + 128, 30 * 256 + 128, 10 * 256 + 128};
  const int64_t y[3] = {5 * 256 + 128, 5 * 256 + 128, 25 * 256 + 128};
  const auto got = render_coverage(x, y);
  EXPECT_EQ(got, reference_coverage(x, y));
  EXPECT_TRUE(got[5 * kSize + 10]);   // the corner on both owned legs
  EXPECT_TRUE(got[5 * kSize + 29]);   // bottom leg
  EXPECT_FALSE(got[5 * kSize + 30]);  // the far vertex is on the hypotenuse
  EXPECT_TRUE(got[24 * kSize + 10]);  // left leg
}

// Additive blending of 1/255 per fragment counts how often each pixel is drawn.
void draw_counted(Renderer& r, Primitive mode, const std::vector<ClipVertex>& v,
                  const std::vector<uint32_t>& indices = {}) {
  DrawState s = state_for(kSize, kSize);
  s.blend = true;
  s.blend_state.src_rgb = s.blend_state.dst_rgb = BlendFactor::One;
  r.draw(s, mode, v, indices);
}

ClipVertex counted_vertex(double x, double y) {
  ClipVertex v = window_vertex(x, y, kSize, kSize);
  v.color[0] = v.back_color[0] = 1.f / 255.f;
  return v;
}

TEST(FillRule, JitteredGridCoversEveryPixelExactlyOnce) {
  std::mt19937 rng(99);
  constexpr int kCells = 8;
  const double cell = static_cast<double>(kSize) / kCells;
  std::uniform_int_distribution<int> jitter(-1000, 1000);
  std::vector<ClipVertex> verts;
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) {
      double x = i * cell, y = j * cell;
      if (i > 0 && i < kCells) x += jitter(rng) / 256.0;  // keep the outline on the window border
      if (j > 0 && j < kCells) y += jitter(rng) / 256.0;
      if (i % 3 == 1 && j % 2 == 1) x = std::floor(x) + 0.5;  // some vertices on pixel centres
      verts.push_back(counted_vertex(x, y));
    }
  std::vector<uint32_t> idx;
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      const uint32_t a = j * (kCells + 1) + i, b = a + 1, c = a + kCells + 1, d = c + 1;
      if ((i + j) % 2) idx.insert(idx.end(), {a, b, d, a, d, c});
      else idx.insert(idx.end(), {a, b, c, b, d, c});
    }
  OwnedFramebuffer fb(kSize, kSize);
  Renderer r(2);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  draw_counted(r, Primitive::Triangles, verts, idx);
  r.flush();
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) ASSERT_EQ(fb.pixel(x, y)[0], 1) << x << "," << y;
}

TEST(FillRule, FanAroundSharedVertexCoversDiscOnce) {
  // 37 triangles sharing the centre vertex, which sits exactly on a pixel centre.
  std::vector<ClipVertex> verts{counted_vertex(100.5, 100.5)};
  constexpr int kSpokes = 37;
  for (int i = 0; i <= kSpokes; ++i) {
    const double a = 2 * 3.14159265358979 * (i % kSpokes) / kSpokes;
    verts.push_back(counted_vertex(100.5 + 80 * std::cos(a), 100.5 + 80 * std::sin(a)));
  }
  OwnedFramebuffer fb(kSize, kSize);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  draw_counted(r, Primitive::TriangleFan, verts);
  r.flush();
  int covered = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      ASSERT_LE(fb.pixel(x, y)[0], 1) << x << "," << y;
      covered += fb.pixel(x, y)[0];
    }
  EXPECT_EQ(fb.pixel(100, 100)[0], 1);
  EXPECT_GT(covered, 19000);  // the polygon's area is about 19.9k px
}

TEST(FillRule, QuadStripAndPolygonShareEdgesWithoutGapsOrOverlap) {
  OwnedFramebuffer fb(kSize, kSize);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  std::vector<ClipVertex> strip;
  for (int i = 0; i <= 10; ++i) {
    const double x = i * 25.6 + (i % 2) * 0.3;
    strip.push_back(counted_vertex(x, 0));
    strip.push_back(counted_vertex(x + 3.7 * (i % 3 == 0 && i > 0 && i < 10), 128.3));
  }
  draw_counted(r, Primitive::QuadStrip, strip);
  // Above the strip: a fan from an apex far outside the guard band (clipped geometrically).
  std::vector<ClipVertex> fan{counted_vertex(128, 100000)};
  for (int i = 10; i >= 0; --i) fan.push_back(strip[2 * i + 1]);
  draw_counted(r, Primitive::TriangleFan, fan);
  r.flush();
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) ASSERT_EQ(fb.pixel(x, y)[0], 1) << x << "," << y;
}

}  // namespace
}  // namespace pineda::raster::test
