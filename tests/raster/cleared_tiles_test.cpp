// A clear skips the tiles that still hold its value (cleared_tiles.h): only where the renderer
// was told nothing else wrote the buffers (flush_for_reading), never after a plain flush.
#include <gtest/gtest.h>

#include "raster/cleared_tiles.h"
#include "tests/raster/test_support.h"

namespace pineda::raster::test {
namespace {

constexpr int kTilesW = 150, kTilesH = 100;  // 3 x 2 tiles, partial on both axes

// A byte written behind the renderer's back: it survives a clear only if the clear skipped
// the tile (the test's way of seeing the skip; a real writer would call flush first).
struct MarkedFramebuffer {
  OwnedFramebuffer fb{kTilesW, kTilesH};
  ClearedTiles tiles;
  Renderer r{1};
  MarkedFramebuffer() {
    fb.fb.cleared_tiles = &tiles;
    r.set_framebuffer(fb.fb);
  }
  void mark(int x, int y) {
    fb.color[(static_cast<size_t>(y) * kTilesW + x) * 4 + 1] = 77;
    fb.depth[static_cast<size_t>(y) * kTilesW + x] = 1234;
    fb.stencil_buf[static_cast<size_t>(y) * kTilesW + x] = 9;
  }
  // A clear, run by a flush that keeps what is known of cleared tiles (as glFinish's does).
  void clear_for_reading(float red, double depth, int stencil) {
    clear_all(r, red, depth, stencil);
    r.flush_for_reading();
  }
  bool marked(int x, int y) const {
    return fb.pixel(x, y)[1] == 77 && fb.depth_at(x, y) == 1234 && fb.stencil_at(x, y) == 9;
  }
};

TEST(ClearedTiles, TheSameClearSkipsTilesKnownToHoldItsValue) {
  MarkedFramebuffer m;
  m.clear_for_reading(1.f, 1.0, 3);
  m.mark(10, 10);    // tile (0, 0)
  m.mark(140, 90);   // tile (2, 1), partial
  m.clear_for_reading(1.f, 1.0, 3);
  EXPECT_TRUE(m.marked(10, 10));
  EXPECT_TRUE(m.marked(140, 90));
  EXPECT_EQ(m.fb.pixel(11, 10)[0], 255);
}

TEST(ClearedTiles, APlainFlushForgetsWhatIsKnown) {
  MarkedFramebuffer m;
  clear_all(m.r, 1.f, 1.0, 3);
  m.r.flush();
  m.mark(10, 10);
  m.clear_for_reading(1.f, 1.0, 3);
  EXPECT_FALSE(m.marked(10, 10));
  EXPECT_EQ(m.fb.pixel(10, 10)[1], 0);
  EXPECT_EQ(m.fb.depth_at(10, 10), 0xffffffu);
  EXPECT_EQ(m.fb.stencil_at(10, 10), 3);
}

TEST(ClearedTiles, AnotherValueIsWritten) {
  MarkedFramebuffer m;
  m.clear_for_reading(1.f, 1.0, 3);
  m.mark(10, 10);
  m.clear_for_reading(0.f, 0.5, 4);
  EXPECT_EQ(m.fb.pixel(10, 10)[0], 0);
  EXPECT_EQ(m.fb.pixel(10, 10)[1], 0);
  EXPECT_EQ(m.fb.depth_at(10, 10), 0x800000u);  // 0.5 of 24 bits, rounded
  EXPECT_EQ(m.fb.stencil_at(10, 10), 4);
}

TEST(ClearedTiles, APrimitiveInATileMakesItUnknown) {
  MarkedFramebuffer m;
  clear_all(m.r, 1.f, 1.0, 3);
  // A triangle inside tile (0, 0) only.
  const ClipVertex v[3] = {window_vertex(2, 2, kTilesW, kTilesH), window_vertex(30, 2, kTilesW, kTilesH), window_vertex(2, 30, kTilesW, kTilesH)};
  m.r.draw(state_for(kTilesW, kTilesH), Primitive::Triangles, v);
  m.r.flush_for_reading();
  m.mark(40, 40);  // tile (0, 0), outside the triangle
  m.mark(100, 40);  // tile (1, 0)
  m.clear_for_reading(1.f, 1.0, 3);
  EXPECT_FALSE(m.marked(40, 40));
  EXPECT_TRUE(m.marked(100, 40));
  EXPECT_EQ(m.fb.pixel(5, 5)[1], 0);  // the triangle's white is cleared
}

TEST(ClearedTiles, ScissoredOrMaskedClearsLeaveTheirTilesUnknown) {
  MarkedFramebuffer m;
  clear_all(m.r, 1.f, 1.0, 3);
  ClearState partial;
  partial.color = partial.depth = partial.stencil = true;
  partial.scissor_test = true;
  partial.scissor = {0, 0, 20, 20};  // part of tile (0, 0)
  m.r.clear(partial);
  ClearState masked;
  masked.color = masked.stencil = true;
  masked.color_write = {false, true, false, false};
  masked.stencil_write_mask = 0x0f;
  masked.color_value[1] = 1.f;
  masked.stencil_value = 0xff;
  masked.scissor_test = true;
  masked.scissor = {64, 0, 64, 64};  // all of tile (1, 0): x, y, width, height
  m.r.clear(masked);
  m.r.flush_for_reading();
  m.mark(40, 40);
  m.mark(100, 40);
  m.mark(140, 40);  // tile (2, 0): still known
  m.clear_for_reading(1.f, 1.0, 3);
  EXPECT_FALSE(m.marked(40, 40));
  EXPECT_FALSE(m.marked(100, 40));
  EXPECT_TRUE(m.marked(140, 40));
  EXPECT_EQ(m.fb.pixel(5, 5)[0], 255);
  EXPECT_EQ(m.fb.pixel(100, 10)[1], 0);
  EXPECT_EQ(m.fb.stencil_at(100, 10), 3);
}

TEST(ClearedTiles, OnlyTheClearedBuffersAreSkipped) {
  ClearRecord clear;
  clear.rect = {0, 0, 64, 64};
  clear.color = clear.depth = true;
  clear.rgba[0] = 255;
  clear.color_write[0] = {true, true, true, true};
  clear.depth_value = 7;
  ClearedTile known;
  known.stencil = true;
  known.stencil_value = 2;
  ClearRecord first = clear;
  skip_cleared_buffers(first, {0, 0, 64, 64}, known);
  EXPECT_TRUE(first.color && first.depth);
  EXPECT_TRUE(known.color && known.depth && known.stencil);
  ClearRecord second = clear;
  second.depth_value = 8;
  skip_cleared_buffers(second, {0, 0, 64, 64}, known);
  EXPECT_FALSE(second.color);
  EXPECT_TRUE(second.depth);
  EXPECT_EQ(known.depth_value, 8u);
  // A clear that covers part of the tile writes and leaves the buffer unknown.
  ClearRecord part = clear;
  part.rect = {0, 0, 32, 64};
  part.rgba[0] = 0;
  skip_cleared_buffers(part, {0, 0, 64, 64}, known);
  EXPECT_TRUE(part.color);
  EXPECT_FALSE(known.color);
  EXPECT_TRUE(known.stencil);
}

}  // namespace
}  // namespace pineda::raster::test
