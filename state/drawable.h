// A set of buffers a context renders into (pbuffer, window back buffer, OSMesa buffer),
// owned by driver/; the context only borrows its framebuffer description.
#pragma once
#include <memory>
#include <vector>

#include "raster/cleared_tiles.h"
#include "raster/framebuffer.h"

namespace pineda {

struct Drawable {
  raster::Framebuffer framebuffer;
  int red_bits = 8, green_bits = 8, blue_bits = 8, alpha_bits = 8;
  bool double_buffered = false;
  bool accum = true;  // has an accumulation buffer (framebuffer objects have none)
  // The front buffer of a double-buffered drawable whose driver keeps one (framebuffer.color
  // is then the back buffer). Otherwise unset, and GL_FRONT names framebuffer.color.
  raster::ColorBuffer front;
  // A multisampled window (framebuffer.samples > 1): the single-sampled back buffer that
  // swaps and reads see, resolved from the sample planes when they need it. Unset otherwise
  // (and for framebuffer objects, which are read sample by sample or not at all).
  raster::ColorBuffer resolved;

  // Set by the context when it renders into the front buffer; the driver clears it when it
  // has shown the front buffer (glFlush shows front-buffer drawing, as in Mesa).
  bool front_drawn = false;

  // A framebuffer object's view: the storage it points into (renderbuffer pixels, texture
  // levels), kept alive while the view or the renderer uses it.
  std::vector<std::shared_ptr<const void>> kept_storage;

  // Called by the driver for newly allocated buffers: a new record of which tiles hold a
  // clear's value (raster/cleared_tiles.h), kept with the storage, where nothing but the
  // renderer writes the colour, depth and stencil buffers (`only_renderer_writes`); else none.
  void track_cleared_tiles(bool only_renderer_writes) {
    std::shared_ptr<raster::ClearedTiles> tiles;
    if (only_renderer_writes && framebuffer.samples == 1) tiles = std::make_shared<raster::ClearedTiles>();
    framebuffer.cleared_tiles = tiles.get();
    kept_storage.clear();
    if (tiles) kept_storage.push_back(std::move(tiles));
  }

  const raster::ColorBuffer& front_color() const { return front.base ? front : framebuffer.color; }
};

}  // namespace pineda
