#include "state/pixels/color_component_reads.h"

#include <immintrin.h>

#include <algorithm>
#include <cstring>

#include "raster/color_reduction.h"
#include "raster/simd_path.h"
#include "state/pixels/pixel_format.h"

namespace pineda::gl {
namespace {

// The index of luminance among the bytes read_rows looks up: R + G + B clamped to 255, whose
// table entry is the general path's min(R + G + B, 1) stored (the same value of every type for
// all 2^24 colours, checked exhaustively: the sum of the three quotients and the quotient of the
// sum round alike).
constexpr int kLuminance = 5;

// Rows of pixels whose `n` components of kSize bytes are table entries of the channels `channels`.
// A buffer that keeps all its bits (kStored) is read in place: `channels` then index its stored
// bytes, 4 standing for an alpha that reads 255 (and kLuminance for luminance in either).
template <int kSize, bool kStored>
void read_rows(const raster::ColorBuffer& cb, bool opaque, const uint8_t* table, const int* channels, int n, int x0,
               int x1, int y0, int y1, uint8_t* first, size_t row_stride) {
  bool luminance = false;
  for (int c = 0; c < n; ++c) luminance |= channels[c] == kLuminance;
  for (int y = y0; y < y1; ++y) {
    const uint8_t* src = cb.base + cb.stride * y + 4 * static_cast<ptrdiff_t>(x0);
    uint8_t* dst = first + row_stride * static_cast<size_t>(y - y0);
    for (int x = x0; x < x1; ++x, src += 4, dst += n * kSize) {
      uint8_t bytes[6];
      if constexpr (kStored) {
        std::memcpy(bytes, src, 4);
        bytes[4] = 255;
      } else {
        raster::read_rgba8(cb, src, bytes);
        if (opaque) bytes[3] = 255;
      }
      if (luminance) bytes[kLuminance] = static_cast<uint8_t>(std::min(bytes[0] + bytes[1] + bytes[2], 255));
      for (int c = 0; c < n; ++c) std::memcpy(dst + c * kSize, table + kSize * bytes[channels[c]], kSize);
    }
  }
}

// read_stored_float_rows' row with AVX2, eight components at a time: each byte k as double(k) *
// (1 / 255.0) converted to float, which is k / 255 in float for all 256 (the double product's
// error is far below half a float step; tests/driver/osmesa_float_reads_test.cpp checks every
// byte), without the division, whose throughput bounded the baseline loop. Returns the
// components done (a multiple of 8).
#if !defined(__clang__)  // (clang's copies are baseline code: raster/simd_path.h)
__attribute__((target("avx2"))) size_t float_row_avx2(const uint8_t* src, size_t components, bool opaque, uint8_t* dst) {
  const __m256d scale = _mm256_set1_pd(1.0 / 255.0);
  // Alpha (every fourth component) 1 where opaque: lanes 3 and 7 taken from ones.
  const __m256 ones = _mm256_set1_ps(1.f);
  size_t i = 0;
  for (; i + 8 <= components; i += 8) {
    const __m256i bytes = _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(src + i)));
    const __m128 low = _mm256_cvtpd_ps(_mm256_mul_pd(_mm256_cvtepi32_pd(_mm256_castsi256_si128(bytes)), scale));
    const __m128 high = _mm256_cvtpd_ps(_mm256_mul_pd(_mm256_cvtepi32_pd(_mm256_extracti128_si256(bytes, 1)), scale));
    __m256 value = _mm256_insertf128_ps(_mm256_castps128_ps256(low), high, 1);
    if (opaque) value = _mm256_blend_ps(value, ones, 0x88);
    _mm256_storeu_ps(reinterpret_cast<float*>(dst + i * sizeof(float)), value);
  }
  return i;
}
#endif

