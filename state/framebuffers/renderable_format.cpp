#include "state/framebuffers/renderable_format.h"

#include <GL/glext.h>

namespace pineda {
namespace {

RenderableFormat color(const TextureFormat& f) { return {RenderableFormat::Kind::Color, f, 0, 0}; }
RenderableFormat depth(int bits) { return {RenderableFormat::Kind::Depth, {}, bits, 0}; }
RenderableFormat float_depth(RenderableFormat::Kind kind, int stencil_bits) { return {kind, {}, 32, stencil_bits, true}; }

// Stored bits of each RGBA8 channel and which written channel feeds it.
void channel_layout(const TextureFormat& f, uint8_t bits[4], uint8_t source[4]) {
  using B = raster::TexBaseFormat;
  const uint8_t lum = f.luminance, a = f.alpha, i = f.intensity;
  switch (f.base) {
    case B::Alpha: bits[0] = bits[1] = bits[2] = 0; bits[3] = a; break;
    case B::Luminance: bits[0] = bits[1] = bits[2] = lum; bits[3] = 0; source[1] = source[2] = 0; break;
    case B::LuminanceAlpha: bits[0] = bits[1] = bits[2] = lum; bits[3] = a; source[1] = source[2] = 0; break;
    case B::Intensity: bits[0] = bits[1] = bits[2] = bits[3] = i; source[1] = source[2] = source[3] = 0; break;
    case B::RGB: bits[0] = f.red; bits[1] = f.green; bits[2] = f.blue; bits[3] = 0; break;
    case B::RGBA: bits[0] = f.red; bits[1] = f.green; bits[2] = f.blue; bits[3] = f.alpha; break;
  }
}

}  // namespace

std::optional<RenderableFormat> renderbuffer_format(GLenum internal_format) {
  switch (internal_format) {
    case GL_DEPTH_COMPONENT: case GL_DEPTH_COMPONENT24: return depth(24);
    case GL_DEPTH_COMPONENT16: return depth(16);
    case GL_DEPTH_COMPONENT32: return depth(32);
    // Every stencil size is kept in 8 bits, as Mesa allocates them.
    case GL_STENCIL_INDEX: case GL_STENCIL_INDEX1: case GL_STENCIL_INDEX4: case GL_STENCIL_INDEX8:
    case GL_STENCIL_INDEX16:
      return RenderableFormat{RenderableFormat::Kind::Stencil, {}, 0, 8};
    case GL_DEPTH_STENCIL: case GL_DEPTH24_STENCIL8: return RenderableFormat{RenderableFormat::Kind::DepthStencil, {}, 24, 8};
    case GL_DEPTH_COMPONENT32F: return float_depth(RenderableFormat::Kind::Depth, 0);
    case GL_DEPTH32F_STENCIL8: return float_depth(RenderableFormat::Kind::DepthStencil, 8);
    case GL_RGB565: {
      TextureFormat f;
      f.base = raster::TexBaseFormat::RGB;
      f.red = 5, f.green = 6, f.blue = 5;
      return color(f);
    }
    // The unsized counts 1..4 name no renderbuffer format; compressed ones neither.
    case 1: case 2: case 3: case 4: return std::nullopt;
    default: break;
  }
  const std::optional<TextureFormat> f = texture_format(GLint(internal_format));
  if (!f || f->depth || stored_internal_format(GLint(internal_format)) != GLint(internal_format)) return std::nullopt;
  return color(*f);
}

std::optional<RenderableFormat> texture_renderable_format(GLint internal_format) {
  if (stored_internal_format(internal_format) != internal_format) return std::nullopt;  // compressed
  const std::optional<TextureFormat> f = texture_format(internal_format);
  if (!f) return std::nullopt;
  if (f->stencil) return RenderableFormat{RenderableFormat::Kind::DepthStencil, {}, f->depth, f->stencil, f->depth_float};
  if (f->depth) return RenderableFormat{RenderableFormat::Kind::Depth, {}, f->depth, 0, f->depth_float};
  return color(*f);
}

raster::ColorReduction color_reduction(const TextureFormat& format) {
  raster::ColorReduction r;
  channel_layout(format, r.bits, r.source);
  for (int c = 0; c < 4; ++c) r.active |= r.bits[c] != 8 || r.source[c] != c;
  return r;
}

GLenum color_base_enum(const TextureFormat& format) {
  switch (format.base) {
    case raster::TexBaseFormat::Alpha: return GL_ALPHA;
    case raster::TexBaseFormat::Luminance: return GL_LUMINANCE;
    case raster::TexBaseFormat::LuminanceAlpha: return GL_LUMINANCE_ALPHA;
    case raster::TexBaseFormat::Intensity: return GL_INTENSITY;
    case raster::TexBaseFormat::RGB: return GL_RGB;
    case raster::TexBaseFormat::RGBA: return GL_RGBA;
  }
  return GL_RGBA;
}

}  // namespace pineda
