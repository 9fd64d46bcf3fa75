// The quad masks of a triangle over a small area (at most kSmallAreaSide pixels each way, inside
// one tile): each quad's pixels whose centres lie inside all three edges and inside the area, for
// every quad row of the area. Most of a dense mesh's triangles are rasterized this way
// (tile_raster.cpp). A scalar copy and an AVX-512 one (an area of two quads by two in one
// vector, of four by four in a vector per quad row, else eight quads a vector); the same masks.
#pragma once
#include <cstdint>

#include "raster/prim_setup.h"
#include "raster/simd_path.h"

namespace pineda::raster {

constexpr int kSmallAreaSide = 16;
// An area of 16 rows from an odd one spans 9 quad rows; 16 columns from an odd one, 9 quads.
constexpr int kSmallAreaQuadRows = kSmallAreaSide / 2 + 1;
constexpr int kSmallAreaQuads = kSmallAreaSide / 2 + 1;
constexpr int kSmallAreaRowBytes = 16;  // a row's masks: two groups of eight quads

// Quad row r is pixel rows y0 + 2r and y0 + 2r + 1 with y0 = area.y0 & ~1; quad q of a row is
// columns x0 + 2q and x0 + 2q + 1 with x0 = area.x0 & ~1; bit i of a mask is pixel (i & 1, i >> 1)
// of its quad. Fills the area's rows and quads; returns the number of quads per row.
using SmallAreaMasks = int (*)(const PrimSetup& p, const PixelRect& area,
                               uint8_t (*masks)[kSmallAreaRowBytes]);

SmallAreaMasks select_small_area_masks(SimdPath path);

}  // namespace pineda::raster
