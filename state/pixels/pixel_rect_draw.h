// Draws a converted pixel rectangle at the current raster position with the pixel zoom
// (GL 1.5 spec 3.6.5, "Conversion to fragments"): the shared back end of glDrawPixels and
// glCopyPixels.
#pragma once
#include <cstdint>
#include <vector>

#include "raster/framebuffer.h"
#include "state/context.h"

namespace pineda {

class ColorImageReader;

struct PixelRectImage {
  // DepthStencil (glDrawPixels and glCopyPixels of GL_DEPTH_STENCIL): the depth and the
  // stencil index written directly (scissor and stencil write mask only), as Mesa.
  enum class Kind { Color, Depth, Stencil, DepthStencil };
  Kind kind = Kind::Color;
  int width = 0, height = 0;
  std::vector<float> color;      // Color: RGBA per pixel, bottom row first
  // Color, in place of `color` when the pixels are bytes without pixel transfer: RGBA8 words
  // (rgba8_rows.h), a component byte k standing for k / 255.
  std::vector<uint32_t> rgba8;
  // Color, in place of both for glDrawPixels: the client's rows read as they are drawn (no copy
  // of the whole image), as RGBA8 words where the reader reads them so, else as RGBA.
  const ColorImageReader* color_reader = nullptr;
  // Color, in place of the others for glCopyPixels: row j read from `buffer`'s row y + j, from
  // column x, as it is drawn (set only where drawing goes in one pass at a y zoom of 1 from a
  // rectangle inside the buffer; the rows then go from the top when the copy moves up, so that
  // each row is read before the copy overwrites it).
  struct SourceRows {
    raster::ColorBuffer buffer;  // no base: not set
    int x = 0, y = 0;
    bool set() const { return buffer.base != nullptr; }
  } source_rows;
  std::vector<double> depth;     // Depth, DepthStencil: one value per pixel in [0, 1]
  std::vector<int64_t> stencil;  // Stencil, DepthStencil: one index per pixel
  std::vector<uint8_t> present;  // empty, or 0 for pixels that produce no fragment
};

void draw_pixel_rect(Context& ctx, const PixelRectImage& image);

}  // namespace pineda
