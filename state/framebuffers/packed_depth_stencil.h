// GL_DEPTH_STENCIL / GL_UNSIGNED_INT_24_8 client pixels (EXT_packed_depth_stencil): each pixel
// one 32-bit word, the depth in the high 24 bits and the stencil index in the low 8.
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdint>
#include <vector>

#include "state/pixel_format.h"

namespace pineda {

class Context;
struct PixelStore;

// Whether format/type involve DEPTH_STENCIL or UNSIGNED_INT_24_8; `error` is then their error
// (other formats with UNSIGNED_INT_24_8: INVALID_OPERATION; DEPTH_STENCIL with another type:
// INVALID_ENUM) or GL_NO_ERROR.
bool packed_depth_stencil_pixels(GLenum format, GLenum type, GlError& error);

// The layout of a width-wide DEPTH_STENCIL image: one 4-byte element per pixel.
ImageLayout packed_depth_stencil_layout(const PixelStore& store, int width);

inline uint32_t pack_depth_stencil(double depth, uint32_t stencil) {
  const double d = depth > 0.0 ? (depth < 1.0 ? depth : 1.0) : 0.0;
  return (uint32_t(d * 16777215.0 + 0.5) << 8) | (stencil & 0xffu);
}

// A client DEPTH_STENCIL image's depths (in [0, 1], depth transfer applied) and stencil
// indices (stencil transfer applied), bottom row first.
void unpack_depth_stencil_image(const Context& ctx, int width, int height, const void* pixels,
                                std::vector<double>& depth, std::vector<int64_t>& stencil);

}  // namespace pineda
