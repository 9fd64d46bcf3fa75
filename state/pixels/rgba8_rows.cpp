#include "state/pixels/rgba8_rows.h"

#include <GL/glext.h>

#include <cstring>

namespace pineda {
namespace {

template <bool kReversed, bool kBlueFirst>
void four_byte_row(const uint8_t* src, int count, uint32_t* out) {
  for (int i = 0; i < count; ++i) {
    uint32_t p;
    std::memcpy(&p, src + 4 * static_cast<size_t>(i), 4);
    if constexpr (kReversed) p = __builtin_bswap32(p);
    if constexpr (kBlueFirst) p = swap_red_blue(p);
    out[i] = p;
  }
}

// One or two bytes a pixel (Rgba8Source's spread and defaults).
void small_pixel_row(const Rgba8Source& source, const uint8_t* src, int count, uint32_t* out) {
  const uint32_t spread = source.spread, defaults = source.defaults;
  if (source.bytes == 1) {
    for (int i = 0; i < count; ++i) out[i] = defaults | src[i] * spread;
  } else {
    for (int i = 0; i < count; ++i) out[i] = defaults | src[2 * i] * spread | uint32_t{src[2 * i + 1]} << 24;
  }
}

template <bool kBlueFirst>
void three_byte_row(const uint8_t* src, int count, uint32_t* out) {
  auto finish = [](uint32_t p) { return (kBlueFirst ? swap_red_blue(p) : p) | 0xff000000u; };
  int i = 0;
  for (; i + 4 <= count; i += 4) {  // four pixels from three words
    uint32_t w[3];
    std::memcpy(w, src + 3 * static_cast<size_t>(i), sizeof w);
    out[i] = finish(w[0] & 0xffffffu);
    out[i + 1] = finish((w[0] >> 24) | ((w[1] & 0xffffu) << 8));
    out[i + 2] = finish((w[1] >> 16) | ((w[2] & 0xffu) << 16));
    out[i + 3] = finish(w[2] >> 8);
  }
  for (; i < count; ++i) {
    const uint8_t* p = src + 3 * static_cast<size_t>(i);
    out[i] = finish(p[0] | (uint32_t{p[1]} << 8) | (uint32_t{p[2]} << 16));
  }
}

}  // namespace

Rgba8Source rgba8_source(GLenum format, GLenum type, bool swap_bytes) {
  Rgba8Source s;
  s.blue_first = format == GL_BGRA || format == GL_BGR;
  if (type == GL_UNSIGNED_BYTE) {  // (SWAP_BYTES leaves single bytes alone)
    s.bytes = format == GL_RGBA || format == GL_BGRA ? 4 : format == GL_RGB || format == GL_BGR ? 3 : 0;
    // (Missing colour components read 0, a missing alpha 1.)
    auto small = [&](int bytes, uint32_t spread, uint32_t defaults) {
      s.bytes = bytes;
      s.spread = spread;
      s.defaults = defaults;
    };
    switch (format) {
      case GL_RED: small(1, 0x1u, 0xff000000u); break;
      case GL_GREEN: small(1, 0x100u, 0xff000000u); break;
      case GL_BLUE: small(1, 0x10000u, 0xff000000u); break;
      case GL_ALPHA: small(1, 0x1000000u, 0u); break;
      case GL_LUMINANCE: small(1, 0x010101u, 0xff000000u); break;
      case GL_LUMINANCE_ALPHA: small(2, 0x010101u, 0u); break;
      default: break;
    }
  } else if ((type == GL_UNSIGNED_INT_8_8_8_8 || type == GL_UNSIGNED_INT_8_8_8_8_REV) &&
             (format == GL_RGBA || format == GL_BGRA)) {
    // _REV: the first component in the lowest byte, as the bytes lie in memory; SWAP_BYTES
    // reverses the word first.
    s.bytes = 4;
    s.reversed = (type == GL_UNSIGNED_INT_8_8_8_8) != swap_bytes;
  }
  return s;
}

void rgba8_row_texels(const Rgba8Source& source, const uint8_t* src, int count, uint32_t* out) {
  if (source.bytes < 3) {
    small_pixel_row(source, src, count, out);
  } else if (source.bytes == 3) {
    if (source.blue_first) three_byte_row<true>(src, count, out);
    else three_byte_row<false>(src, count, out);
  } else if (source.reversed) {
    if (source.blue_first) four_byte_row<true, true>(src, count, out);
    else four_byte_row<true, false>(src, count, out);
  } else {
    if (source.blue_first) four_byte_row<false, true>(src, count, out);
    else four_byte_row<false, false>(src, count, out);
  }
}

}  // namespace pineda
