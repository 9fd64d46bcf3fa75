// The accumulation buffer (GL 1.1 4.2.4): signed 16-bit RGBA values in [-1, 1], as Mesa's
// software drivers keep it. Each context allocates it at its first use, for the size of the
// drawable it draws to; programs that never accumulate pay nothing.
#pragma once
#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "raster/framebuffer.h"

namespace pineda {

class Context;

constexpr int kAccumBits = 16;  // per channel, in every configuration

struct AccumState {
  float clear_value[4] = {0, 0, 0, 0};  // glClearAccum, in [-1, 1]
  int width = 0, height = 0;
  std::vector<int16_t> values;  // RGBA per pixel, bottom row first
};

// A window-coordinate rectangle: the drawable, limited by the scissor box when it is enabled.
struct AccumRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// Makes the buffer `width` x `height` (zeroed when the size changes) and returns the area
// accumulation operations touch.
AccumRect prepare_accum(Context& ctx, int width, int height);

// glClear(GL_ACCUM_BUFFER_BIT): the clear value inside the scissor box.
void clear_accum(Context& ctx);

}  // namespace pineda
