// Multisampled points (GL 1.5 section 3.3.3): whatever POINT_SMOOTH says, a point covers the
// samples inside the disc of its size centred on it, or a point sprite those inside its square.
// Rasterized once per sample with the point moved by the sample's offset (multisample.cpp), as
// triangles are with their edges.
#pragma once
#include <cstdint>

#include "raster/prim_setup.h"

namespace pineda::raster {

// Whether the point covers position (x, y), in sub-pixels. The disc is closed; the square
// takes its left and bottom sides (the fill rule llvmpipe's sprites follow).
inline bool sample_point_covers(const SamplePoint& p, int64_t x, int64_t y) {
  const int64_t dx = 2 * (x - p.x), dy = 2 * (y - p.y), size = int64_t{p.size};
  if (p.square) return -size <= dx && dx < size && -size <= dy && dy < size;
  return dx * dx + dy * dy <= size * size;
}

// The pixels whose samples the point may cover: those its bounding square touches.
PixelRect sample_point_bounds(const SamplePoint& p);

}  // namespace pineda::raster
