#include "state/pixels/color_byte_reads.h"

#include <GL/glext.h>

#include <immintrin.h>

#include <cstring>

#include "raster/simd_path.h"
#include "state/pixels/rgba8_rows.h"

namespace pineda::gl {
namespace {

// One row of n pixels: kSwap exchanges red and blue, kBytes (4 or 3) of each pixel stored.
template <bool kSwap, int kBytes>
void copy_row(const uint8_t* src, uint8_t* dst, int n, uint32_t alpha) {
  auto pixel = [&](int i) {
    uint32_t p;
    std::memcpy(&p, src + 4 * static_cast<size_t>(i), 4);
    if constexpr (kSwap) p = swap_red_blue(p);
    return p | alpha;
  };
  int i = 0;
  if constexpr (kBytes == 3) {  // four pixels' twelve bytes as three words
    for (; i + 4 <= n; i += 4) {
      const uint32_t p0 = pixel(i), p1 = pixel(i + 1), p2 = pixel(i + 2), p3 = pixel(i + 3);
      const uint32_t words[3] = {(p0 & 0xffffffu) | (p1 << 24), ((p1 >> 8) & 0xffffu) | (p2 << 16),
                                 ((p2 >> 16) & 0xffu) | (p3 << 8)};
      std::memcpy(dst + 3 * static_cast<size_t>(i), words, sizeof words);
    }
  }
  for (; i < n; ++i) {
    const uint32_t p = pixel(i);
    uint8_t* out = dst + kBytes * static_cast<size_t>(i);
    if constexpr (kBytes == 4) {
      std::memcpy(out, &p, 4);
    } else {
      out[0] = static_cast<uint8_t>(p);
      out[1] = static_cast<uint8_t>(p >> 8);
      out[2] = static_cast<uint8_t>(p >> 16);
    }
  }
}

// copy_row eight pixels at a time with AVX2 (the same bytes): each 16-byte half's four pixels
// shuffled to their order (and to their twelve bytes for RGB, the halves' twelve then joined by a
// permute of words).
#if !defined(__clang__)  // (clang's copies are baseline code: raster/simd_path.h)
__attribute__((target("avx2"))) void copy_row_avx2(const uint8_t* src, uint8_t* dst, int n, bool swap, bool three,
                                                   uint32_t alpha) {
  const __m128i half = three ? (swap ? _mm_setr_epi8(2, 1, 0, 6, 5, 4, 10, 9, 8, 14, 13, 12, -1, -1, -1, -1)
                                     : _mm_setr_epi8(0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1))
                             : (swap ? _mm_setr_epi8(2, 1, 0, 3, 6, 5, 4, 7, 10, 9, 8, 11, 14, 13, 12, 15)
                                     : _mm_setr_epi8(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15));
  const __m256i bytes = _mm256_broadcastsi128_si256(half);
  const __m256i words = _mm256_setr_epi32(0, 1, 2, 4, 5, 6, 3, 7);
  const __m256i alpha_bits = _mm256_set1_epi32(static_cast<int>(alpha));
  const int pixel_bytes = three ? 3 : 4;
  int i = 0;
  for (; i + 8 <= n; i += 8) {
    const __m256i v = _mm256_shuffle_epi8(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(src + 4 * static_cast<size_t>(i))), bytes);
    uint8_t* out = dst + static_cast<size_t>(pixel_bytes) * static_cast<size_t>(i);
    if (three) {
      const __m256i packed = _mm256_permutevar8x32_epi32(v, words);
      _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm256_castsi256_si128(packed));
      _mm_storel_epi64(reinterpret_cast<__m128i*>(out + 16), _mm256_extracti128_si256(packed, 1));
    } else {
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(out), _mm256_or_si256(v, alpha_bits));
    }
  }
  const auto rest = three ? (swap ? &copy_row<true, 3> : &copy_row<false, 3>) : (swap ? &copy_row<true, 4> : &copy_row<false, 4>);
  rest(src + 4 * static_cast<size_t>(i), dst + static_cast<size_t>(pixel_bytes) * static_cast<size_t>(i), n - i, alpha);
}
#endif

}  // namespace

bool packs_rgba8_bytes(GLenum format, GLenum type) {
  if (type == GL_UNSIGNED_INT_8_8_8_8 || type == GL_UNSIGNED_INT_8_8_8_8_REV) return format == GL_RGBA || format == GL_BGRA;
  return type == GL_UNSIGNED_BYTE && (format == GL_RGBA || format == GL_BGRA || format == GL_RGB || format == GL_BGR);
}

bool reverses_rgba8_words(GLenum type, bool swap_bytes) {
  if (type == GL_UNSIGNED_INT_8_8_8_8) return !swap_bytes;
  return type == GL_UNSIGNED_INT_8_8_8_8_REV && swap_bytes;
}

void pack_rgba8_row(const uint8_t* src, bool stored_bgra, GLenum format, uint32_t alpha, uint8_t* dst, int n,
                    bool reversed) {
  const bool wants_bgr = format == GL_BGRA || format == GL_BGR;
  const bool swap = stored_bgra != wants_bgr;
  const bool three = format == GL_RGB || format == GL_BGR;
  static const bool avx2 = raster::kCopiesHaveTheirTargets && raster::uses_avx2(raster::simd_path_from_environment());
  if (!swap && !three && alpha == 0) {
    std::memcpy(dst, src, 4 * static_cast<size_t>(n));
  } else if (avx2) {
#if !defined(__clang__)
    copy_row_avx2(src, dst, n, swap, three, alpha);
#endif
  } else {
    auto copy = swap ? (three ? &copy_row<true, 3> : &copy_row<true, 4>) : (three ? &copy_row<false, 3> : &copy_row<false, 4>);
    copy(src, dst, n, alpha);
  }
  if (reversed)
    for (size_t i = 0; i < static_cast<size_t>(n); ++i) {
      uint32_t p;
      std::memcpy(&p, dst + 4 * i, 4);
      p = __builtin_bswap32(p);
      std::memcpy(dst + 4 * i, &p, 4);
    }
}

bool reads_color_bytes(const raster::ColorBuffer& cb, GLenum format, GLenum type) {
  // A reduced buffer (raster/color_reduction.h) reads some components as constants.
  return cb.base && !cb.reduction.active && packs_rgba8_bytes(format, type);
}

void read_color_bytes(const raster::ColorBuffer& cb, bool opaque, GLenum format, int x0, int x1, int y0, int y1,
                      uint8_t* first, size_t row_stride, bool reversed) {
  if (x0 >= x1) return;
  const bool stored_bgra = cb.format == raster::ColorFormat::BGRA8;
  const uint32_t alpha = opaque ? 0xff000000u : 0u;
  for (int y = y0; y < y1; ++y)
    pack_rgba8_row(cb.base + cb.stride * y + 4 * static_cast<ptrdiff_t>(x0), stored_bgra, format, alpha,
                   first + row_stride * static_cast<size_t>(y - y0), x1 - x0, reversed);
}

}  // namespace pineda::gl
