// Lines and points in reference mode: their coverage is the fixed-point path's (exact integer
// spans and squares); their planes are evaluated in double at each pixel centre and shaded at
// once, on the calling thread, by the reference fragment stage.
#pragma once
#include <cstdint>

#include "raster/draw_record.h"
#include "raster/framebuffer.h"
#include "raster/prim_setup.h"

namespace pineda::raster {

// Returns the pixels that passed every test up to depth (also added to the draw's occlusion
// query counter).
uint64_t reference_lines_points(const PrimSetup& prim, const DrawRecord& draw, const Framebuffer& fb);

// The QuadRoutine behind it (installed in the draw record of every reference-mode draw).
uint32_t reference_plane_quads(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, int count,
                               const uint8_t* masks);

}  // namespace pineda::raster
