// Colour interpolation, flat shading's provoking vertex, facing: culling, two-sided colour,
// polygon modes with edge flags.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "tests/raster/test_support.h"

namespace pineda::raster::test {
namespace {

ClipVertex coloured(float x, float y, float r, float g = 0.f) {
  ClipVertex v = vertex(x, y, 0, 1, r, g, 0, 1);
  return v;
}

TEST(Shading, SmoothGradientIsExact) {
  OwnedFramebuffer fb(256, 2);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  r.draw(state_for(256, 2), Primitive::Quads,
         std::vector<ClipVertex>{coloured(-1, -1, 0), coloured(1, -1, 1), coloured(1, 1, 1), coloured(-1, 1, 0)});
  r.flush();
  for (int x = 0; x < 256; ++x) {
    const int expect = static_cast<int>((x + 0.5) / 256.0 * 255.0 + 0.5);
    ASSERT_EQ(fb.pixel(x, 0)[0], expect) << x;
    ASSERT_EQ(fb.pixel(x, 1)[0], expect) << x;
  }
}

TEST(Shading, PerspectiveCorrectInterpolation) {
  // A quad whose right side is 4 times farther (w = 4): colour is linear in clip space, so at a
  // window position the value is the hyperbolic mix. Within 1/255 of the exact value.
  OwnedFramebuffer fb(64, 4);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  const float w1 = 4.f;
  std::vector<ClipVertex> v{coloured(-1, -1, 0), coloured(w1, -w1, 1), coloured(w1, w1, 1), coloured(-1, 1, 0)};
  v[1].clip[3] = v[2].clip[3] = w1;
  r.draw(state_for(64, 4), Primitive::Quads, v);
  r.flush();
  for (int x = 0; x < 64; ++x) {
    const double t = (x + 0.5) / 64.0;  // window-space fraction
    const double exact = (t / w1) / ((1 - t) / 1.0 + t / w1);
    EXPECT_NEAR(fb.pixel(x, 1)[0], exact * 255.0, 1.0) << x;
  }
}

// Draws `v` in `mode` flat shaded, each vertex a different red level i/16, and returns the set
// of red values found in the framebuffer.
std::set<int> flat_reds(Primitive mode, int count, bool strip_layout = false) {
  OwnedFramebuffer fb(64, 64);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  std::vector<ClipVertex> v;
  for (int i = 0; i < count; ++i) {
    // Points on a circle: every mode yields non-degenerate primitives.
    const double a = 2 * 3.14159265358979 * i / count;
    float x = static_cast<float>(0.9 * std::cos(a)), y = static_cast<float>(0.9 * std::sin(a));
    if (strip_layout) {  // two rows, as quad strips want them
      x = -0.9f + 0.6f * (i / 2);
      y = i % 2 ? 0.8f : -0.8f;
    }
    v.push_back(coloured(x, y, (i + 1) / 16.f));
  }
  DrawState s = state_for(64, 64);
  s.flat_shading = true;
  r.draw(s, mode, v);
  r.flush();
  std::set<int> reds;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      if (fb.pixel(x, y)[0]) reds.insert((fb.pixel(x, y)[0] * 16 + 127) / 255 - 1);
  return reds;
}

TEST(Shading, FlatShadingUsesTheProvokingVertex) {
  EXPECT_EQ(flat_reds(Primitive::Triangles, 6), (std::set<int>{2, 5}));
  EXPECT_EQ(flat_reds(Primitive::TriangleStrip, 5), (std::set<int>{2, 3, 4}));
  EXPECT_EQ(flat_reds(Primitive::TriangleFan, 5), (std::set<int>{2, 3, 4}));
  EXPECT_EQ(flat_reds(Primitive::Quads, 8), (std::set<int>{3, 7}));
  EXPECT_EQ(flat_reds(Primitive::QuadStrip, 6, true), (std::set<int>{3, 5}));
  EXPECT_EQ(flat_reds(Primitive::Polygon, 6), (std::set<int>{0}));
  EXPECT_EQ(flat_reds(Primitive::Lines, 4), (std::set<int>{1, 3}));
  EXPECT_EQ(flat_reds(Primitive::LineStrip, 4), (std::set<int>{1, 2, 3}));
  EXPECT_EQ(flat_reds(Primitive::LineLoop, 4), (std::set<int>{0, 1, 2, 3}));
}

// A quad whose only lit corner is v1 (lower right): split along v0-v2 (Mesa's choice for draws
// that need no clipping) the upper-left half stays black; split along v1-v3 (its choice once a
// vertex of the draw leaves the view volume) v1 reaches into that half.
TEST(Shading, QuadsSplitLikeMesa) {
  for (const bool clipped_draw : {false, true}) {
    OwnedFramebuffer fb(16, 16);
    Renderer r(1);
    r.set_framebuffer(fb.fb);
    clear_all(r);
    std::vector<ClipVertex> v{coloured(-1, -1, 0), coloured(1, -1, 1), coloured(1, 1, 0), coloured(-1, 1, 0)};
    if (clipped_draw) {  // a second, invisible quad outside the view volume
      for (int i = 0; i < 4; ++i) v.push_back(coloured(5.f + i % 2, 5.f + i / 2, 0));
    }
    r.draw(state_for(16, 16), Primitive::Quads, v);
    r.flush();
    EXPECT_EQ(fb.pixel(2, 12)[0] != 0, clipped_draw);
    EXPECT_NE(fb.pixel(12, 2)[0], 0);
  }
}

struct FaceResult {
  int covered;
  uint8_t red;
};

FaceResult draw_face(const DrawState& s, bool clockwise) {
  OwnedFramebuffer fb(8, 8);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  std::vector<ClipVertex> v{vertex(-1, -1), vertex(1, -1), vertex(1, 1), vertex(-1, 1)};
  for (auto& p : v) {
    p.color[0] = 1.f;
    p.back_color[0] = 0.2f;
  }
  if (clockwise) std::swap(v[1], v[3]);
  r.draw(s, Primitive::Quads, v);
  r.flush();
  return {fb.count_nonzero_red(), fb.pixel(3, 3)[0]};
}

TEST(Shading, CullingAndTwoSidedColour) {
  DrawState s = state_for(8, 8);
  EXPECT_EQ(draw_face(s, false).red, 255);
  EXPECT_EQ(draw_face(s, true).red, 51);  // back face: back colour
  s.cull_face = true;
  s.cull_back = true;
  EXPECT_EQ(draw_face(s, true).covered, 0);
  EXPECT_EQ(draw_face(s, false).covered, 64);
  s.front_ccw = false;
  EXPECT_EQ(draw_face(s, false).covered, 0);
  EXPECT_EQ(draw_face(s, true).red, 255);
  s.cull_front = true;
  EXPECT_EQ(draw_face(s, true).covered, 0);
  EXPECT_EQ(draw_face(s, false).covered, 0);
}

TEST(Shading, PolygonModeLineDrawsFlaggedEdgesOnly) {
  OwnedFramebuffer fb(32, 32);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  DrawState s = state_for(32, 32);
  s.polygon_front = PolygonMode::Line;
  // Window square (4.5,4.5)-(20.5,20.5); the edge from the 3rd to the 4th vertex is not flagged.
  std::vector<ClipVertex> v{window_vertex(4.5, 4.5, 32, 32), window_vertex(20.5, 4.5, 32, 32),
                            window_vertex(20.5, 20.5, 32, 32), window_vertex(4.5, 20.5, 32, 32)};
  v[2].edge_flag = false;
  r.draw(s, Primitive::Quads, v);
  r.flush();
  EXPECT_EQ(fb.count_nonzero_red(), 16 * 3);
  EXPECT_NE(fb.pixel(4, 4)[0], 0);
  EXPECT_EQ(fb.pixel(12, 20)[0], 0);  // the unflagged top edge
  EXPECT_EQ(fb.pixel(12, 12)[0], 0);  // interior
}

TEST(Shading, PolygonModePointDrawsFlaggedVertices) {
  OwnedFramebuffer fb(32, 32);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  DrawState s = state_for(32, 32);
  s.polygon_front = s.polygon_back = PolygonMode::Point;
  std::vector<ClipVertex> v{window_vertex(4.5, 4.5, 32, 32), window_vertex(20.5, 4.5, 32, 32),
                            window_vertex(20.5, 20.5, 32, 32)};
  v[1].edge_flag = false;
  r.draw(s, Primitive::Triangles, v);
  r.flush();
  EXPECT_EQ(fb.count_nonzero_red(), 2);
  EXPECT_NE(fb.pixel(4, 4)[0], 0);
  EXPECT_NE(fb.pixel(20, 20)[0], 0);
}

}  // namespace
}  // namespace pineda::raster::test
