// A set of buffers a context renders into (pbuffer, window back buffer, OSMesa buffer),
// owned by driver/; the context only borrows its framebuffer description.
#pragma once
#include "raster/framebuffer.h"

namespace pineda {

struct Drawable {
  raster::Framebuffer framebuffer;
  int red_bits = 8, green_bits = 8, blue_bits = 8, alpha_bits = 8;
  bool double_buffered = false;
};

}  // namespace pineda
