// WindowTransform::prepare_many: vertices in vector lanes, in two copies, baseline x86-64 (its
// 8-lane vectors are split into SSE2 ones) and AVX-512, both with the operations of prepare()
// (no FMA, no contraction), so every path gives the same windows.
#include <immintrin.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "raster/raster_limits.h"
#include "raster/window_transform.h"

// The copies pass vectors wider than the baseline's registers but only within one function.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace pineda::raster {

constexpr int kWindowLanes = 8;

namespace window_lanes_baseline {
constexpr bool kAvx512 = false;
#include "raster/window_lanes_body.inc"
}  // namespace window_lanes_baseline

#pragma GCC push_options
#pragma GCC target("avx512f,avx512dq,avx512vl")
namespace window_lanes_avx512 {
constexpr bool kAvx512 = kCopiesHaveTheirTargets;  // (clang ignores the pragma: baseline code there)
#include "raster/window_lanes_body.inc"
}  // namespace window_lanes_avx512
#pragma GCC pop_options

void WindowTransform::prepare_many(const ClipVertex* v, const float* varyings, size_t varying_count, size_t count,
                                   PreparedWindow* out, SimdPath path) const {
  const size_t done = uses_avx512(path) ? window_lanes_avx512::prepare_lanes(p_, v, varyings, varying_count, count, out)
                                        : window_lanes_baseline::prepare_lanes(p_, v, varyings, varying_count, count, out);
  for (size_t i = done; i < count; ++i) prepare(v[i], varyings + i * varying_count, out[i]);
}

}  // namespace pineda::raster
