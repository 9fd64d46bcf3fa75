#include "state/textures/texture_format.h"

#include <GL/glext.h>
#include <emmintrin.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include "raster/fragment_ops.h"

namespace pineda {
namespace {

using raster::TexBaseFormat;

TextureFormat rgba(TexBaseFormat base, uint8_t r, uint8_t g, uint8_t b, uint8_t a) {
  TextureFormat f;
  f.base = base;
  f.red = r, f.green = g, f.blue = b, f.alpha = a;
  return f;
}
TextureFormat luminance_alpha(uint8_t l, uint8_t a) {
  TextureFormat f;
  f.base = a ? (l ? TexBaseFormat::LuminanceAlpha : TexBaseFormat::Alpha) : TexBaseFormat::Luminance;
  f.luminance = l, f.alpha = a;
  return f;
}
TextureFormat depth_format(uint8_t bits) {
  TextureFormat f;
  f.base = TexBaseFormat::Luminance;  // DEPTH_TEXTURE_MODE decides it when the texture is sampled
  f.depth = bits;
  return f;
}
TextureFormat float_depth(uint8_t stencil) {
  TextureFormat f = depth_format(32);
  f.depth_float = true;
  f.stencil = stencil;
  return f;
}
TextureFormat srgb(TextureFormat f) {
  f.srgb = true;
  return f;
}
TextureFormat intensity() {
  TextureFormat f;
  f.base = TexBaseFormat::Intensity;
  f.intensity = 8;
  return f;
}

// The bits of each RGBA8 texel channel: luminance and intensity live in R (intensity in all four).
int channel_bits(const TextureFormat& f, int channel) {
  switch (f.base) {
    case TexBaseFormat::Luminance: case TexBaseFormat::LuminanceAlpha:
      return channel == 3 ? f.alpha : f.luminance;
    case TexBaseFormat::Intensity: return f.intensity;
    default: {
      const uint8_t bits[4] = {f.red, f.green, f.blue, f.alpha};
      return bits[channel];
    }
  }
}

// A value of 0..max as the nearest 8-bit one.
uint32_t widen(uint32_t q, uint32_t max) { return (q * 255 + max / 2) / max; }

// An 8-bit channel value rounded to `bits` bits and widened back to 8.
uint32_t quantize(uint32_t v, int bits) {
  if (bits <= 0 || bits >= 8) return v;
  const uint32_t max = (1u << bits) - 1;
  return widen((v * max + 127) / 255, max);
}

GLint generic_compressed_base(GLint internal_format) {
  switch (internal_format) {
    case GL_COMPRESSED_ALPHA: return GL_ALPHA;
    case GL_COMPRESSED_LUMINANCE: return GL_LUMINANCE;
    case GL_COMPRESSED_LUMINANCE_ALPHA: return GL_LUMINANCE_ALPHA;
    case GL_COMPRESSED_INTENSITY: return GL_INTENSITY;
    case GL_COMPRESSED_RGB: return GL_RGB;
    case GL_COMPRESSED_RGBA: return GL_RGBA;
    case GL_COMPRESSED_SRGB: return GL_SRGB;
    case GL_COMPRESSED_SRGB_ALPHA: return GL_SRGB_ALPHA;
    case GL_COMPRESSED_SLUMINANCE: return GL_SLUMINANCE;
    case GL_COMPRESSED_SLUMINANCE_ALPHA: return GL_SLUMINANCE_ALPHA;
    default: return 0;
  }
}

}  // namespace

GLint stored_internal_format(GLint internal_format) {
  const GLint base = generic_compressed_base(internal_format);
  return base ? base : internal_format;
}

// Mesa's choices (llvmpipe, probed with glGetTexLevelParameter), with 8 bits for those it keeps wider.
std::optional<TextureFormat> texture_format(GLint internal_format) {
  switch (stored_internal_format(internal_format)) {
    case GL_ALPHA: case GL_ALPHA4: case GL_ALPHA8: case GL_ALPHA12: case GL_ALPHA16:
      return luminance_alpha(0, 8);
    case 1: case GL_LUMINANCE: case GL_LUMINANCE4: case GL_LUMINANCE8: case GL_LUMINANCE12: case GL_LUMINANCE16:
      return luminance_alpha(8, 0);
    case GL_LUMINANCE4_ALPHA4:
      return luminance_alpha(4, 4);
    case 2: case GL_LUMINANCE_ALPHA: case GL_LUMINANCE6_ALPHA2: case GL_LUMINANCE8_ALPHA8:
    case GL_LUMINANCE12_ALPHA4: case GL_LUMINANCE12_ALPHA12: case GL_LUMINANCE16_ALPHA16:
      return luminance_alpha(8, 8);
    case GL_INTENSITY: case GL_INTENSITY4: case GL_INTENSITY8: case GL_INTENSITY12: case GL_INTENSITY16:
      return intensity();
    case GL_R3_G3_B2: return rgba(TexBaseFormat::RGB, 3, 3, 2, 0);
    case GL_RGB4: return rgba(TexBaseFormat::RGB, 4, 4, 4, 0);
    case GL_RGB5: return rgba(TexBaseFormat::RGB, 5, 5, 5, 0);
    case GL_RGB565: return rgba(TexBaseFormat::RGB, 5, 6, 5, 0);  // ARB_ES2_compatibility
    case 3: case GL_RGB: case GL_RGB8: case GL_RGB10: case GL_RGB12: case GL_RGB16:
      return rgba(TexBaseFormat::RGB, 8, 8, 8, 0);
    case GL_RGBA2: case GL_RGBA4: return rgba(TexBaseFormat::RGBA, 4, 4, 4, 4);
    case GL_RGB5_A1: return rgba(TexBaseFormat::RGBA, 5, 5, 5, 1);
    case GL_RGB10_A2: return rgba(TexBaseFormat::RGBA, 8, 8, 8, 2);
    case 4: case GL_RGBA: case GL_RGBA8: case GL_RGBA12: case GL_RGBA16:
      return rgba(TexBaseFormat::RGBA, 8, 8, 8, 8);
    case GL_SRGB: case GL_SRGB8: return srgb(rgba(TexBaseFormat::RGB, 8, 8, 8, 0));
    case GL_SRGB_ALPHA: case GL_SRGB8_ALPHA8: return srgb(rgba(TexBaseFormat::RGBA, 8, 8, 8, 8));
    case GL_SLUMINANCE: case GL_SLUMINANCE8: return srgb(luminance_alpha(8, 0));
    case GL_SLUMINANCE_ALPHA: case GL_SLUMINANCE8_ALPHA8: return srgb(luminance_alpha(8, 8));
    case GL_DEPTH_COMPONENT: case GL_DEPTH_COMPONENT24: return depth_format(24);
    case GL_DEPTH_COMPONENT16: return depth_format(16);
    case GL_DEPTH_COMPONENT32: return depth_format(32);
    case GL_DEPTH_STENCIL: case GL_DEPTH24_STENCIL8: {
      TextureFormat f = depth_format(24);
      f.stencil = 8;
      return f;
    }
    case GL_DEPTH_COMPONENT32F: return float_depth(0);
    case GL_DEPTH32F_STENCIL8: return float_depth(8);
    default: return std::nullopt;
  }
}

uint32_t depth_texel(double depth, const TextureFormat& format) {
  const double d = depth > 0.0 ? std::min(depth, 1.0) : 0.0;  // NaN as 0
  if (format.depth_float) return std::bit_cast<uint32_t>(static_cast<float>(d));
  const double max = std::ldexp(1.0, format.depth) - 1.0;
  return std::bit_cast<uint32_t>(static_cast<float>(std::floor(d * max) / max));  // truncated, as Mesa packs
}

uint32_t requantize_texel(uint32_t texel, const TextureFormat& format) {
  uint32_t out = 0;
  for (int c = 0; c < 4; ++c) out |= quantize((texel >> (8 * c)) & 0xffu, channel_bits(format, c)) << (8 * c);
  return out;
}

void reduce_to_base_format(float rgba[4], raster::TexBaseFormat base) {
  switch (base) {
    case TexBaseFormat::Alpha: rgba[0] = rgba[1] = rgba[2] = 0.f; break;
    case TexBaseFormat::Luminance: rgba[1] = rgba[2] = rgba[0]; rgba[3] = 1.f; break;
    case TexBaseFormat::LuminanceAlpha: rgba[1] = rgba[2] = rgba[0]; break;
    case TexBaseFormat::Intensity: rgba[1] = rgba[2] = rgba[3] = rgba[0]; break;
    case TexBaseFormat::RGB: rgba[3] = 1.f; break;
    case TexBaseFormat::RGBA: break;
  }
}

bool keeps_bytes(const TextureFormat& format) {
  if (format.depth || format.stencil) return false;
  for (int i = 0; i < 4; ++i) {
    const int bits = channel_bits(format, i);
    if (bits > 0 && bits < 8) return false;
  }
  return true;
}

void reduce_rgba8_to_base(uint32_t* rgba, int count, TexBaseFormat base) {
  auto each = [&](auto reduce) {
    for (int i = 0; i < count; ++i) rgba[i] = reduce(rgba[i]);
  };
  switch (base) {
    case TexBaseFormat::Alpha: return each([](uint32_t t) { return t & 0xff000000u; });
    case TexBaseFormat::Luminance: return each([](uint32_t t) { return (t & 0xffu) * 0x010101u | 0xff000000u; });
    case TexBaseFormat::LuminanceAlpha:
      return each([](uint32_t t) { return (t & 0xffu) * 0x010101u | (t & 0xff000000u); });
    case TexBaseFormat::Intensity: return each([](uint32_t t) { return (t & 0xffu) * 0x01010101u; });
    case TexBaseFormat::RGB: return each([](uint32_t t) { return t | 0xff000000u; });
    case TexBaseFormat::RGBA: return;
  }
}

namespace {

// raster::to_unorm8 of n floats, 16 at a time with SSE2 (the baseline; -O2 leaves the scalar
// loop scalar): the same values lane by lane. maxps returns its second operand, 0, for a NaN as
// clamp01 does, and +0 for -0.
void to_unorm8_bytes(const float* in, size_t n, uint8_t* out) {
  const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.f), scale = _mm_set1_ps(255.f),
               magic = _mm_set1_ps(8388608.f);
  const __m128i magic_bits = _mm_set1_epi32(0x4b000000);
  auto quarter = [&](const float* p) {
    const __m128 clamped = _mm_min_ps(_mm_max_ps(_mm_loadu_ps(p), zero), one);
    return _mm_sub_epi32(_mm_castps_si128(_mm_add_ps(_mm_mul_ps(clamped, scale), magic)), magic_bits);
  };
  size_t i = 0;
  for (; i + 16 <= n; i += 16) {
    const __m128i low = _mm_packs_epi32(quarter(in + i), quarter(in + i + 4));  // values 0..255 pack exactly
    const __m128i high = _mm_packs_epi32(quarter(in + i + 8), quarter(in + i + 12));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i), _mm_packus_epi16(low, high));
  }
  for (; i < n; ++i) out[i] = raster::to_unorm8(in[i]);
}

}  // namespace

