#pragma once
// A depth texture rendered into: its float texels as the integers the depth test compares
// (Attachment::depth_copy), and the integers back as texels.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace pineda {

// The largest depth value of `bits` bits (1.0).
inline double depth_max(int bits) { return std::ldexp(1.0, bits) - 1.0; }

// Texels (floats; clamped to [0, 1], NaN as 0) as integers of `bits` bits (at most 32), rounded
// to the nearest, ties to even.
inline void depth_integers_from_floats(const uint32_t* texels, uint32_t* out, size_t n, int bits) {
  const double max = depth_max(bits);
  for (size_t i = 0; i < n; ++i) {
    const float f = std::bit_cast<float>(texels[i]);
    const double z = f > 0.f ? std::min(double(f), 1.0) : 0.0;
    // Adding 2^52 rounds z * max (below 2^32) to the nearest integer, ties to even, as
    // nearbyint, into the low bits of the sum: no library call, and the loop vectorizes.
    out[i] = static_cast<uint32_t>(std::bit_cast<uint64_t>(z * max + 0x1p52));
  }
}

// Integers of `bits` bits as texels: each d / max rounded to float.
inline void depth_floats_from_integers(const uint32_t* in, uint32_t* texels, size_t n, int bits) {
  const double max = depth_max(bits);
  if (bits > 24) {
    for (size_t i = 0; i < n; ++i) texels[i] = std::bit_cast<uint32_t>(static_cast<float>(in[i] / max));
    return;
  }
  // With bits <= 24, d * (1 / max) rounds to the same float: the quotient's binary expansion
  // repeats with period `bits`, so it never lies within the product's error of a float rounding
  // boundary (that takes a run of more than 24 equal bits). Multiplying vectorizes; dividing did not.
  const double scale = 1.0 / max;
  for (size_t i = 0; i < n; ++i) texels[i] = std::bit_cast<uint32_t>(static_cast<float>(double(int32_t(in[i])) * scale));
}

}  // namespace pineda
