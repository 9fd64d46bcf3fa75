// The small-area quad masks (raster/small_area_masks.h) of every copy against the definition:
// a pixel is set when it lies in the area and its centre is inside all three edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>

#include "raster/raster_limits.h"
#include "raster/setup.h"
#include "raster/small_area_masks.h"

namespace pineda::raster {
namespace {

bool inside(const PrimSetup& p, int x, int y) {
  for (const EdgeFunction& e : p.edges)
    if (e.a * (x * kSubpixelOne + kSubpixelHalf) + e.b * (y * kSubpixelOne + kSubpixelHalf) + e.c < 0) return false;
  return true;
}

PrimSetup triangle(double x0, double y0, double x1, double y1, double x2, double y2) {
  WinVert v[3];
  const double xy[3][2] = {{x0, y0}, {x1, y1}, {x2, y2}};
  for (int i = 0; i < 3; ++i) {
    v[i].fx = xy[i][0];
    v[i].fy = xy[i][1];
    v[i].x = std::llround(xy[i][0] * kSubpixelOne);
    v[i].y = std::llround(xy[i][1] * kSubpixelOne);
  }
  SetupParams params;
  params.clip = {0, 0, 4096, 4096};
  PrimSetup p;
  if (!setup_triangle(v[0], v[1], v[2], params, p)) p.bounds = {};
  return p;
}

// The masks of `path` for the area, checked pixel by pixel; returns the pixels set.
int covered(const PrimSetup& p, const PixelRect& area, SimdPath path) {
  uint8_t masks[kSmallAreaQuadRows][kSmallAreaRowBytes];
  const int count = select_small_area_masks(path)(p, area, masks);
  const int x0 = area.x0 & ~1, y0 = area.y0 & ~1;
  EXPECT_EQ(count, (area.x1 - x0 + 1) / 2);
  int set = 0;
  for (int r = 0; y0 + 2 * r < area.y1; ++r)
    for (int q = 0; q < count; ++q)
      for (int i = 0; i < 4; ++i) {
        const int x = x0 + 2 * q + (i & 1), y = y0 + 2 * r + (i >> 1);
        const bool want = x >= area.x0 && x < area.x1 && y >= area.y0 && y < area.y1 && inside(p, x, y);
        const bool got = (masks[r][q] >> i) & 1;
        EXPECT_EQ(got, want) << "pixel " << x << "," << y << " path " << static_cast<int>(path);
        set += got;
      }
  return set;
}

TEST(SmallAreaMasks, EveryCopySetsThePixelsInsideTheEdgesAndTheArea) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> pos(1000.0, 1040.0), offset(-20.0, 20.0);
  std::uniform_int_distribution<int> side(1, kSmallAreaSide), start(-8, 24);
  int pixels = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double cx = pos(rng), cy = pos(rng);
    // Slivers on every fifth: one vertex near the line of the other two.
    const double x2 = trial % 5 ? cx + offset(rng) : cx + 30.0 + offset(rng) * 0.01;
    const PrimSetup p = triangle(cx, cy, cx + 30.0, cy + offset(rng), x2, cy + offset(rng));
    const int ax = static_cast<int>(cx) + start(rng), ay = static_cast<int>(cy) - 12 + start(rng);
    const PixelRect area = intersect(p.bounds, PixelRect{ax, ay, ax + side(rng), ay + side(rng)});
    if (area.empty()) continue;
    const int scalar = covered(p, area, SimdPath::Baseline);
    EXPECT_EQ(covered(p, area, SimdPath::Best), scalar);
    pixels += scalar;
  }
  EXPECT_GT(pixels, 150000) << pixels;  // the areas are mostly covered in part, often wholly
}

// Random areas of `sides` pixels each way from near a triangle's first vertex, the other two
// within `near` pixels of it on odd trials (edge values that fit 32 bits there) and within 4000
// on even ones (they do not: the AVX-512 copy falls back to 64-bit lanes): every copy's masks
// against the definition. Returns the areas and the pixels set.
std::pair<int, int> compare_areas_near_and_far(unsigned seed, double near, std::uniform_int_distribution<int> sides,
                                               std::uniform_int_distribution<int> start) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> pos(1000.0, 1040.0), small(-near, near), large(-4000.0, 4000.0);
  int pixels = 0, areas = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double cx = pos(rng), cy = pos(rng);
    auto offset = [&]() { return trial % 2 ? small(rng) : large(rng); };
    const PrimSetup p = triangle(cx, cy, cx + offset(), cy + offset(), cx + offset(), cy + offset());
    const int ax = static_cast<int>(cx) + start(rng), ay = static_cast<int>(cy) + start(rng);
    const PixelRect area = intersect(p.bounds, PixelRect{ax, ay, ax + sides(rng), ay + sides(rng)});
    if (area.empty()) continue;
    const int scalar = covered(p, area, SimdPath::Baseline);
    EXPECT_EQ(covered(p, area, SimdPath::Best), scalar);
    pixels += scalar;
    ++areas;
  }
  return {areas, pixels};
}

// Areas of at most two quads by two (the AVX-512 copy's one-vector case): triangles of a few
// pixels and corners of triangles thousands of pixels wide.
TEST(SmallAreaMasks, AreasOfFourQuadsNearAndFarFromTheVertices) {
  const auto [areas, pixels] = compare_areas_near_and_far(5, 3.0, std::uniform_int_distribution<int>(1, 4),
                                                          std::uniform_int_distribution<int>(-2, 2));
  EXPECT_GT(areas, 10000);
  EXPECT_GT(pixels, 15000) << pixels;
}

// Areas of at most four quads by four (the AVX-512 copy's vector per quad row): triangles of a
// dozen pixels and corners of triangles thousands of pixels wide.
TEST(SmallAreaMasks, AreasOfFourQuadRowsNearAndFarFromTheVertices) {
  const auto [areas, pixels] = compare_areas_near_and_far(7, 7.0, std::uniform_int_distribution<int>(5, 8),
                                                          std::uniform_int_distribution<int>(-3, 3));
  EXPECT_GT(areas, 10000);
  EXPECT_GT(pixels, 100000) << pixels;
}

// A right triangle over a 16x16 area from odd corners (9 quad rows of 9 quads), its slanted side
// on y = x + 100.25: the pixel centres above it, (dx, dy) from the corner with dy > dx (none lies
// on a side).
TEST(SmallAreaMasks, AnOddAreaUnderADiagonal) {
  const PrimSetup p = triangle(101.0, 201.25, 117.0, 217.25, 101.0, 217.25);
  const PixelRect area{101, 201, 117, 217};
  for (const SimdPath path : {SimdPath::Baseline, SimdPath::Best}) EXPECT_EQ(covered(p, area, path), 120);
}

}  // namespace
}  // namespace pineda::raster
