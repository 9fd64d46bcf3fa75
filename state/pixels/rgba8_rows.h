// Client rows that hold colour as bytes or as 8_8_8_8 words, turned into RGBA8 words (R in the
// lowest byte; the components a format lacks 0, alpha 1, as load_color gives them) without the
// general path's conversion through floats: texture uploads of GL_RGBA / GL_BGRA / GL_RGB /
// GL_BGR bytes, GL_RGBA / GL_BGRA 8_8_8_8(_REV) words (SDL's renderer, video players and image
// loaders upload these) and GL_ALPHA / GL_LUMINANCE / GL_LUMINANCE_ALPHA / GL_RED / GL_GREEN /
// GL_BLUE bytes (glyph atlases). A byte k read through the general path becomes k / 255 and is
// stored as lrint(k / 255 * 255) = k, so the texels are the same.
#pragma once
#include <GL/gl.h>

#include <cstdint>

#include "raster/framebuffer.h"

namespace pineda {

using raster::swap_red_blue;

// How a client format and type hold RGBA8; bytes 0: not in a way rgba8_row_texels reads.
struct Rgba8Source {
  int bytes = 0;          // per pixel: 4, 3 (RGB or BGR), or 1 or 2 (below)
  bool reversed = false;  // each pixel a word whose highest byte is the format's first component
  bool blue_first = false;
  // 1 or 2 bytes: the word is `defaults` | first byte * `spread` (| second byte << 24: alpha).
  uint32_t spread = 0, defaults = 0;
};
Rgba8Source rgba8_source(GLenum format, GLenum type, bool swap_bytes);

// `count` pixels from `src` as RGBA8 words.
void rgba8_row_texels(const Rgba8Source& source, const uint8_t* src, int count, uint32_t* out);

}  // namespace pineda
