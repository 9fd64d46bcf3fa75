// GL_DEPTH_STENCIL client pixels: GL_UNSIGNED_INT_24_8 (EXT_packed_depth_stencil), one 32-bit
// word a pixel, the depth in the high 24 bits and the stencil index in the low 8; or
// GL_FLOAT_32_UNSIGNED_INT_24_8_REV (ARB_depth_buffer_float), two words a pixel, the depth as
// a float in the first and the stencil index in the low 8 bits of the second.
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdint>
#include <vector>

#include "state/pixels/pixel_format.h"

namespace pineda {

class Context;
struct PixelStore;

// Whether format/type involve DEPTH_STENCIL or a packed depth-stencil type; `error` is then
// their error (another format with a packed depth-stencil type: INVALID_OPERATION;
// DEPTH_STENCIL with another type: INVALID_ENUM) or GL_NO_ERROR.
bool packed_depth_stencil_pixels(GLenum format, GLenum type, GlError& error);

// DEPTH_STENCIL pixels of `type` as the plain format and type of the same size and byte
// swapping (one or two UNSIGNED_INT components); other pairs unchanged.
void packed_depth_stencil_as_plain(GLenum& format, GLenum& type);

// The layout of a width-wide DEPTH_STENCIL image of `type`.
ImageLayout packed_depth_stencil_layout(const PixelStore& store, int width, GLenum type);

inline uint32_t pack_depth_stencil(double depth, uint32_t stencil) {
  const double d = depth > 0.0 ? (depth < 1.0 ? depth : 1.0) : 0.0;
  return (uint32_t(d * 16777215.0 + 0.5) << 8) | (stencil & 0xffu);
}

// One pixel of `type` (depth in [0, 1]) at `dst`, bytes swapped when `swap_bytes`.
void store_depth_stencil(double depth, uint32_t stencil, GLenum type, bool swap_bytes, uint8_t* dst);

// A client DEPTH_STENCIL image's depths (in [0, 1], depth transfer applied) and stencil
// indices (stencil transfer applied), bottom row first.
void unpack_depth_stencil_image(const Context& ctx, int width, int height, GLenum type, const void* pixels,
                                std::vector<double>& depth, std::vector<int64_t>& stencil);

}  // namespace pineda