void to_texels(const float* rgba, int count, const TextureFormat& format, uint32_t* out) {
  uint32_t max[4];
  bool bytes = true;
  for (int i = 0; i < 4; ++i) {
    const int bits = channel_bits(format, i);
    max[i] = bits > 0 && bits < 8 ? (1u << bits) - 1 : 255u;
    bytes = bytes && max[i] == 255u;
  }
  if (bytes && format.base == TexBaseFormat::RGBA) {  // no reduction: byte for component
    // RGBA8 words: R in the lowest byte.
    to_unorm8_bytes(rgba, 4 * static_cast<size_t>(count), reinterpret_cast<uint8_t*>(out));
    return;
  }
  for (int k = 0; k < count; ++k, rgba += 4) {
    float c[4] = {rgba[0], rgba[1], rgba[2], rgba[3]};
    reduce_to_base_format(c, format.base);
    uint32_t texel = 0;
    if (bytes) {
      // raster::to_unorm8 is std::lrint(std::clamp(c, 0, 1) * 255) below for every float (NaN
      // too: lrint's out-of-range result truncates to 0), without a call per channel.
      for (int i = 0; i < 4; ++i) texel |= uint32_t{raster::to_unorm8(c[i])} << (8 * i);
      out[k] = texel;
      continue;
    }
    for (int i = 0; i < 4; ++i) {
      // Rounded in float as Mesa's texture packing: ties to even for 8 bits (float_to_ubyte:
      // 0.3f * 255 is 76.5 and stores 76), away from zero for fewer (util_iround).
      const float scaled = std::clamp(c[i], 0.f, 1.f) * float(max[i]);
      const uint32_t q = uint32_t(max[i] == 255u ? std::lrint(scaled) : std::lround(scaled));
      texel |= widen(q, max[i]) << (8 * i);
    }
    out[k] = texel;
  }
}

}  // namespace pineda
