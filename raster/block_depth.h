// The early depth test of a shader block without stencil: four adjacent quads (8x2 pixels)
// that lie inside the framebuffer and one tile, tested and written as quad_ops::depth_only
// tests each quad (the same window depths, comparison and writes), 16 lanes at a time.
#pragma once
#include <cstdint>

#include "raster/draw_record.h"
#include "raster/framebuffer.h"
#include "raster/prim_setup.h"
#include "raster/simd_path.h"

namespace pineda::raster {

// (x, y): the first quad's lower left pixel; ox, oy: each lane's offset from the primitive's
// reference point (lane 4j + i: quad j's pixel (i & 1, i >> 1)); quad_bits: the pixels to test,
// bit 4j + i for that lane. Returns those that pass, in the same bits. (The masks travel in a
// register: four 32-bit stores read back as one vector load would wait for the stores to retire.)
using BlockDepthTest = unsigned (*)(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y,
                                    const float* ox, const float* oy, unsigned quad_bits);

BlockDepthTest select_block_depth_test(SimdPath path);

}  // namespace pineda::raster
