// The colour write of a shader block when nothing is left to decide per pixel but coverage: up
// to four quads (adjacent: 8x2 pixels, or anywhere) of an RGBA8 or BGRA8 buffer, every channel written, no
// reduction, no blending or one of blend8.h's. The same conversion (clamp, round to nearest
// even) per pixel as write_quad (quad_ops.h) and blend8.h's arithmetic, 16 lanes at a time.
#pragma once
#include <cstdint>

#include "raster/blend8.h"
#include "raster/simd_path.h"

namespace pineda::raster {

// color[c][lane]: channel c of lane 4j + i (quad j, pixel i = (i & 1, i >> 1)); shift[c]: where
// channel c goes in a pixel; row0/row1: the block's 8 pixels in its first and second row;
// live: the lanes written (only their pixels are read and written); blend: Other for none.
using BlockWriter = void (*)(const float (*color)[16], const uint32_t shift[4], Blend8 blend, uint8_t* row0,
                             uint8_t* row1, uint16_t live);

BlockWriter select_block_writer(SimdPath path);

// The same for four quads anywhere, no two at one place: rows[2j] and rows[2j + 1] are quad j's
// first and second row at its left pixel (only its live pixels are read and written; a row
// without any should point at 8 bytes anywhere: its moves are masked off).
using QuadsWriter = void (*)(const float (*color)[16], const uint32_t shift[4], Blend8 blend, uint8_t* const rows[8],
                             uint16_t live);

QuadsWriter select_quads_writer(SimdPath path);

}  // namespace pineda::raster
