// The write-stage reduction of a pixel to a render target's format (framebuffer.h).
#pragma once
#include <array>
#include <cstdint>

#include "raster/framebuffer.h"

namespace pineda::raster {

// kRequantize[bits][v]: the 8-bit value v rounded to `bits` bits and widened back to 8 (the
// same rounding as texture storage: state/textures/texture_format.cpp).
inline constexpr auto kRequantize = [] {
  std::array<std::array<uint8_t, 256>, 9> table{};
  for (uint32_t bits = 0; bits <= 8; ++bits)
    for (uint32_t v = 0; v < 256; ++v) {
      if (bits == 0 || bits == 8) {
        table[bits][v] = static_cast<uint8_t>(v);
        continue;
      }
      const uint32_t max = (1u << bits) - 1;
      const uint32_t q = (v * max + 127) / 255;
      table[bits][v] = static_cast<uint8_t>((q * 255 + max / 2) / max);
    }
  return table;
}();

// An RGBA8 pixel (R in the lowest byte) as the target's format stores it.
inline uint32_t reduce_pixel(const ColorReduction& r, uint32_t pixel) {
  uint32_t out = 0;
  for (int c = 0; c < 4; ++c) {
    const uint8_t bits = r.bits[c];
    uint32_t v = (pixel >> (8 * r.source[c])) & 0xffu;
    v = bits == 0 ? (c == 3 ? 255u : 0u) : kRequantize[bits][v];
    out |= v << (8 * c);
  }
  return out;
}

// The same for four bytes in R, G, B, A order.
inline void reduce_bytes(const ColorReduction& r, uint8_t rgba[4]) {
  uint32_t v = uint32_t{rgba[0]} | uint32_t{rgba[1]} << 8 | uint32_t{rgba[2]} << 16 | uint32_t{rgba[3]} << 24;
  v = reduce_pixel(r, v);
  for (int c = 0; c < 4; ++c) rgba[c] = static_cast<uint8_t>(v >> (8 * c));
}

// The RGBA bytes a stored pixel reads as (glReadPixels, copies, blits): a luminance or
// intensity target reads as red, (L, 0, 0, A) or (I, 0, 0, 1), as Mesa rebases them.
inline void read_rgba8(const ColorBuffer& cb, const uint8_t* p, uint8_t out[4]) {
  const bool bgra = cb.format == ColorFormat::BGRA8;
  out[0] = p[bgra ? 2 : 0];
  out[1] = p[1];
  out[2] = p[bgra ? 0 : 2];
  out[3] = p[3];
  const ColorReduction& r = cb.reduction;
  if (r.active && r.source[1] == 0) {
    out[1] = out[2] = 0;
    if (r.source[3] == 0) out[3] = 255;
  }
}

}  // namespace pineda::raster
