// glReadPixels of colour into the unpacked types (GL_FLOAT, GL_UNSIGNED_SHORT, GL_INT, bytes in
// the formats color_byte_reads.h does not take, ...) with no pixel transfer: each stored byte k
// becomes store_color's value of k / 255, looked up in a table of the 256 values instead of
// converted per component (1024x768 as GL_RGBA GL_FLOAT, one thread: 30 ms through the general
// path), luminance the entry of R + G + B clamped to 255.
#pragma once
#include <GL/gl.h>

#include <cstddef>
#include <cstdint>

#include "raster/framebuffer.h"

namespace pineda::gl {

// Whether read_color_components reads `format` and `type` from `cb` (no pixel transfer
// assumed: the caller checks it).
bool reads_color_components(const raster::ColorBuffer& cb, GLenum format, GLenum type, bool swap_bytes);

// Pixels [x0, x1) x [y0, y1) of cb in `format` and `type` to `first` (pixel (x0, y0)), rows
// `row_stride` bytes apart; `opaque`: alpha reads 1 (a buffer without alpha bits).
void read_color_components(const raster::ColorBuffer& cb, bool opaque, GLenum format, GLenum type, int x0, int x1,
                           int y0, int y1, uint8_t* first, size_t row_stride);

}  // namespace pineda::gl
