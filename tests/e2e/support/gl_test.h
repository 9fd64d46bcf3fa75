// GoogleTest fixtures over GlSurface: a current context, pixel read-back helpers, and a
// projection where one unit is one pixel (glOrtho(0, w, 0, h, -1, 1)).
#pragma once
#include <GL/gl.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "tests/e2e/support/gl_surface.h"

namespace pineda::test {

using Rgba = std::array<int, 4>;

// The pixel (x, y) of the read framebuffer, as glReadPixels gives it in RGBA8.
inline Rgba read_rgba(int x, int y) {
  uint8_t p[4] = {0, 0, 0, 0};
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  return {p[0], p[1], p[2], p[3]};
}

// Makes `surface` current, its viewport the whole surface and one unit one pixel (projection).
inline void make_current_with_pixel_projection(GlSurface& surface) {
  EXPECT_TRUE(surface.make_current());
  glViewport(0, 0, surface.width(), surface.height());
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, surface.width(), 0, surface.height(), -1, 1);
}

class GlTest : public ::testing::Test {
 protected:
  virtual SurfaceSpec spec() const { return {}; }

  void SetUp() override {
    surface_ = std::make_unique<GlSurface>(spec());
    ASSERT_TRUE(surface_->ok()) << surface_->error();
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
  void TearDown() override {
    if (surface_) surface_->release();
    surface_.reset();
  }

  int width() const { return surface_->width(); }
  int height() const { return surface_->height(); }

  // One unit = one pixel, origin at the bottom-left corner.
  void pixel_projection() {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, width(), 0, height(), -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
  }

  void clear_to(float r, float g, float b, float a) {
    glClearColor(r, g, b, a);
    glClear(GL_COLOR_BUFFER_BIT);
  }

  // The depth buffer cleared to `left` on the left half of the surface, `right` on the right.
  void clear_depth_halves(double left, double right) {
    glClearDepth(right);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, width() / 2, height());
    glClearDepth(left);
    glClear(GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
  }

  Rgba pixel(int x, int y) { return read_rgba(x, y); }

  // The whole colour buffer, bottom row first.
  std::vector<uint8_t> read_all() {
    std::vector<uint8_t> out(size_t(width()) * height() * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width(), height(), GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    return out;
  }

  // How many pixels have exactly this colour.
  int count_pixels(const Rgba& c) {
    const std::vector<uint8_t> all = read_all();
    int n = 0;
    for (size_t i = 0; i < all.size(); i += 4)
      if (all[i] == c[0] && all[i + 1] == c[1] && all[i + 2] == c[2] && all[i + 3] == c[3]) ++n;
    return n;
  }

  // The OSMesa buffer must hold what glReadPixels returns (no-op on EGL).
  void expect_osmesa_buffer_matches_readback() {
    const uint8_t* buf = surface_->osmesa_buffer();
    if (!buf) return;
    glFinish();
    const std::vector<uint8_t> all = read_all();
    EXPECT_TRUE(std::equal(all.begin(), all.end(), buf)) << "OSMesa buffer differs from glReadPixels";
  }

  std::unique_ptr<GlSurface> surface_;
};

inline ::testing::AssertionResult near_rgba(const Rgba& actual, const Rgba& expected, int tolerance = 0) {
  for (int i = 0; i < 4; ++i)
    if (std::abs(actual[i] - expected[i]) > tolerance)
      return ::testing::AssertionFailure()
             << "got (" << actual[0] << "," << actual[1] << "," << actual[2] << "," << actual[3] << ") expected ("
             << expected[0] << "," << expected[1] << "," << expected[2] << "," << expected[3] << ") +-" << tolerance;
  return ::testing::AssertionSuccess();
}

// Byte of a [0, 1] value, rounded as GL converts colours to fixed point.
inline int to_byte(double v) { return int(v * 255.0 + 0.5); }

}  // namespace pineda::test
