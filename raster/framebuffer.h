// The memory a draw renders into: plain pointers and strides, owned by a surface.
#pragma once
#include <cstddef>
#include <cstdint>

namespace pineda::raster {

enum class ColorFormat : uint8_t { RGBA8, BGRA8 };

// Row 0 is the bottom row (GL window y = 0); `stride` is in bytes and may be negative,
// so a top-down user buffer is expressed without copying.
struct ColorBuffer {
  uint8_t* base = nullptr;
  ptrdiff_t stride = 0;
  ColorFormat format = ColorFormat::RGBA8;
};

// Depth values are unsigned integers of `bits` bits (16, 24 or 32), one uint32 per pixel.
// bits == 0 means there is no depth buffer.
struct DepthBuffer {
  uint32_t* base = nullptr;
  ptrdiff_t stride = 0;  // in elements
  int bits = 0;
};

// bits == 0 means there is no stencil buffer; otherwise 8.
struct StencilBuffer {
  uint8_t* base = nullptr;
  ptrdiff_t stride = 0;  // in elements
  int bits = 0;
};

struct Framebuffer {
  int width = 0;
  int height = 0;
  ColorBuffer color;
  DepthBuffer depth;
  StencilBuffer stencil;
};

}  // namespace pineda::raster
