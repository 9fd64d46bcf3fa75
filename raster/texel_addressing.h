// Texel addressing shared by the samplers: coordinate sanitizing and the wrap modes'
// texel indices along one axis (GL 1.5 3.8.7-3.8.8).
#pragma once
#include <algorithm>

#include "raster/quad_vector.h"
#include "raster/texture.h"

namespace pineda::raster {

// Keeps coordinates where float-to-int conversions are defined; NaN becomes 0.
inline float sane(float v) { return v > -1e6f ? (v < 1e6f ? v : 1e6f) : (v <= -1e6f ? -1e6f : 0.f); }
// sane() for four lanes: the same operations in each lane.
inline F4 sane4(F4 v) {
  const F4 hi = splat(1e6f), lo = splat(-1e6f);
  return v > lo ? (v < hi ? v : hi) : (v <= lo ? lo : F4{});
}

// floor() for |v| < 2^31 without a libm call (the x86-64 baseline has no round instruction).
inline float floor_fast(float v) {
  const float t = static_cast<float>(static_cast<int>(v));
  return t > v ? t - 1.f : t;
}

inline int floor_int(float v) {
  const int i = static_cast<int>(v);
  return static_cast<float>(i) > v ? i - 1 : i;
}

inline float mirror(float s) {
  const float f = floor_fast(s);
  const float frac = s - f;
  return (static_cast<int>(f) & 1) ? 1.f - frac : frac;
}

// Texel index along one axis for nearest filtering; -1 means the border colour.
// kTexels: s is in texels already (a rectangle texture), used as it is, so that s = i + 0.5
// lands on texel i exactly; only the clamping wrap modes apply (the others clamp to the edge).
template <bool kTexels = false>
inline int nearest_index(TexWrap wrap, float s, int size) {
  if constexpr (kTexels) {
    const float n = static_cast<float>(size);
    if (wrap != TexWrap::ClampToBorder) return std::clamp(floor_int(std::clamp(s, 0.f, n)), 0, size - 1);
    const int i = floor_int(std::clamp(s, -1.f, n + 1.f));
    return i < 0 || i >= size ? -1 : i;
  }
  switch (wrap) {
    case TexWrap::Repeat: {
      const int i = floor_int((s - floor_fast(s)) * size);
      return std::min(i, size - 1);
    }
    case TexWrap::MirroredRepeat:
      return std::clamp(floor_int(mirror(s) * size), 0, size - 1);
    case TexWrap::ClampToBorder: {
      const int i = floor_int(std::clamp(s, -1.f, 2.f) * size);
      return i < 0 || i >= size ? -1 : i;
    }
    case TexWrap::Clamp:
    case TexWrap::ClampToEdge:
      break;
  }
  return std::clamp(floor_int(std::clamp(s, 0.f, 1.f) * size), 0, size - 1);
}

// The two texel indices and the weight of the second one for linear filtering; -1 means
// the border colour. kTexels: as nearest_index's.
template <bool kTexels = false>
inline void linear_indices(TexWrap wrap, float s, int size, int& i0, int& i1, float& frac) {
  float u = 0.f;
  if constexpr (kTexels) {
    const float n = static_cast<float>(size);
    if (wrap == TexWrap::Clamp) u = std::clamp(s, 0.f, n) - 0.5f;
    else if (wrap == TexWrap::ClampToBorder) u = std::clamp(s, -1.f, n + 1.f) - 0.5f;
    else {
      wrap = TexWrap::ClampToEdge;
      u = std::clamp(s, 0.5f, n - 0.5f) - 0.5f;
    }
  } else {
    switch (wrap) {
      case TexWrap::Repeat: u = (s - floor_fast(s)) * size - 0.5f; break;
      case TexWrap::MirroredRepeat: u = mirror(s) * size - 0.5f; break;
      case TexWrap::Clamp: u = std::clamp(s, 0.f, 1.f) * size - 0.5f; break;
      case TexWrap::ClampToEdge: u = std::clamp(s * size, 0.5f, size - 0.5f) - 0.5f; break;
      case TexWrap::ClampToBorder: u = std::clamp(s, -1.f, 2.f) * size - 0.5f; break;
    }
  }
  const float f = floor_fast(u);
  frac = u - f;
  i0 = static_cast<int>(f);
  i1 = i0 + 1;
  switch (wrap) {
    case TexWrap::Repeat:
      // s - floor(s) lies in [0, 1] (1 when rounding a tiny negative s), so i0 >= -1 and
      // i1 <= size: one step wraps them.
      i0 = i0 < 0 ? i0 + size : i0;
      i1 = i1 >= size ? i1 - size : i1;
      break;
    case TexWrap::MirroredRepeat:
    case TexWrap::ClampToEdge:
      i0 = std::clamp(i0, 0, size - 1);
      i1 = std::clamp(i1, 0, size - 1);
      break;
    case TexWrap::Clamp:
    case TexWrap::ClampToBorder:  // out of range: the border colour
      if (i0 < 0 || i0 >= size) i0 = -1;
      if (i1 < 0 || i1 >= size) i1 = -1;
      break;
  }
}

}  // namespace pineda::raster
