// Coverage inside one tile: finds the 2x2 quads a primitive touches and hands them to the
// draw's fragment routine.
#pragma once

#include "raster/draw_record.h"
#include "raster/framebuffer.h"
#include "raster/prim_setup.h"

namespace pineda::raster {

// Returns the samples that passed the depth test when the draw counts them, 0 otherwise.
uint64_t rasterize_in_tile(const PrimSetup& prim, const DrawRecord& draw, const Framebuffer& fb, const PixelRect& tile);

// Conservative: false only when no pixel centre of `rect` is inside all three edges.
bool triangle_may_touch(const PrimSetup& prim, const PixelRect& rect);

}  // namespace pineda::raster
