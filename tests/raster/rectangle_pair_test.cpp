// Two triangles of one draw that make an axis-aligned rectangle are rasterized as the
// rectangle (rectangle_pair.h): the same pixels, each once, the same depths, and the pairing
// only for halves whose values lie on one plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "raster/rectangle_pair.h"
#include "tests/raster/test_support.h"

namespace pineda::raster::test {
namespace {

constexpr int kSize = 128;  // a power of two: window <-> NDC conversions are exact

ClipVertex at(int64_t x, int64_t y, float red, float z = 0.f) {
  ClipVertex v = window_vertex(static_cast<double>(x) / 256.0, static_cast<double>(y) / 256.0, kSize, kSize, z);
  v.color[0] = v.back_color[0] = red;
  return v;
}

// How often each pixel is drawn: additive blending of 1/255 per fragment.
std::vector<int> draw_counted(const std::vector<std::vector<ClipVertex>>& draws, Primitive mode = Primitive::Triangles) {
  OwnedFramebuffer fb(kSize, kSize);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  DrawState s = state_for(kSize, kSize);
  s.blend = true;
  s.blend_state.src_rgb = s.blend_state.dst_rgb = BlendFactor::One;
  for (const std::vector<ClipVertex>& v : draws) r.draw(s, mode, v);
  r.flush();
  std::vector<int> out(kSize * kSize);
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) out[j * kSize + i] = fb.pixel(i, j)[0];
  return out;
}

// Two triangles drawn with `s` into `merged` in one draw (paired) and into `split` in a draw each.
void draw_merged_and_split(const DrawState& s, const std::vector<ClipVertex>& first, const std::vector<ClipVertex>& second,
                           OwnedFramebuffer& merged, OwnedFramebuffer& split) {
  std::vector<ClipVertex> both = first;
  both.insert(both.end(), second.begin(), second.end());
  for (OwnedFramebuffer* fb : {&merged, &split}) {
    Renderer r(1);
    r.set_framebuffer(fb->fb);
    clear_all(r);
    if (fb == &merged) {
      r.draw(s, Primitive::Triangles, both);
    } else {
      r.draw(s, Primitive::Triangles, first);
      r.draw(s, Primitive::Triangles, second);
    }
    r.flush();
  }
}

TEST(RectanglePair, TheTwoTrianglesPixelsEachOnce) {
  std::mt19937 rng(53);
  std::uniform_int_distribution<int64_t> corner(-10 * 256, 138 * 256), size(1, 60 * 256);
  for (int iter = 0; iter < 300; ++iter) {
    int64_t x0 = corner(rng), y0 = corner(rng), x1 = x0 + size(rng), y1 = y0 + (iter % 7 == 0 ? 3 : size(rng));
    if (iter % 4 == 0) {  // sides through pixel centres
      x0 = x0 / 128 * 128, y0 = y0 / 128 * 128, x1 = x1 / 128 * 128 + 128, y1 = y1 / 128 * 128 + 128;
    }
    // Corners counter-clockwise from (x0, y0); the diagonal from corner k to k + 2.
    const int64_t cx[4] = {x0, x1, x1, x0}, cy[4] = {y0, y0, y1, y1};
    const int k = iter % 2, first = iter % 3;
    int order[6] = {k, k + 1, k + 2, k, k + 2, k + 3};
    for (int& i : order) i %= 4;
    std::vector<ClipVertex> v;
    int64_t tx[2][3], ty[2][3];
    for (int i = 0; i < 6; ++i) {
      const int c = order[(i / 3) * 3 + (i % 3 + first) % 3];  // each triangle's vertices rotated
      v.push_back(at(cx[c], cy[c], 1.f / 255.f));
      tx[i / 3][i % 3] = cx[c];
      ty[i / 3][i % 3] = cy[c];
    }
    const std::vector<uint8_t> a = reference_triangle_coverage(tx[0], ty[0], kSize),
                               b = reference_triangle_coverage(tx[1], ty[1], kSize);
    std::vector<int> expected(a.size());
    for (size_t i = 0; i < a.size(); ++i) expected[i] = a[i] + b[i];
    ASSERT_EQ(draw_counted({v}), expected) << "rectangle " << iter;
  }
}

TEST(RectanglePair, StripsFansAndQuadsOfFourPairToo) {
  std::mt19937 rng(530);
  std::uniform_int_distribution<int64_t> corner(-10 * 256, 138 * 256), size(1, 60 * 256);
  for (int iter = 0; iter < 60; ++iter) {
    const int64_t x0 = corner(rng), y0 = corner(rng), x1 = x0 + size(rng), y1 = y0 + size(rng);
    const int64_t cx[4] = {x0, x1, x1, x0}, cy[4] = {y0, y0, y1, y1};  // counter-clockwise
    std::vector<ClipVertex> around;
    for (int c = 0; c < 4; ++c) around.push_back(at(cx[c], cy[c], 1.f / 255.f));
    // A fan and a quad: triangles 0 1 2 and 0 2 3; a strip 0 1 3 2: triangles 0 1 3 and 3 1 2.
    auto expected = [&](const int (&t)[2][3]) {
      std::vector<int> sum(kSize * kSize, 0);
      for (const auto& tri : t) {
        const int64_t tx[3] = {cx[tri[0]], cx[tri[1]], cx[tri[2]]}, ty[3] = {cy[tri[0]], cy[tri[1]], cy[tri[2]]};
        const std::vector<uint8_t> c = reference_triangle_coverage(tx, ty, kSize);
        for (size_t i = 0; i < c.size(); ++i) sum[i] += c[i];
      }
      return sum;
    };
    const int fan[2][3] = {{0, 1, 2}, {0, 2, 3}}, strip[2][3] = {{0, 1, 3}, {3, 1, 2}};
    ASSERT_EQ(draw_counted({around}, Primitive::TriangleFan), expected(fan)) << "fan " << iter;
    ASSERT_EQ(draw_counted({around}, Primitive::Quads), expected(fan)) << "quad " << iter;
    const std::vector<ClipVertex> zigzag = {around[0], around[1], around[3], around[2]};
    ASSERT_EQ(draw_counted({zigzag}, Primitive::TriangleStrip), expected(strip)) << "strip " << iter;
  }
}

TEST(RectanglePair, ADrawOfManyUnpairedHalvesStillGivesEachPixelOnce) {
  // 40 grid cells whose corners' values do not lie on one plane (no pair: the stage stops
  // holding halves after 16), then 10 rectangles that would pair, in one draw.
  std::vector<ClipVertex> v;
  std::vector<int> expected(kSize * kSize, 0);
  auto add_cell = [&](int64_t x0, int64_t y0, int64_t x1, int64_t y1, float bent) {
    const int64_t cx[4] = {x0, x1, x1, x0}, cy[4] = {y0, y0, y1, y1};
    const float red[4] = {1.f / 255.f, 1.f / 255.f, bent, 1.f / 255.f};
    static const int kTriangles[2][3] = {{0, 1, 2}, {0, 2, 3}};
    for (const auto& t : kTriangles) {
      int64_t tx[3], ty[3];
      for (int i = 0; i < 3; ++i) {
        v.push_back(at(cx[t[i]], cy[t[i]], red[t[i]]));
        tx[i] = cx[t[i]];
        ty[i] = cy[t[i]];
      }
      const std::vector<uint8_t> c = reference_triangle_coverage(tx, ty, kSize);
      for (size_t i = 0; i < c.size(); ++i) expected[i] += c[i];
    }
  };
  for (int i = 0; i < 40; ++i) add_cell((i % 8) * 1600 + 40, (i / 8) * 1500 + 70, (i % 8) * 1600 + 1500, (i / 8) * 1500 + 1400, 0.5f);
  for (int i = 0; i < 10; ++i) add_cell(i * 3000 + 100, 9000 + 40 * i, i * 3000 + 2900, 12000 + 33 * i, 1.f / 255.f);
  // The bent corners add their own amount where they interpolate: compare coverage only.
  std::vector<int> drawn = draw_counted({v});
  for (int& d : drawn) d = d != 0;
  for (int& e : expected) {
    ASSERT_LE(e, 1);
  }
  EXPECT_EQ(drawn, expected);
  // And the rectangles of the same draw without the grid before them, each pixel once.
  const std::vector<ClipVertex> rectangles(v.begin() + 40 * 6, v.end());
  const std::vector<int> counted = draw_counted({rectangles});
  EXPECT_EQ(*std::max_element(counted.begin(), counted.end()), 1);
}

TEST(RectanglePair, OneDrawGivesTheImageAndDepthsOfTwo) {
  // A colour ramp across a rectangle at one depth: drawn in one draw (a rectangle), then its
  // triangles each in a draw of its own (not paired) with the depth test EQUAL: every pixel passes.
  const int64_t x0 = 3 * 256 + 77, y0 = 5 * 256 + 128, x1 = 101 * 256 + 3, y1 = 90 * 256 + 200;
  auto corner = [&](int64_t x, int64_t y) {
    ClipVertex v = at(x, y, 0.f, 0.25f);
    v.color[0] = v.back_color[0] = static_cast<float>(x - x0) / static_cast<float>(x1 - x0);
    v.color[1] = v.back_color[1] = static_cast<float>(y - y0) / static_cast<float>(y1 - y0);
    return v;
  };
  const std::vector<ClipVertex> first = {corner(x0, y0), corner(x1, y0), corner(x1, y1)};
  const std::vector<ClipVertex> second = {corner(x0, y0), corner(x1, y1), corner(x0, y1)};
  OwnedFramebuffer merged(kSize, kSize), split(kSize, kSize);
  DrawState tested = state_for(kSize, kSize);
  tested.depth_test = true;
  draw_merged_and_split(tested, first, second, merged, split);
  EXPECT_EQ(merged.color, split.color);
  EXPECT_EQ(merged.depth, split.depth);
  // The split triangles over the rectangle at the same depths.
  Renderer r(1);
  r.set_framebuffer(merged.fb);
  DrawState s = state_for(kSize, kSize);
  s.depth_test = true;
  s.depth_func = CompareFunc::Equal;
  s.stencil_test = true;
  s.stencil_front.func = CompareFunc::Always;
  s.stencil_front.depth_pass = StencilOp::Incr;
  s.stencil_back = s.stencil_front;
  r.draw(s, Primitive::Triangles, first);
  r.draw(s, Primitive::Triangles, second);
  r.flush();
  int drawn = 0, passed = 0;
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) {
      drawn += merged.depth_at(i, j) != 0xffffffu;
      passed += merged.stencil_at(i, j);
    }
  EXPECT_EQ(drawn, 98 * 86);
  EXPECT_EQ(passed, drawn);
}

