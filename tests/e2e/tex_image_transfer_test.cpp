// glTexImage applies the pixel-transfer scale and bias to every component, alpha included
// (GL 1.5 3.8.1), as piglit teximage-scale-bias checks; that test asks for an RGB visual and
// probes the drawn alpha, which a framebuffer without alpha reads as 1 (on llvmpipe too).
#include "tests/e2e/support/pixel_test.h"

namespace pineda::test {
namespace {

class TexImageTransferTest : public PixelTest {};

TEST_F(TexImageTransferTest, ScaleAndBiasReachEveryComponent) {
  glPixelTransferf(GL_RED_SCALE, 2.f);
  glPixelTransferf(GL_RED_BIAS, -0.25f);
  glPixelTransferf(GL_GREEN_SCALE, 3.f);
  glPixelTransferf(GL_BLUE_BIAS, 0.4f);
  glPixelTransferf(GL_ALPHA_SCALE, 0.5f);
  glPixelTransferf(GL_ALPHA_BIAS, 0.25f);
  const float texel[4] = {0.5f, 0.25f, 0.1f, 0.5f};
  glBindTexture(GL_TEXTURE_2D, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_FLOAT, texel);
  glPixelTransferf(GL_RED_SCALE, 1.f);
  glPixelTransferf(GL_RED_BIAS, 0.f);
  glPixelTransferf(GL_GREEN_SCALE, 1.f);
  glPixelTransferf(GL_BLUE_BIAS, 0.f);
  glPixelTransferf(GL_ALPHA_SCALE, 1.f);
  glPixelTransferf(GL_ALPHA_BIAS, 0.f);
  const Rgba want{191, 191, 128, 128};  // 0.75, 0.75, 0.5, 0.5
  uint8_t stored[4] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, stored);
  EXPECT_EQ((Rgba{stored[0], stored[1], stored[2], stored[3]}), want);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0), glVertex2f(0, 0);
  glTexCoord2f(1, 0), glVertex2f(4, 0);
  glTexCoord2f(1, 1), glVertex2f(4, 4);
  glTexCoord2f(0, 1), glVertex2f(0, 4);
  glEnd();
  EXPECT_EQ(pixel(2, 2), want);
}

}  // namespace
}  // namespace pineda::test
