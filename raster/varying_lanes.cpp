#include "raster/varying_lanes.h"

#include <cstring>

// The copies pass vectors wider than the baseline's registers but only within one function.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace pineda::raster::varyings_sse2 {
using VF = float __attribute__((vector_size(16)));
#include "raster/varying_lanes_body.inc"
}  // namespace pineda::raster::varyings_sse2

#pragma GCC push_options
#pragma GCC target("avx2")
namespace pineda::raster::varyings_avx2 {
using VF = float __attribute__((vector_size(32)));
#include "raster/varying_lanes_body.inc"
}  // namespace pineda::raster::varyings_avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f,avx512bw,avx512vl,avx512dq")
namespace pineda::raster::varyings_avx512 {
using VF = float __attribute__((vector_size(64)));
#include "raster/varying_lanes_body.inc"
}  // namespace pineda::raster::varyings_avx512
#pragma GCC pop_options

namespace pineda::raster {

VaryingInterpolator select_varying_interpolator(SimdPath path) {
  if (uses_avx512(path)) return &varyings_avx512::interpolate;
  return uses_avx2(path) ? &varyings_avx2::interpolate : &varyings_sse2::interpolate;
}

}  // namespace pineda::raster