TEST(RectanglePair, FlatShadedHalvesPairOnlyWithOneFlatColour) {
  // GL_FLAT takes each triangle's colour from its last vertex. Both quads' colours lie on one
  // plane; the first's two provoking vertices agree (one colour: paired), the second's do not.
  const int64_t x0 = 7 * 256 + 10, y0 = 9 * 256 + 128, x1 = 77 * 256 + 1, y1 = 60 * 256 + 90;
  for (const bool one_colour : {true, false}) {
    const float c = 0.25f, p = one_colour ? 0.25f : 0.5f, d = 0.75f, q = one_colour ? 0.75f : 0.5f;
    const std::vector<ClipVertex> first = {at(x0, y0, c), at(x1, y0, p), at(x1, y1, d)};
    const std::vector<ClipVertex> second = {at(x0, y0, c), at(x1, y1, d), at(x0, y1, q)};
    OwnedFramebuffer merged(kSize, kSize), split(kSize, kSize);
    DrawState flat = state_for(kSize, kSize);
    flat.flat_shading = true;
    draw_merged_and_split(flat, first, second, merged, split);
    EXPECT_EQ(merged.color, split.color) << "one colour " << one_colour;
    EXPECT_EQ(merged.pixel(70, 15)[0], 191) << "one colour " << one_colour;  // below the diagonal: d
    EXPECT_EQ(merged.pixel(10, 55)[0], one_colour ? 191 : 128) << "one colour " << one_colour;  // above: q
  }
}

