// Four-lane vectors, one lane per pixel of a 2x2 quad (GCC/Clang vector extensions; SSE2 on
// x86-64). Lane i is pixel (x + (i & 1), y + (i >> 1)).
#pragma once
#include <cstdint>
#include <cstring>

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

// Round to nearest unorm8 (v * 255 + 0.5, truncated) in the low byte of each lane.
// (Converted as signed: one instruction, and the values fit.)
inline U4 to_unorm8(F4 v) { return reinterpret_cast<U4>(__builtin_convertvector(clamp01(v) * 255.f + 0.5f, I4)); }

inline F4 from_unorm8(U4 v) { return __builtin_convertvector(reinterpret_cast<I4>(v & 0xffu), F4) * (1.f / 255.f); }

inline F4 load4(const float* p) {
  F4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

inline void store4(float* p, F4 v) { std::memcpy(p, &v, sizeof v); }

}  // namespace pineda::raster
