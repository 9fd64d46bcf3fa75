// Client images of glDrawPixels, glBitmap and glTexImage read under the unpack state,
// converted to the values the pixel-transfer stage works on.
#pragma once
#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "state/pixels/bitmap_layout.h"
#include "state/context.h"
#include "state/pixels/pixel_format.h"
#include "state/pixels/rgba8_rows.h"

namespace pineda {

// Bytes from `pixels` that a width x height image of format/type reads (BITMAP included).
size_t client_image_size(const PixelStore& store, int width, int height, GLenum format, GLenum type);

// Where the pixels of a client image are: any format and type, BITMAP included.
class ClientImage {
 public:
  ClientImage(const PixelStore& store, int width, GLenum format, GLenum type, const void* pixels);
  // The bytes of pixel i of row j, with their elements swapped (into `scratch`, 16 bytes)
  // under SWAP_BYTES. Not for BITMAP.
  const uint8_t* pixel(int i, int64_t j, uint8_t* scratch) const;
  // Pixel i of row j as an index: the bit of a BITMAP, or the value of an index type.
  int64_t index(int i, int64_t j) const;
  // The first byte of row j (its pixels follow at the format's pixel size). Not for BITMAP.
  const uint8_t* row(int64_t j) const;

 private:
  GLenum format_, type_;
  const uint8_t* data_;
  ImageLayout layout_;
  BitmapLayout bits_;
  bool swap_;
};

// One client colour image read pixel by pixel: a colour format of any type, or COLOR_INDEX
// (BITMAP too) through index shift/offset and the I_TO_R.. maps; pixel transfer applied.
class ColorImageReader {
 public:
  // `width`: pixels in a row of the image.
  ColorImageReader(const Context& ctx, int width, GLenum format, GLenum type, const void* pixels);
  // Pixel i of row j as RGBA in [0, 1].
  void read(int i, int64_t j, float rgba[4]) const;
  // Pixels first..first + count - 1 of row j as read() gives them, RGBA per pixel to `out`.
  void read_row(int64_t j, int first, int count, float* out) const;
  // Pixels first..first + count - 1 of row j as RGBA8 words (rgba8_rows.h), when the image
  // holds bytes in a way rgba8_source takes and no pixel transfer applies, so that read() would
  // give each byte / 255 exactly; false, with nothing written, otherwise.
  bool rgba8_texels(int64_t j, int first, int count, uint32_t* out) const;
  // Whether rgba8_texels reads this image.
  bool reads_rgba8() const { return !transfer_ && rgba8_.bytes; }
  // Row j's `width` pixels as RGBA8 words, when reads_rgba8(): the client row itself where it
  // holds them so (RGBA bytes or RGBA 8_8_8_8_REV words in this machine's order, on a word
  // boundary), else converted into `scratch` (`width` words).
  const uint32_t* rgba8_row_words(int64_t j, uint32_t* scratch) const;

 private:
  const Context& ctx_;
  int width_;
  GLenum format_, type_;
  ClientImage image_;
  bool transfer_;
  Rgba8Source rgba8_;
};

// Depth per pixel in [0, 1], after depth scale and bias.
std::vector<double> unpack_depth_image(const Context& ctx, int width, int height, GLenum type, const void* pixels);
// Stencil indices per pixel, after index shift, offset and MAP_STENCIL.
std::vector<int64_t> unpack_stencil_image(const Context& ctx, int width, int height, GLenum type,
                                          const void* pixels);

}  // namespace pineda
