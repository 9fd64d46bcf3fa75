// Client images of glDrawPixels and glBitmap read under the unpack state, converted to the
// values the pixel-transfer stage works on.
#pragma once
#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "state/context.h"

namespace pineda {

// GL 1.5 spec 3.6.4, "Unpacking of bitmaps": one bit per pixel, rows padded to the alignment,
// SKIP_PIXELS counted in bits, most significant bit first unless LSB_FIRST.
class BitmapLayout {
 public:
  BitmapLayout(const PixelStore& store, int width);
  bool bit(const uint8_t* data, int i, int j) const;
  // Bytes from `data` that a width x height image reads.
  size_t size(int height) const;

 private:
  size_t row_stride_ = 0;
  size_t first_row_ = 0;
  int skip_bits_ = 0;
  int width_ = 0;
  bool lsb_first_ = false;
};

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
