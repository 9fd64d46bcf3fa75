// glReadPixels' common case without the general path's conversions: an RGBA8 or BGRA8 colour
// buffer read as GL_UNSIGNED_BYTE RGBA, BGRA, RGB or BGR with no pixel transfer. The bytes are
// moved as they are stored: the general path's c / 255 and back (a component byte k becomes
// round(255 * k / 255) = k) gives the same bytes (pineda-bench's read_pixels scene, one thread:
// 70-77 ms a frame through the general path, 3.3-4.2 ms this way).
#pragma once
#include <GL/gl.h>

#include <cstddef>
#include <cstdint>

#include "raster/framebuffer.h"

namespace pineda::gl {

// Whether read_color_bytes reads `format` and `type` from `cb` (no pixel transfer assumed:
// the caller checks it).
bool reads_color_bytes(const raster::ColorBuffer& cb, GLenum format, GLenum type);

// Pixels [x0, x1) x [y0, y1) of cb in `format` (reads_color_bytes) to `first` (pixel (x0, y0)),
// rows `row_stride` bytes apart; `opaque`: alpha reads 255 (a buffer without alpha bits).
void read_color_bytes(const raster::ColorBuffer& cb, bool opaque, GLenum format, int x0, int x1, int y0, int y1,
                      uint8_t* first, size_t row_stride);

}  // namespace pineda::gl
