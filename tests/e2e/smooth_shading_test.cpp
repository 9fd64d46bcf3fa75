// Gouraud shading: colours interpolate linearly in window space (orthographic), within
// 1/255 of the analytic value at every pixel centre.
#include <cmath>

#include "tests/e2e/support/pixel_test.h"

namespace pineda::test {
namespace {

class SmoothShadingTest : public PixelTest {
 protected:
  SurfaceSpec spec() const override { return {64, 32, 24, 8}; }
};

TEST_F(SmoothShadingTest, HorizontalRamp) {
  glBegin(GL_QUADS);
  glColor3f(0, 0, 1);
  glVertex2f(0, 0);
  glColor3f(1, 0, 0);
  glVertex2f(64, 0);
  glColor3f(1, 0, 0);
  glVertex2f(64, 32);
  glColor3f(0, 0, 1);
  glVertex2f(0, 32);
  glEnd();
  for (int y : {0, 13, 31})
    for (int x = 0; x < 64; ++x) {
      const double t = (x + 0.5) / 64.0;
      EXPECT_TRUE(near_rgba(pixel(x, y), {to_byte(t), 0, to_byte(1 - t), 255}, 1)) << x << "," << y;
    }
}

TEST_F(SmoothShadingTest, TriangleBarycentricColours) {
  // Red at (0,0), green at (32,0), blue at (0,32): at a centre (px, py) the weights are
  // green = px / 32, blue = py / 32, red = 1 - both.
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0);
  glVertex2f(0, 0);
  glColor3f(0, 1, 0);
  glVertex2f(32, 0);
  glColor3f(0, 0, 1);
  glVertex2f(0, 32);
  glEnd();
  for (int y = 0; y < 32; y += 3)
    for (int x = 0; x + y < 31; x += 2) {
      const double g = (x + 0.5) / 32, b = (y + 0.5) / 32, r = 1 - g - b;
      EXPECT_TRUE(near_rgba(pixel(x, y), {to_byte(r), to_byte(g), to_byte(b), 255}, 1)) << x << "," << y;
    }
}

TEST_F(SmoothShadingTest, AlphaInterpolates) {
  glBegin(GL_QUADS);
  glColor4f(1, 1, 1, 0);
  glVertex2f(0, 0);
  glVertex2f(64, 0);
  glColor4f(1, 1, 1, 1);
  glVertex2f(64, 32);
  glVertex2f(0, 32);
  glEnd();
  for (int y = 0; y < 32; y += 5) {
    const double t = (y + 0.5) / 32.0;
    EXPECT_TRUE(near_rgba(pixel(20, y), {255, 255, 255, to_byte(t)}, 1)) << y;
  }
}

TEST_F(SmoothShadingTest, ColoursOutsideZeroOneAreClamped) {
  glBegin(GL_QUADS);
  glColor3f(2, -1, 0.5f);
  glVertex2f(0, 0);
  glVertex2f(8, 0);
  glVertex2f(8, 8);
  glVertex2f(0, 8);
  glEnd();
  EXPECT_TRUE(near_rgba(pixel(4, 4), {255, 0, 128, 255}, 1));
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

// Under glFrustum, colours interpolate perspective-correctly: a quad receding from z = -2
// (black) to z = -4 (white) has, at window row y, the parameter s of the point the pixel
// sees: y_ndc = (2s - 1) / (2 + 2s), so s = (2 y_ndc + 1) / (2 - 2 y_ndc).
TEST_F(SmoothShadingTest, PerspectiveCorrectInterpolation) {
  glViewport(0, 0, 32, 32);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 1, -1, 1, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glBegin(GL_QUADS);
  glColor3f(0, 0, 0);
  glVertex3f(-2, -1, -2);
  glVertex3f(2, -1, -2);
  glColor3f(1, 1, 1);
  glVertex3f(2, 1, -4);
  glVertex3f(-2, 1, -4);
  glEnd();
  for (int y = 9; y < 20; ++y) {
    const double y_ndc = (y + 0.5) / 16 - 1;
    const double s = (2 * y_ndc + 1) / (2 - 2 * y_ndc);
    EXPECT_NEAR(pixel(16, y)[0], s * 255, 1.0) << y;
  }
  EXPECT_TRUE(near_rgba(pixel(16, 7), {0, 0, 0, 0}));   // below the quad
  EXPECT_TRUE(near_rgba(pixel(16, 20), {0, 0, 0, 0}));  // above it
}

}  // namespace
}  // namespace pineda::test
