// The quads of triangles over areas of a tile up to 16 pixels a side (tile_raster.cpp's small
// path, which steps the edges quad by quad) against the definition: a pixel is covered when all
// three edge functions are >= 0 at its centre, for coefficients of every magnitude.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>

#include "raster/tile_raster.h"

namespace pineda::raster {
namespace {

int64_t edge_value(const EdgeFunction& e, int x, int y) {
  return e.a * (int64_t{x} * kSubpixelOne + kSubpixelHalf) + e.b * (int64_t{y} * kSubpixelOne + kSubpixelHalf) + e.c;
}

// Compares every pixel of the tile at (x0, y0) for the primitive's edges over `area`.
void expect_definition(const PrimSetup& prim, const PixelRect& area, int x0, int y0, int case_index) {
  TileSampleMasks masks;
  masks.x0 = x0;
  masks.y0 = y0;
  std::memset(masks.quads, 0, sizeof masks.quads);
  add_sample_masks(prim, area, 0, masks);
  for (int y = y0; y < y0 + kTileSize; ++y)
    for (int x = x0; x < x0 + kTileSize; ++x) {
      const bool in_area = x >= area.x0 && x < area.x1 && y >= area.y0 && y < area.y1;
      bool inside = in_area;
      for (const EdgeFunction& e : prim.edges) inside = inside && edge_value(e, x, y) >= 0;
      const int bit = (x & 1) | ((y & 1) << 1);
      const bool got = (masks.quads[(y - y0) / 2][(x - x0) / 2] >> bit) & 1u;
      ASSERT_EQ(got, inside) << "case " << case_index << " pixel " << x << "," << y;
    }
}

TEST(SmallAreaCoverage, RandomEdgesOfEveryMagnitudeMatchTheDefinition) {
  std::mt19937_64 rng(7);
  const int x0 = 3 * kTileSize, y0 = 5 * kTileSize;
  for (int i = 0; i < 4000; ++i) {
    // Coefficients from those of a few-pixel triangle to ones whose values pass 32 bits.
    const int magnitude = 4 + static_cast<int>(rng() % 24);
    std::uniform_int_distribution<int64_t> coefficient(-(int64_t{1} << magnitude), int64_t{1} << magnitude);
    PrimSetup prim;
    prim.kind = CoverageKind::Triangle;
    std::uniform_int_distribution<int> corner(0, kTileSize - 1), side(1, 16);
    const int ax = x0 + corner(rng), ay = y0 + corner(rng);
    const PixelRect area{ax, ay, std::min(ax + side(rng), x0 + kTileSize), std::min(ay + side(rng), y0 + kTileSize)};
    // Each edge passes near a pixel of the area, so that the areas are partly covered.
    std::uniform_int_distribution<int> px(area.x0, area.x1 - 1), py(area.y0, area.y1 - 1);
    for (EdgeFunction& e : prim.edges) {
      e.a = coefficient(rng);
      e.b = coefficient(rng);
      e.c = 0;
      e.c = -edge_value(e, px(rng), py(rng)) + static_cast<int64_t>(rng() % 512) - 256;
    }
    prim.bounds = area;
    expect_definition(prim, area, x0, y0, i);
  }
}

TEST(SmallAreaCoverage, EdgeValuesAtThe32BitLimits) {
  const int x0 = 0, y0 = 0;
  const PixelRect area{1, 2, 17, 18};  // 16 wide from an odd column: the last quad half outside
  for (const int64_t c : {int64_t{INT32_MAX}, int64_t{INT32_MAX} + 1, int64_t{INT32_MIN}, int64_t{INT32_MIN} - 1}) {
    PrimSetup prim;
    prim.kind = CoverageKind::Triangle;
    prim.edges[0] = {1, 0, c - 300 * kSubpixelOne};  // crosses 0 inside the area only for c near 0
    prim.edges[1] = {0, 1, c};
    prim.edges[2] = {-1, -1, c};
    prim.bounds = area;
    expect_definition(prim, area, x0, y0, static_cast<int>(c & 0xffff));
  }
}

}  // namespace
}  // namespace pineda::raster
