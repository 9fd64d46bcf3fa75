// EXT_texture_swizzle / ARB_texture_swizzle: each channel of a sampled texel taken from one of
// its channels, zero or one, after the base format's conversion to RGBA and before the texture
// environment or the shader sees it.
#pragma once
#include <array>
#include <cstdint>

namespace pineda::raster {

// Per output channel R, G, B, A: the source channel 0-3, or kSwizzleZero / kSwizzleOne.
using TexSwizzle = std::array<uint8_t, 4>;
constexpr uint8_t kSwizzleZero = 4, kSwizzleOne = 5;
constexpr TexSwizzle kIdentitySwizzle{0, 1, 2, 3};

inline void swizzle_rgba(const TexSwizzle& swizzle, float rgba[4]) {
  const float in[6] = {rgba[0], rgba[1], rgba[2], rgba[3], 0.f, 1.f};
  for (int c = 0; c < 4; ++c) rgba[c] = in[swizzle[c]];
}

// An RGBA8 texel (R in the lowest byte).
inline uint32_t swizzle_texel(const TexSwizzle& swizzle, uint32_t texel) {
  const uint32_t in[6] = {texel & 0xffu, (texel >> 8) & 0xffu, (texel >> 16) & 0xffu, texel >> 24, 0u, 0xffu};
  return in[swizzle[0]] | in[swizzle[1]] << 8 | in[swizzle[2]] << 16 | in[swizzle[3]] << 24;
}

}  // namespace pineda::raster
