// The most common blend, SRC_ALPHA / ONE_MINUS_SRC_ALPHA with ADD on every channel, in unorm8
// integers: round((s * a + d * (255 - a)) / 255). For every (s, a, d) in [0, 255]^3 this equals
// the float path (s, a, d as x * (1/255.f), s * a + d * (1 - a), rounded to nearest), checked
// exhaustively: the exact quotient is never within float error of a rounding tie.
#pragma once
#include <cstdint>

#include "raster/draw_state.h"
#include "raster/quad_vector.h"

namespace pineda::raster {

inline bool is_blend_over(const BlendState& b) {
  return b.eq_rgb == BlendEquation::Add && b.eq_alpha == BlendEquation::Add && b.src_rgb == BlendFactor::SrcAlpha &&
         b.src_alpha == BlendFactor::SrcAlpha && b.dst_rgb == BlendFactor::OneMinusSrcAlpha &&
         b.dst_alpha == BlendFactor::OneMinusSrcAlpha;
}

// Four packed pixels; the alpha byte is the top one in both RGBA8 and BGRA8.
inline U4 blend_over8(U4 src, U4 dst) {
  const U4 a1 = src >> 24;
  const U4 a2 = a1 | (a1 << 16);
  const U4 alpha = a2 | (a2 << 8);  // each pixel's source alpha in all four bytes
#if defined(__SSE2__)
  const __m128i s = reinterpret_cast<__m128i>(src), d = reinterpret_cast<__m128i>(dst);
  const __m128i a = reinterpret_cast<__m128i>(alpha), zero = _mm_setzero_si128();
  const __m128i k255 = _mm_set1_epi16(255), k127 = _mm_set1_epi16(127), k1 = _mm_set1_epi16(1);
  auto half = [&](__m128i s16, __m128i d16, __m128i a16) {
    // At most 255 * 255 + 127 = 65152: no 16-bit lane overflows.
    const __m128i v = _mm_add_epi16(
        _mm_add_epi16(_mm_mullo_epi16(s16, a16), _mm_mullo_epi16(d16, _mm_sub_epi16(k255, a16))), k127);
    return _mm_srli_epi16(_mm_add_epi16(_mm_add_epi16(v, _mm_srli_epi16(v, 8)), k1), 8);
  };
  const __m128i lo = half(_mm_unpacklo_epi8(s, zero), _mm_unpacklo_epi8(d, zero), _mm_unpacklo_epi8(a, zero));
  const __m128i hi = half(_mm_unpackhi_epi8(s, zero), _mm_unpackhi_epi8(d, zero), _mm_unpackhi_epi8(a, zero));
  return reinterpret_cast<U4>(_mm_packus_epi16(lo, hi));
#else
  U4 out = {0, 0, 0, 0};
  for (int c = 0; c < 4; ++c) {
    const U4 s = (src >> (8 * c)) & 0xffu, d = (dst >> (8 * c)) & 0xffu, a = alpha & 0xffu;
    const U4 v = s * a + d * (255u - a) + 127u;
    out |= ((v + (v >> 8) + 1u) >> 8) << (8 * c);
  }
  return out;
#endif
}

}  // namespace pineda::raster
