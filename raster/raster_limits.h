// Fixed sizes of the rasterizer: sub-pixel precision, tiles, guard band.
#pragma once
#include <cstdint>

namespace pineda::raster {

constexpr int kSubpixelBits = 8;
constexpr int64_t kSubpixelOne = int64_t{1} << kSubpixelBits;  // 1 pixel in sub-pixel units
constexpr int64_t kSubpixelHalf = kSubpixelOne / 2;            // a pixel centre's offset

constexpr int kTileSize = 64;
constexpr int kTileShift = 6;

// Window coordinates inside [-kGuardBand, kGuardBand] are rasterized directly; primitives
// reaching beyond are clipped geometrically. With 8 sub-pixel bits the edge functions then
// stay far inside int64 (|a|,|b| < 2^25, |c| < 2^50).
constexpr double kGuardBand = 32768.0;

// Largest framebuffer dimension rendered to; beyond it nothing is drawn.
constexpr int kMaxRenderSize = 32768;

// Largest point size and line width honoured.
constexpr int kMaxPointSize = 2048;
constexpr int kMaxLineWidth = 2048;

}  // namespace pineda::raster
