// The fixture of the tests that draw in window coordinates: a 16x16 surface with depth and
// stencil, one unit per pixel (GlTest::pixel_projection), cleared to transparent black.
#pragma once
#include "tests/e2e/support/gl_test.h"
#include "tests/e2e/support/window_quad.h"

namespace pineda::test {

class PixelTest : public GlTest {
 protected:
  SurfaceSpec spec() const override { return {16, 16, 24, 8}; }
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
  }
  // A quad over the whole surface at depth 0.
  void full_quad() { draw_window_quad(float(width()), float(height())); }
};

}  // namespace pineda::test
