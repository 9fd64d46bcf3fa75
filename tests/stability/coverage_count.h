// Counting how often each pixel is hit: every fragment increments the stencil buffer.
#pragma once
#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {

class CoverageCountTest : public GlTest {
 protected:
  SurfaceSpec spec() const override { return {96, 80, 24, 8}; }

  // Clears stencil and makes every fragment add one to it; colour writes off.
  void begin_counting() {
    pixel_projection();
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT | GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOp(GL_INCR, GL_INCR, GL_INCR);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  }

  // Hits per pixel, bottom row first.
  std::vector<uint8_t> hits() {
    std::vector<uint8_t> out(size_t(width()) * height());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width(), height(), GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, out.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    return out;
  }

  // Pixels whose hit count is not `expected`.
  int count_not(uint8_t expected) {
    int n = 0;
    for (uint8_t h : hits()) n += h != expected;
    return n;
  }
};

}  // namespace pineda::test
