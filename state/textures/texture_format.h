// Texture internal formats (GL 1.5 spec tables 3.15 and 3.16): which components a format
// keeps and how many bits each is stored with.
//
// Texels are stored as RGBA8. A format with fewer bits than 8 per component is quantized to
// the bits Mesa allocates for it (RGBA4 to 4, RGB5_A1 to 5/5/5/1, R3_G3_B2 to 3/3/2, ...),
// so that sampling and glGetTexImage see the values Mesa would; a format asking for more
// (RGB10, RGBA12, LUMINANCE16, ...) is kept at 8 bits, and its sizes say so.
#pragma once
#include <GL/gl.h>

#include <cstdint>
#include <optional>

#include "raster/texture.h"

namespace pineda {

struct TextureFormat {
  raster::TexBaseFormat base = raster::TexBaseFormat::RGBA;
  // Bits stored per component, as glGetTexLevelParameter's TEXTURE_*_SIZE report them.
  uint8_t red = 0, green = 0, blue = 0, alpha = 0, luminance = 0, intensity = 0;
  // A depth format (GL 1.4, ARB_depth_texture): its bits, 0 for a colour format. Its texels
  // hold the depth as a float's bits (depth_texel).
  uint8_t depth = 0;
  uint8_t stencil = 0;  // DEPTH_STENCIL formats (EXT_packed_depth_stencil): the stencil bits
  // DEPTH_COMPONENT32F and DEPTH32F_STENCIL8 (ARB_depth_buffer_float): the depth is a 32-bit
  // float, kept as given instead of truncated to `depth` bits.
  bool depth_float = false;
  // An sRGB format (GL 2.1, EXT_texture_sRGB): texels keep the sRGB-encoded values as given;
  // the sampler decodes them (raster/srgb.h).
  bool srgb = false;
};

// The storage of a colour internal format (1..4, the base formats and the sized ones), or
// nullopt when `internal_format` is not one.
std::optional<TextureFormat> texture_format(GLint internal_format);

// The internal format a level records (TEXTURE_INTERNAL_FORMAT): GL 1.3's generic compressed
// formats (COMPRESSED_RGB, ...) become their base format, as the spec says when no specific
// compressed format is chosen; any other is kept as given.
GLint stored_internal_format(GLint internal_format);

// An RGBA colour as a texel of the base format holds it (GL 1.5 table 3.15): missing colour
// components 0, missing alpha 1, luminance in R, G and B, intensity in all four.
void reduce_to_base_format(float rgba[4], raster::TexBaseFormat base);

// A depth clamped to [0, 1] as a texel of the depth format: truncated to its bits (as Mesa's
// Z16/Z24/Z32 packing), or rounded to float for a float format.
uint32_t depth_texel(double depth, const TextureFormat& format);

// `count` RGBA colours (4 floats each) reduced to the components the format keeps and quantized
// to its bits, as RGBA8 texels (R in the lowest byte).
void to_texels(const float* rgba, int count, const TextureFormat& format, uint32_t* out);

// Whether to_texels keeps 8-bit values: a colour format without a component of fewer than 8
// bits, whose texel of (k0, k1, k2, k3) / 255 is reduce_rgba8_to_base of (k0, k1, k2, k3).
bool keeps_bytes(const TextureFormat& format);

// reduce_to_base_format on `count` RGBA8 words (R in the lowest byte).
void reduce_rgba8_to_base(uint32_t* rgba, int count, raster::TexBaseFormat base);

// An RGBA8 texel (an average of stored texels, say) quantized again to the format's bits.
uint32_t requantize_texel(uint32_t texel, const TextureFormat& format);

}  // namespace pineda
