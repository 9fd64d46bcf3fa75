// Four-lane vectors, one lane per pixel of a 2x2 quad (GCC/Clang vector extensions; SSE2 on
// x86-64). Lane i is pixel (x + (i & 1), y + (i >> 1)).
#pragma once
#include <cstdint>
#include <cmath>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace pineda::raster {

using F4 = float __attribute__((vector_size(16)));
using I4 = int32_t __attribute__((vector_size(16)));
using U4 = uint32_t __attribute__((vector_size(16)));

inline F4 splat(float v) { return F4{v, v, v, v}; }

// NaN-safe clamp to [0, 1]: NaN lanes become 0.
inline F4 clamp01(F4 v) {
  const F4 zero = splat(0.f), one = splat(1.f);
  const F4 upper = v < one ? v : one;
  return v > zero ? upper : zero;
}

// Round to the nearest unorm8, ties to even (as llvmpipe's conversions do), in the low byte
// of each lane.
inline U4 to_unorm8(F4 v) {
#if defined(__SSE2__)
  return reinterpret_cast<U4>(_mm_cvtps_epi32(reinterpret_cast<__m128>(clamp01(v) * 255.f)));
#else
  const F4 s = clamp01(v) * 255.f;
  return U4{static_cast<uint32_t>(std::nearbyint(s[0])), static_cast<uint32_t>(std::nearbyint(s[1])),
            static_cast<uint32_t>(std::nearbyint(s[2])), static_cast<uint32_t>(std::nearbyint(s[3]))};
#endif
}

inline F4 from_unorm8(U4 v) { return __builtin_convertvector(reinterpret_cast<I4>(v & 0xffu), F4) * (1.f / 255.f); }

inline F4 load4(const float* p) {
  F4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

inline void store4(float* p, F4 v) { std::memcpy(p, &v, sizeof v); }

}  // namespace pineda::raster
