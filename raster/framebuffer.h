// The memory a draw renders into: plain pointers and strides, owned by a surface.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

namespace pineda::raster {

enum class ColorFormat : uint8_t { RGBA8, BGRA8 };

// A pixel word (R in the lowest byte) with red and blue exchanged: RGBA8 to BGRA8 and back; T is
// uint32_t or a vector of them (the fill routines' rows).
template <typename T>
inline T swap_red_blue(T p) {
  return (p & 0xff00ff00u) | ((p >> 16) & 0xffu) | ((p & 0xffu) << 16);
}

class ClearedTiles;

// A target that keeps fewer bits or components than its four bytes (RGB565, RGBA4, RGB8,
// luminance, ...; framebuffer objects): every written pixel is reduced to what the format
// holds before it is stored, so that blending, reads and sampling see the format's values.
// Only RGBA8-ordered buffers are reduced.
struct ColorReduction {
  bool active = false;  // false: the four bytes are kept as written
  // Per channel R, G, B, A: the bits kept (1..8; each value rounded to them and widened back
  // to 8), or 0 when the format has no such component (it then reads 0, alpha 1).
  uint8_t bits[4] = {8, 8, 8, 8};
  // The written channel each stored channel takes: luminance keeps R in R, G and B.
  uint8_t source[4] = {0, 1, 2, 3};
};

// Row 0 is the bottom row (GL window y = 0); `stride` is in bytes and may be negative,
// so a top-down user buffer is expressed without copying.
struct ColorBuffer {
  uint8_t* base = nullptr;
  ptrdiff_t stride = 0;
  ColorFormat format = ColorFormat::RGBA8;
  ColorReduction reduction;
  ptrdiff_t sample_stride = 0;  // bytes from one sample's plane to the next (multisampled)
};

// Depth values are unsigned integers of `bits` bits (16, 24 or 32), one uint32 per pixel.
// bits == 0 means there is no depth buffer.
struct DepthBuffer {
  uint32_t* base = nullptr;
  ptrdiff_t stride = 0;  // in elements
  int bits = 0;
  ptrdiff_t sample_stride = 0;  // elements from one sample's plane to the next
};

// bits == 0 means there is no stencil buffer; otherwise 8.
struct StencilBuffer {
  uint8_t* base = nullptr;
  ptrdiff_t stride = 0;  // in elements
  int bits = 0;
  ptrdiff_t sample_stride = 0;  // elements from one sample's plane to the next
};

// The colour buffers one draw writes at most (GL_MAX_DRAW_BUFFERS).
constexpr int kMaxColorTargets = 8;

// A multisampled framebuffer (samples > 1) keeps each sample as a whole plane of every
// buffer: sample s of a pixel is where the pixel is in plane s (raster/multisample.h).
//
// A framebuffer object with several draw buffers (glDrawBuffers) has `color_targets` > 1:
// `color` is draw buffer 0 and more_color[i - 1] draw buffer i, a null base where the draw
// buffer is GL_NONE. Every draw buffer takes the fragment's colour (draw_targets.h); depth and
// stencil are tested and written once.
struct Framebuffer {
  int width = 0;
  int height = 0;
  int samples = 1;
  ColorBuffer color;
  DepthBuffer depth;
  StencilBuffer stencil;
  int color_targets = 1;
  std::array<ColorBuffer, kMaxColorTargets - 1> more_color{};
  // The draw buffer `color` is: a window's glDrawBuffers passes write one draw buffer at a
  // time, and each takes its own blend enable and colour mask (DrawState::use_target_write).
  int color_index = 0;
  // Set (by the buffers' owner) only where nothing but the renderer writes these buffers
  // between flushes (cleared_tiles.h); single-sampled, one colour target.
  ClearedTiles* cleared_tiles = nullptr;

  const ColorBuffer& target_color(int i) const { return i == 0 ? color : more_color[static_cast<size_t>(i - 1)]; }
  // The same framebuffer with draw buffer i as its only colour buffer.
  Framebuffer target(int i) const {
    Framebuffer one = *this;
    one.color = target_color(i);
    one.color_targets = 1;
    one.more_color = {};
    one.color_index = color_index + i;
    one.cleared_tiles = nullptr;
    return one;
  }
};

}  // namespace pineda::raster
