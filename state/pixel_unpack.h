// Client images of glDrawPixels and glBitmap read under the unpack state, converted to the
// values the pixel-transfer stage works on.
#pragma once
#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "state/bitmap_layout.h"
#include "state/context.h"

namespace pineda {

// Bytes from `pixels` that a width x height image of format/type reads (BITMAP included).
size_t client_image_size(const PixelStore& store, int width, int height, GLenum format, GLenum type);

// RGBA per pixel, bottom row first; colour indices go through the index maps. Pixel transfer
// is applied.
std::vector<float> unpack_color_image(const Context& ctx, int width, int height, GLenum format, GLenum type,
                                      const void* pixels);
// Depth per pixel in [0, 1], after depth scale and bias.
std::vector<double> unpack_depth_image(const Context& ctx, int width, int height, GLenum type, const void* pixels);
// Stencil indices per pixel, after index shift, offset and MAP_STENCIL.
std::vector<int64_t> unpack_stencil_image(const Context& ctx, int width, int height, GLenum type,
                                          const void* pixels);

}  // namespace pineda
