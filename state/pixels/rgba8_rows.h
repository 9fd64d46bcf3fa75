// Client rows that hold RGBA8 as bytes or as 8_8_8_8 words, turned into RGBA8 texel words (R in
// the lowest byte) without the general path's conversion through floats: texture uploads of
// GL_RGBA / GL_BGRA / GL_RGB / GL_BGR bytes and of GL_RGBA / GL_BGRA 8_8_8_8(_REV) words (SDL's
// renderer, video players and image loaders upload these). A byte k read through the general
// path becomes k / 255 and is stored as lrint(k / 255 * 255) = k, so the texels are the same.
#pragma once
#include <GL/gl.h>

#include <cstdint>

namespace pineda {

// A pixel word (R in the lowest byte) with red and blue exchanged.
inline uint32_t swap_red_blue(uint32_t p) { return (p & 0xff00ff00u) | ((p >> 16) & 0xffu) | ((p & 0xffu) << 16); }

// How a client format and type hold RGBA8; bytes 0: not in a way rgba8_row_texels reads.
struct Rgba8Source {
  int bytes = 0;          // per pixel: 4, or 3 (no alpha: it reads 255)
  bool reversed = false;  // each pixel a word whose highest byte is the format's first component
  bool blue_first = false;
};
Rgba8Source rgba8_source(GLenum format, GLenum type, bool swap_bytes);

// `count` pixels from `src` as RGBA8 texels; `opaque`: alpha 255 whatever the source says.
void rgba8_row_texels(const Rgba8Source& source, const uint8_t* src, int count, bool opaque, uint32_t* out);

}  // namespace pineda
