// glReadPixels of depth and stencil in the types programs read them as, a row at a time
// without the general path's per-pixel dispatch on format and type: depth as GL_UNSIGNED_INT,
// GL_UNSIGNED_SHORT or GL_FLOAT without depth scale and bias, stencil as GL_UNSIGNED_BYTE
// without index shift, offset or map. Each value is the general path's (store_component of
// stored / (2^bits - 1)), so the bytes are the same.
#pragma once
#include <GL/gl.h>

#include <cstddef>
#include <cstdint>

#include "raster/framebuffer.h"
#include "state/pixels/pixel_state.h"

namespace pineda::gl {

// Whether read_depth_rows reads `type` under `mode` and `swap_bytes`.
bool reads_depth_rows(const PixelMode& mode, GLenum type, bool swap_bytes);
// Depth pixels [x0, x1) x [y0, y1) as `type` to `first` (pixel (x0, y0)), rows `row_stride`
// bytes apart.
void read_depth_rows(const raster::DepthBuffer& depth, GLenum type, int x0, int x1, int y0, int y1, uint8_t* first,
                     size_t row_stride);

// Whether read_stencil_rows reads `type` under `mode`.
bool reads_stencil_rows(const PixelMode& mode, GLenum type);
// Stencil pixels [x0, x1) x [y0, y1) as bytes to `first`, rows `row_stride` bytes apart.
void read_stencil_rows(const raster::StencilBuffer& stencil, int x0, int x1, int y0, int y1, uint8_t* first,
                       size_t row_stride);

}  // namespace pineda::gl
