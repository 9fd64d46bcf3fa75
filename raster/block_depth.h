// The early depth test of a shader block without stencil, tested and written as
// quad_ops::depth_only tests each quad (the same window depths, comparison and writes), 16 lanes
// at a time: four adjacent quads (8x2 pixels) of one primitive that lie inside the framebuffer
// and one tile, or up to four quads apart in one tile.
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

// Up to four quads of a block anywhere in one tile, each of its own primitive, each inside the
// framebuffer, no two at one place: quad j's lower left pixel (x[j], y[j]), its primitive prim[j]
// (every entry set: a missing quad repeats quad 0).
struct BlockQuads {
  int x[4], y[4];
  const PrimSetup* prim[4];
};

// The early depth test without stencil of such quads, as quad_ops::depth_only tests each: lanes
// and bits in quad order (lane 4j + i: quad j's pixel (i & 1, i >> 1)); returns the pixels of
// quad_bits that pass.
using QuadsDepthTest = unsigned (*)(const DrawRecord& d, const BlockQuads& quads, const Framebuffer& fb,
                                    const float* ox, const float* oy, unsigned quad_bits);

QuadsDepthTest select_quads_depth_test(SimdPath path);

}  // namespace pineda::raster