// Rows whose four float components are the stored bytes in their order, alpha 1 where `opaque`:
// each byte k as k / 255 in float, by a division (correctly rounded, so the table's value: the
// double quotient converted to float, equal for all 256) over whole rows, which vectorizes; with
// AVX2, by float_row_avx2's product.
void read_stored_float_rows(const raster::ColorBuffer& cb, bool opaque, int x0, int x1, int y0, int y1, uint8_t* first,
                            size_t row_stride) {
  constexpr size_t kChunk = 64;  // components: 16 pixels
#if !defined(__clang__)
  static const bool avx2 = raster::kCopiesHaveTheirTargets && raster::uses_avx2(raster::simd_path_from_environment());
#endif
  for (int y = y0; y < y1; ++y) {
    const uint8_t* src = cb.base + cb.stride * y + 4 * static_cast<ptrdiff_t>(x0);
    uint8_t* dst = first + row_stride * static_cast<size_t>(y - y0);
    const size_t components = 4 * static_cast<size_t>(x1 - x0);
    float chunk[kChunk];
    auto convert = [&](size_t done, size_t n) {  // (a constant n for whole chunks: the loop vectorizes)
      for (size_t i = 0; i < n; ++i) chunk[i] = static_cast<float>(src[done + i]) / 255.f;
      if (opaque)
        for (size_t i = 3; i < n; i += 4) chunk[i] = 1.f;
      std::memcpy(dst + done * sizeof(float), chunk, n * sizeof(float));  // (client rows need not be aligned)
    };
    size_t done = 0;
#if !defined(__clang__)
    if (avx2) done = float_row_avx2(src, components, opaque, dst);
#endif
    for (; done + kChunk <= components; done += kChunk) convert(done, kChunk);
    if (done < components) convert(done, components - done);
  }
}

template <int kSize>
void read_rows(const raster::ColorBuffer& cb, bool opaque, const uint8_t* table, int* channels, int n, int x0, int x1,
               int y0, int y1, uint8_t* first, size_t row_stride) {
  if (cb.reduction.active) return read_rows<kSize, false>(cb, opaque, table, channels, n, x0, x1, y0, y1, first, row_stride);
  const bool bgra = cb.format == raster::ColorFormat::BGRA8;
  for (int c = 0; c < n; ++c) {  // read_rgba8's order and opaque alpha, as byte indices (a sum in either order)
    if (bgra && (channels[c] == 0 || channels[c] == 2)) channels[c] = 2 - channels[c];
    if (opaque && channels[c] == 3) channels[c] = 4;
  }
  read_rows<kSize, true>(cb, opaque, table, channels, n, x0, x1, y0, y1, first, row_stride);
}

}  // namespace

bool reads_color_components(const raster::ColorBuffer& cb, GLenum format, GLenum type, bool swap_bytes) {
  const int n = color_format_components(format);
  const int size = pixel_type_size(type);
  return cb.base && !swap_bytes && n != 0 && size != 0;
}

void read_color_components(const raster::ColorBuffer& cb, bool opaque, GLenum format, GLenum type, int x0, int x1,
                           int y0, int y1, uint8_t* first, size_t row_stride) {
  const int n = color_format_components(format), size = pixel_type_size(type);
  int channels[4] = {0, 0, 0, 0};
  for (int c = 0; c < n; ++c) channels[c] = channel_of(format, c) < 0 ? kLuminance : channel_of(format, c);
  const bool stored_order = n == 4 && channels[0] == 0 && channels[1] == 1 && channels[2] == 2 && channels[3] == 3 &&
                            cb.format == raster::ColorFormat::RGBA8 && !cb.reduction.active;
  if (type == GL_FLOAT && stored_order) return read_stored_float_rows(cb, opaque, x0, x1, y0, y1, first, row_stride);
  uint8_t table[256 * 4];
  for (int k = 0; k < 256; ++k) {
    const double v[4] = {k / 255.0, 0, 0, 0};
    store_color(v, GL_RED, type, table + size * k);
  }
  if (size == 1) return read_rows<1>(cb, opaque, table, channels, n, x0, x1, y0, y1, first, row_stride);
  if (size == 2) return read_rows<2>(cb, opaque, table, channels, n, x0, x1, y0, y1, first, row_stride);
  read_rows<4>(cb, opaque, table, channels, n, x0, x1, y0, y1, first, row_stride);
}

}  // namespace pineda::gl
