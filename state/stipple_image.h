// The 32x32 polygon stipple as a client bitmap (GL_COLOR_INDEX / GL_BITMAP under the pixel
// store state) and as the rasterizer's rows (bit x of row y, bit 0 = leftmost pixel).
#pragma once
#include <GL/gl.h>

#include <array>
#include <cstdint>

namespace pineda {

struct PixelStore;

using StippleRows = std::array<uint32_t, 32>;

StippleRows unpack_stipple(const PixelStore& unpack, const GLubyte* bitmap);
// Writes only the bits of the 32x32 image; other bits of partly covered bytes are kept.
void pack_stipple(const PixelStore& pack, const StippleRows& rows, GLubyte* bitmap);

}  // namespace pineda
