// The reference mode's triangle rasterizer (PINEDA_REFERENCE=1): a plain per-pixel loop over
// the bounding box with edge functions in double precision through the unsnapped vertices,
// the same top-left fill rule and pixel-centre sampling as the fixed-point path, and
// perspective-correct attributes and linear window depth computed in double per pixel.
#pragma once

#include "raster/draw_record.h"
#include "raster/framebuffer.h"
#include "raster/setup.h"

namespace pineda::raster {

// Rasterizes and shades the triangle into `fb` at once; returns the pixels that passed every
// test up to depth (also added to the draw's occlusion query counter).
uint64_t reference_triangle(const WinVert& a, const WinVert& b, const WinVert& c, const SetupParams& params,
                            const DrawRecord& draw, const Framebuffer& fb);

}  // namespace pineda::raster
