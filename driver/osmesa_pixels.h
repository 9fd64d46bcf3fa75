// The user's OSMesa image: its layout, and conversion between it and an RGBA8 image.
#pragma once
#include <GL/gl.h>

#include <cstddef>
#include <cstdint>

namespace pineda::osmesa {

// Bytes per pixel of an OSMesa format with GL_UNSIGNED_BYTE; 0 when Pineda cannot render it.
int bytes_per_pixel(GLenum format);
// RGBA and BGRA are rendered in place; the others through an RGBA8 copy.
bool renders_in_place(GLenum format);

struct UserImage {
  uint8_t* pixels = nullptr;
  GLenum format = 0;
  int width = 0, height = 0;
  ptrdiff_t row_bytes = 0;
  bool y_up = true;  // row 0 of the memory is the bottom row

  uint8_t* row(int gl_y) const {
    int memory_row = y_up ? gl_y : height - 1 - gl_y;
    return pixels + memory_row * row_bytes;
  }
};

// `rgba` is width*height RGBA8 pixels, row 0 at the bottom, rows packed.
void store(const uint8_t* rgba, const UserImage& image);
void load(uint8_t* rgba, const UserImage& image);

}  // namespace pineda::osmesa
