// The geometry stage's cache of window vertices (raster/geometry.cpp) gives the pixels of its
// general path: an indexed mesh of more vertices than the cache has slots, with shared
// vertices, front and back faces, culling, and vertices outside the clip volume, drawn once as
// it is (cached triangles) and once with a zero polygon offset (which the cache leaves to the
// general path, with the same depth).
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "tests/raster/test_support.h"

namespace pineda::raster::test {
namespace {

constexpr int kW = 97, kH = 71;

struct Mesh {
  std::vector<ClipVertex> vertices;
  std::vector<uint32_t> indices;
};

// A grid of 60x40 cells (2501 vertices) with jittered positions, depths and colours; some
// vertices leave the view volume (beyond x = +-1, or behind the near plane), and the
// triangles refer to vertices far apart in the array (slot collisions in a 1024-slot cache).
Mesh jittered_grid() {
  constexpr int kCols = 60, kRows = 40;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> jitter(-0.02f, 0.02f), unit(0.f, 1.f);
  Mesh m;
  for (int j = 0; j <= kRows; ++j)
    for (int i = 0; i <= kCols; ++i) {
      const float x = -1.1f + 2.2f * i / kCols + jitter(rng), y = -1.05f + 2.1f * j / kRows + jitter(rng);
      const float z = (i * j) % 97 == 5 ? -1.5f : unit(rng) * 1.6f - 0.8f;
      m.vertices.push_back(vertex(x, y, z, 1.f, unit(rng), unit(rng), unit(rng), 1.f));
    }
  const uint32_t side = kCols + 1;
  for (uint32_t j = 0; j < kRows; ++j)
    for (uint32_t i = 0; i < kCols; ++i) {
      const uint32_t v = j * side + i;
      // Every third cell turned around: back faces. Every fifth also refers to the last row.
      if ((i + j) % 3 == 0) m.indices.insert(m.indices.end(), {v, v + side + 1, v + 1});
      else m.indices.insert(m.indices.end(), {v, v + 1, v + side + 1});
      const uint32_t far = (i + j) % 5 == 0 ? kRows * side + i : v + side;
      m.indices.insert(m.indices.end(), {v, v + side + 1, far});
    }
  return m;
}

struct Result {
  std::vector<uint8_t> color;
  std::vector<uint32_t> depth;
};

Result render(const Mesh& m, DrawState s) {
  OwnedFramebuffer fb(kW, kH);
  Renderer r{1};
  r.set_framebuffer(fb.fb);
  clear_all(r);
  s.depth_test = true;
  r.draw(s, Primitive::Triangles, m.vertices, m.indices);
  r.flush();
  return {fb.color, fb.depth};
}

void expect_cache_matches_general_path(DrawState s, const char* name) {
  const Mesh m = jittered_grid();
  const Result cached = render(m, s);
  s.offset_fill = true;  // factor and units 0: the same depth, through the general path
  const Result general = render(m, s);
  EXPECT_EQ(cached.color, general.color) << name;
  EXPECT_EQ(cached.depth, general.depth) << name;
  int covered = 0;
  for (const uint32_t z : cached.depth) covered += z != 0xffffffu;
  EXPECT_GT(covered, kW * kH / 8) << name;  // front faces culled: the third turned around
}

TEST(WindowCache, GivesThePixelsOfTheGeneralPath) {
  DrawState s = state_for(kW, kH);
  expect_cache_matches_general_path(s, "no culling");
  s.cull_face = true;
  s.cull_back = true;
  expect_cache_matches_general_path(s, "back faces culled");
  s.cull_back = false;
  s.cull_front = true;
  expect_cache_matches_general_path(s, "front faces culled");
  s = state_for(kW, kH);
  s.flat_shading = true;
  s.front_ccw = false;
  expect_cache_matches_general_path(s, "flat, clockwise front");
}

// The cache is the renderer's, kept from draw to draw (window_cache.h): a draw whose vertices sit
// at the same indices as the previous draw's, elsewhere, gets its own windows.
TEST(WindowCache, ADrawNeverTakesThePreviousDrawsWindows) {
  for (const Primitive mode : {Primitive::Triangles, Primitive::LineStrip}) {
    auto draw = [&](Renderer& r, float x0) {
      const std::vector<ClipVertex> v = {window_vertex(x0, 10, kW, kH), window_vertex(x0 + 30, 12, kW, kH),
                                         window_vertex(x0 + 5, 50, kW, kH)};
      r.draw(state_for(kW, kH), mode, v);
    };
    OwnedFramebuffer both(kW, kH), second(kW, kH);
    Renderer r{1}, fresh{1};
    r.set_framebuffer(both.fb);
    fresh.set_framebuffer(second.fb);
    clear_all(r);
    clear_all(fresh);
    draw(r, 5.f);
    r.flush();
    const int first_only = both.count_nonzero_red();
    clear_all(r);
    draw(r, 50.f);  // the same indices, 45 pixels to the right
    draw(fresh, 50.f);
    r.flush();
    fresh.flush();
    EXPECT_GT(first_only, 0);
    EXPECT_EQ(both.color, second.color) << (mode == Primitive::Triangles ? "triangles" : "line strip");
  }
}

}  // namespace
}  // namespace pineda::raster::test