// Window vertices of a rectangle's corners (sub-pixels), with two values each.
struct Corners {
  WinVert v[4];  // (x0, y0), (x1, y0), (x1, y1), (x0, y1)
  float values[4][2];
  Corners() {
    const int64_t x[4] = {256, 2560, 2560, 256}, y[4] = {512, 512, 1280, 1280};
    for (int i = 0; i < 4; ++i) {
      v[i].x = x[i];
      v[i].y = y[i];
      v[i].fx = static_cast<double>(x[i]) / 256.0;
      v[i].fy = static_cast<double>(y[i]) / 256.0;
      v[i].z = 100.0;
      values[i][0] = static_cast<float>(i == 1 || i == 2);  // a ramp along x
      values[i][1] = 0.5f;
    }
  }
  // The half with its right angle at corner c, whose other vertices are c's neighbours.
  bool completes(int c_held, int c_new) const {
    RectangleHalf half;
    const int held[3] = {c_held, (c_held + 1) % 4, (c_held + 3) % 4};
    for (int i = 0; i < 3; ++i) half.v[i] = v[held[i]];
    int64_t x0, y0, x1, y1;
    if (!rectangle_corner(half.v[0], half.v[1], half.v[2], half.corner, x0, y0, x1, y1)) return false;
    half.x0 = x0, half.y0 = y0, half.x1 = x1, half.y1 = y1;
    const float* held_values[3] = {values[held[0]], values[held[1]], values[held[2]]};
    const int next[3] = {(c_new + 1) % 4, c_new, (c_new + 3) % 4};
    const WinPosition* w[3] = {&v[next[0]], &v[next[1]], &v[next[2]]};
    const float* w_values[3] = {values[next[0]], values[next[1]], values[next[2]]};
    return completes_rectangle(half, held_values, w, w_values, 2);
  }
};

