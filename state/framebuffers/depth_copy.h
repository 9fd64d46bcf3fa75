#pragma once
// A depth texture rendered into: its float texels as the integers the depth test compares
// (Attachment::depth_copy), and the integers back as texels.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <immintrin.h>

#include "raster/simd_path.h"

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

namespace depth_copy_detail {

// d * scale rounded to float, for d below 2^31: a conversion to double, one product, one
// rounding, the same in both copies (so the same floats), two at a time in the baseline and eight
// in the AVX-512 one (glmark2's shadow turns its 800x600 depth map back into texels every frame;
// written as a loop, -O2 left it one at a time).
inline void scaled_floats_one_at_a_time(const uint32_t* in, uint32_t* texels, size_t n, double scale) {
  for (size_t i = 0; i < n; ++i) texels[i] = std::bit_cast<uint32_t>(static_cast<float>(double(int32_t(in[i])) * scale));
}
inline void scaled_floats(const uint32_t* in, uint32_t* texels, size_t n, double scale) {
  const __m128d factor = _mm_set1_pd(scale);
  size_t i = 0;
  for (; i + 2 <= n; i += 2) {
    const __m128i d = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(in + i));
    const __m128 product = _mm_cvtpd_ps(_mm_mul_pd(_mm_cvtepi32_pd(d), factor));
    _mm_storel_epi64(reinterpret_cast<__m128i*>(texels + i), _mm_castps_si128(product));
  }
  scaled_floats_one_at_a_time(in + i, texels + i, n - i, scale);
}
[[gnu::target("avx512f,avx512dq,avx512vl")]] inline void scaled_floats_avx512(const uint32_t* in, uint32_t* texels,
                                                                             size_t n, double scale) {
  const __m512d factor = _mm512_set1_pd(scale);
  size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    const __m256i d = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(in + i));
    // (The zero-masked forms with every lane on: GCC 12 warns about the unmasked ones' sources.)
    const __m512d product = _mm512_maskz_mul_pd(0xFF, _mm512_maskz_cvtepi32_pd(0xFF, d), factor);
    _mm256_storeu_ps(reinterpret_cast<float*>(texels + i), _mm512_maskz_cvtpd_ps(0xFF, product));
  }
  scaled_floats_one_at_a_time(in + i, texels + i, n - i, scale);
}

}  // namespace depth_copy_detail

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
  static const bool avx512 = raster::uses_avx512(raster::simd_path_from_environment());
  (avx512 ? depth_copy_detail::scaled_floats_avx512 : depth_copy_detail::scaled_floats)(in, texels, n, 1.0 / max);
}

}  // namespace pineda
