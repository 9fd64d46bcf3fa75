// Coverage inside one tile: finds the 2x2 quads a primitive touches and hands them to the
// draw's fragment routine.
#pragma once

#include "raster/draw_record.h"
#include "raster/framebuffer.h"
#include "raster/prim_setup.h"
#include "raster/raster_limits.h"

namespace pineda::raster {

class ShaderQuadBatch;

// Returns the samples that passed the depth test when the draw counts them, 0 otherwise. With a
// batch (which must take the draw: ShaderQuadBatch::takes), the quads go there, and their samples
// come from its flush.
uint64_t rasterize_in_tile(const PrimSetup& prim, const DrawRecord& draw, const Framebuffer& fb, const PixelRect& tile,
                           ShaderQuadBatch* batch = nullptr);

// The quads of a tile a multisampled primitive covers: quad (r, q) is at (x0 + 2q, y0 + 2r),
// and its bits 4s to 4s + 3 are sample s's quad mask (bit i: pixel (i & 1, i >> 1) of the quad).
struct TileSampleMasks {
  int x0 = 0, y0 = 0;  // the tile's first pixel (even)
  uint16_t quads[kTileSize / 2][kTileSize / 2];
};

// Adds the quad masks of `prim` (moved to sample `sample`) in `area`, a part of out's tile whose
// quads are zero in that sample's bits.
void add_sample_masks(const PrimSetup& prim, const PixelRect& area, int sample, TileSampleMasks& out);

// Conservative: false only when no pixel centre of `rect` is inside all three edges.
bool triangle_may_touch(const PrimSetup& prim, const PixelRect& rect);

}  // namespace pineda::raster
