// The shader block's lane helpers (varying_lanes.h, block_write.h) in three copies: baseline
// x86-64, AVX2 and AVX-512, the same operations per lane in each.
#include <cstring>

#include "raster/block_write.h"
#include "raster/varying_lanes.h"

// The copies pass vectors wider than the baseline's registers but only within one function.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace pineda::raster::block_lanes_sse2 {
using VF = float __attribute__((vector_size(16)));
#include "raster/block_lanes_types.inc"
#include "raster/block_write_body.inc"
#include "raster/varying_lanes_body.inc"
}  // namespace pineda::raster::block_lanes_sse2

#pragma GCC push_options
#pragma GCC target("avx2")
namespace pineda::raster::block_lanes_avx2 {
using VF = float __attribute__((vector_size(32)));
#include "raster/block_lanes_types.inc"
#include "raster/block_write_body.inc"
#include "raster/varying_lanes_body.inc"
}  // namespace pineda::raster::block_lanes_avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f,avx512bw,avx512vl,avx512dq")
namespace pineda::raster::block_lanes_avx512 {
using VF = float __attribute__((vector_size(64)));
#include "raster/block_lanes_types.inc"
#include "raster/block_write_body.inc"
#include "raster/varying_lanes_body.inc"
}  // namespace pineda::raster::block_lanes_avx512
#pragma GCC pop_options

namespace pineda::raster {

VaryingInterpolator select_varying_interpolator(SimdPath path) {
  if (uses_avx512(path)) return &block_lanes_avx512::interpolate;
  return uses_avx2(path) ? &block_lanes_avx2::interpolate : &block_lanes_sse2::interpolate;
}

BlockWriter select_block_writer(SimdPath path) {
  if (uses_avx512(path)) return &block_lanes_avx512::write_block;
  return uses_avx2(path) ? &block_lanes_avx2::write_block : &block_lanes_sse2::write_block;
}

}  // namespace pineda::raster
