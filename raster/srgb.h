// sRGB textures (EXT_texture_sRGB, GL 2.1 3.8.15): the R, G and B of an sRGB texel are
// decoded to linear per texel, before filtering; alpha is linear already.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>

#include "raster/quad_vector.h"
#include "raster/texture.h"

namespace pineda::raster {

// The spec's decoding of an 8-bit sRGB value c / 255: c / 12.92 up to 0.04045, else
// ((c + 0.055) / 1.055)^2.4.
inline const std::array<float, 256>& srgb_decode_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const double c = i / 255.0;
      t[i] = float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
    }
    return t;
  }();
  return table;
}

// An RGBA8 texel of `level` (R in the lowest byte) as RGBA in [0, 1], linear.
inline F4 texel_to_rgba(const TextureLevel& level, uint32_t texel) {
  if (!level.srgb) return from_unorm8(U4{texel, texel >> 8, texel >> 16, texel >> 24});
  const std::array<float, 256>& decode = srgb_decode_table();
  return F4{decode[texel & 0xffu], decode[(texel >> 8) & 0xffu], decode[(texel >> 16) & 0xffu],
            float(texel >> 24) * (1.f / 255.f)};
}

}  // namespace pineda::raster
