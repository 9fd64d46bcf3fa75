// The common blends done on unorm8 integers, each equal to the float path (s, a, d as
// x * (1/255.f), the factors' products summed, clamped, rounded to nearest) for every
// (s, a, d) in [0, 255]^3 (tests/raster/blend8_test.cpp checks every one):
// - Over, SRC_ALPHA / ONE_MINUS_SRC_ALPHA: round((s * a + d * (255 - a)) / 255); the exact
//   quotient is never within float error of a rounding tie.
// - AddScaled, SRC_ALPHA / ONE: min(255, d + round(s * a / 255)) (s * a / 255 is never a tie).
// - Add, ONE / ONE: min(255, s + d).
// - OverKeepAlpha: Over for colour, ZERO / ONE for alpha (the destination's alpha kept, as
//   compositors draw).
// Each with ADD on every channel and, but for OverKeepAlpha, the same factors for colour and alpha.
#pragma once
#include <cstdint>

#include "raster/draw_state.h"
#include "raster/quad_vector.h"

namespace pineda::raster {

// Other: blending in float, or none (in a fill routine's key: none).
enum class Blend8 : uint8_t { Other, Over, AddScaled, Add, OverKeepAlpha };

// The integer blend that does the draw's blending, or Other when the float path must.
inline Blend8 blend8_of(const BlendState& b) {
  if (b.eq_rgb != BlendEquation::Add || b.eq_alpha != BlendEquation::Add) return Blend8::Other;
  if (b.src_rgb == BlendFactor::SrcAlpha && b.dst_rgb == BlendFactor::OneMinusSrcAlpha &&
      b.src_alpha == BlendFactor::Zero && b.dst_alpha == BlendFactor::One)
    return Blend8::OverKeepAlpha;
  if (b.src_rgb != b.src_alpha || b.dst_rgb != b.dst_alpha) return Blend8::Other;
  if (b.src_rgb == BlendFactor::SrcAlpha && b.dst_rgb == BlendFactor::OneMinusSrcAlpha) return Blend8::Over;
  if (b.src_rgb == BlendFactor::SrcAlpha && b.dst_rgb == BlendFactor::One) return Blend8::AddScaled;
  if (b.src_rgb == BlendFactor::One && b.dst_rgb == BlendFactor::One) return Blend8::Add;
  return Blend8::Other;
}

// Over on four packed pixels; the alpha byte is the top one in both RGBA8 and BGRA8.
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

// The lane templates are always inlined: no call passes their vectors, whatever their width.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

// Over on packed pixels (V: a vector of uint32_t lanes, any width): two channels per lane, one
// in each 16-bit half, with blend_over8's integer formula (at most 255 * 255 + 127 = 65152: no
// half overflows). 16-bit multiplies: a 32-bit one is two operations on some cores.
template <typename V>
[[gnu::always_inline]] inline V blend_over_halves(V src, V dst) {
  typedef uint16_t Halves __attribute__((vector_size(sizeof(V))));
  const V a = src >> 24;
  const Halves alpha = reinterpret_cast<Halves>(a | (a << 16));
  const Halves inverse = reinterpret_cast<Halves>(V{} + 0x00ff00ffu) - alpha;
  auto two_channels = [&](V s, V d) __attribute__((always_inline)) {
    Halves v = reinterpret_cast<Halves>(s) * alpha + reinterpret_cast<Halves>(d) * inverse + 127;
    v = (v + (v >> 8) + 1) >> 8;
    return reinterpret_cast<V>(v);
  };
  return two_channels(src & 0x00ff00ffu, dst & 0x00ff00ffu) | (two_channels((src >> 8) & 0x00ff00ffu, (dst >> 8) & 0x00ff00ffu) << 8);
}

// Saturating byte-wise sum of packed pixels (V: a vector of uint32_t lanes, any width).
template <typename V>
[[gnu::always_inline]] inline V blend_add8(V src, V dst) {
  typedef uint8_t Bytes __attribute__((vector_size(sizeof(V))));
  const Bytes s = reinterpret_cast<Bytes>(src), sum = s + reinterpret_cast<Bytes>(dst);
  return reinterpret_cast<V>(sum | reinterpret_cast<Bytes>(sum < s));  // a wrapped byte becomes 255
}

// AddScaled: each channel of src times its pixel's alpha (rounded to unorm8), added to dst
// saturating. The alpha byte is the top one in both RGBA8 and BGRA8.
template <typename V>
[[gnu::always_inline]] inline V blend_add_scaled8(V src, V dst) {
  typedef uint16_t Halves __attribute__((vector_size(sizeof(V))));
  const V a = src >> 24;
  const Halves alpha = reinterpret_cast<Halves>(a | (a << 16));
  auto two_channels = [&](V s) {  // one channel in each 16-bit half; s * a + 127 <= 65152
    Halves v = reinterpret_cast<Halves>(s) * alpha + 127;
    v = (v + (v >> 8) + 1) >> 8;
    return reinterpret_cast<V>(v);
  };
  const V scaled = two_channels(src & 0x00ff00ffu) | (two_channels((src >> 8) & 0x00ff00ffu) << 8);
  return blend_add8(scaled, dst);
}
// OverKeepAlpha: Over with the destination's alpha byte (the top one in both byte orders).
template <typename V>
[[gnu::always_inline]] inline V keep_alpha8(V blended, V dst) {
  return (blended & 0x00ffffffu) | (dst & 0xff000000u);
}
#pragma GCC diagnostic pop

}  // namespace pineda::raster