TEST(RectanglePair, PairsOnlyOppositeHalvesOnOnePlane) {
  Corners c;
  EXPECT_TRUE(c.completes(0, 2));
  EXPECT_TRUE(c.completes(1, 3));
  EXPECT_TRUE(c.completes(3, 1));
  EXPECT_FALSE(c.completes(0, 1));  // overlapping halves
  EXPECT_FALSE(c.completes(0, 0));
  Corners bent;
  bent.values[2][1] = 0.75f;  // not on the plane of the other three
  EXPECT_FALSE(bent.completes(0, 2));
  Corners deep;
  deep.v[2].z = 101.0;  // another depth at one corner
  EXPECT_FALSE(deep.completes(0, 2));
  Corners shared_deep;
  shared_deep.v[3].z = 101.0;  // at a corner both halves share
  EXPECT_FALSE(shared_deep.completes(0, 2));
  Corners perspective;
  perspective.v[2].inv_w = 0.5;
  EXPECT_FALSE(perspective.completes(0, 2));
  Corners shared_perspective;
  shared_perspective.v[1].inv_w = 0.5;
  EXPECT_FALSE(shared_perspective.completes(0, 2));
  Corners skewed;
  skewed.v[2].fx += 1.0 / 1024.0;  // the same snapped corner, another exact one
  EXPECT_FALSE(skewed.completes(0, 2));
}

TEST(RectanglePair, OnlyRightTrianglesAlongTheAxesAreHalves) {
  WinPosition a, b, c;
  a.x = 0, a.y = 0, b.x = 512, b.y = 0, c.x = 0, c.y = 300;
  int corner = -1;
  int64_t x0, y0, x1, y1;
  ASSERT_TRUE(rectangle_corner(b, c, a, corner, x0, y0, x1, y1));
  EXPECT_EQ(corner, 2);
  EXPECT_EQ(x0, 0);
  EXPECT_EQ(x1, 512);
  EXPECT_EQ(y0, 0);
  EXPECT_EQ(y1, 300);
  c.x = 1;  // a leg off the axis
  EXPECT_FALSE(rectangle_corner(a, b, c, corner, x0, y0, x1, y1));
  c.x = 0, c.y = 0;  // degenerate
  EXPECT_FALSE(rectangle_corner(a, b, c, corner, x0, y0, x1, y1));
}

TEST(RectanglePair, TheRectanglesPixelsFollowTheFillRule) {
  RectangleHalf half;
  // Sides through the centres of columns 10 and 20 and rows 5 and 8: the left and bottom sides'
  // centres are inside, the right and top sides' outside.
  half.x0 = 10 * 256 + 128, half.x1 = 20 * 256 + 128, half.y0 = 5 * 256 + 128, half.y1 = 8 * 256 + 128;
  PrimSetup prim;
  make_rectangle(half, PixelRect{0, 0, 100, 100}, prim);
  EXPECT_EQ(prim.bounds.x0, 10);
  EXPECT_EQ(prim.bounds.x1, 20);
  EXPECT_EQ(prim.bounds.y0, 5);
  EXPECT_EQ(prim.bounds.y1, 8);
  half.x0 = 10 * 256 + 129, half.x1 = 20 * 256 + 129;  // just past the centres
  make_rectangle(half, PixelRect{0, 0, 100, 100}, prim);
  EXPECT_EQ(prim.bounds.x0, 11);
  EXPECT_EQ(prim.bounds.x1, 21);
  make_rectangle(half, PixelRect{0, 0, 15, 6}, prim);  // and the clip rectangle
  EXPECT_EQ(prim.bounds.x1, 15);
  EXPECT_EQ(prim.bounds.y1, 6);
}

}  // namespace
}  // namespace pineda::raster::test
