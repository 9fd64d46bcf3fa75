// Colour read back as bytes without the general path's conversions: glReadPixels of an RGBA8
// or BGRA8 colour buffer, and glGetTexImage of an RGBA8-stored level, as GL_UNSIGNED_BYTE
// RGBA, BGRA, RGB or BGR, or as RGBA or BGRA GL_UNSIGNED_INT_8_8_8_8(_REV) words (the bytes of a
// little-endian machine, each pixel's reversed for 8_8_8_8 and under SWAP_BYTES), with no pixel
// transfer. The bytes are moved as they are stored: the
// general path's c / 255 and back (a component byte k becomes round(255 * k / 255) = k) gives
// the same bytes (pineda-bench's read_pixels scene, one thread: 70-77 ms a frame through the
// general path, 3.3-4.2 ms this way).
#pragma once
#include <GL/gl.h>

#include <cstddef>
#include <cstdint>

#include "raster/framebuffer.h"

namespace pineda::gl {

// Whether pack_rgba8_row writes `format` and `type`.
bool packs_rgba8_bytes(GLenum format, GLenum type);
// Whether pack_rgba8_row reverses each pixel's four bytes for `type` (packs_rgba8_bytes).
bool reverses_rgba8_words(GLenum type, bool swap_bytes);

// `n` pixels stored as RGBA8 words (R in the lowest byte; BGRA8 when `stored_bgra`) to `dst` in
// `format` (packs_rgba8_bytes), alpha ORed with `alpha` (0xff000000: alpha reads 255), each
// pixel's bytes reversed when `reversed` (reverses_rgba8_words).
void pack_rgba8_row(const uint8_t* src, bool stored_bgra, GLenum format, uint32_t alpha, uint8_t* dst, int n,
                    bool reversed = false);

// Whether read_color_bytes reads `format` and `type` from `cb` (no pixel transfer assumed:
// the caller checks it).
bool reads_color_bytes(const raster::ColorBuffer& cb, GLenum format, GLenum type);

// Pixels [x0, x1) x [y0, y1) of cb in `format` (reads_color_bytes) to `first` (pixel (x0, y0)),
// rows `row_stride` bytes apart; `opaque`: alpha reads 255 (a buffer without alpha bits).
void read_color_bytes(const raster::ColorBuffer& cb, bool opaque, GLenum format, int x0, int x1, int y0, int y1,
                      uint8_t* first, size_t row_stride, bool reversed = false);

}  // namespace pineda::gl
