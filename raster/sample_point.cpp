#include "raster/sample_point.h"

#include "raster/raster_limits.h"
#include "raster/setup.h"

namespace pineda::raster {

PixelRect sample_point_bounds(const SamplePoint& p) {
  const int64_t half = (int64_t{p.size} + 1) / 2;
  auto first = [&](int64_t c) { return static_cast<int>(floor_div(c - half, kSubpixelOne)); };
  auto last = [&](int64_t c) { return static_cast<int>(floor_div(c + half, kSubpixelOne)); };
  return {first(p.x), first(p.y), last(p.x) + 1, last(p.y) + 1};
}

}  // namespace pineda::raster
