// PINEDA_CAPTURE=DIR: every frame a program presents (a GLX or EGL window's swap or
// front-buffer flush, an EGL pbuffer's swap) is written as DIR/frame-NNNNN.png, numbered from
// 00000 in presentation order across the process: headless screenshots of any GL program.
#pragma once
#include "raster/framebuffer.h"

namespace pineda::driver {

// Writes `color` (width x height, row 0 at the bottom) as the next frame when PINEDA_CAPTURE
// is set; does nothing otherwise. Failures to write are reported once on stderr.
void capture_frame(const raster::ColorBuffer& color, int width, int height);

}  // namespace pineda::driver
