// glClear with scissor and write masks; the OSMesa buffer holds what glReadPixels reads.
#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

using ClearTest = GlTest;

TEST_F(ClearTest, ClearsEveryPixel) {
  clear_to(0.2f, 0.4f, 0.6f, 0.8f);
  EXPECT_EQ(count_pixels({51, 102, 153, 204}), width() * height());
  expect_osmesa_buffer_matches_readback();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ClearTest, ScissorLimitsTheClear) {
  clear_to(0, 0, 0, 0);
  glEnable(GL_SCISSOR_TEST);
  glScissor(3, 5, 7, 4);
  clear_to(1, 1, 1, 1);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 7 * 4);
  EXPECT_TRUE(near_rgba(pixel(3, 5), {255, 255, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(9, 8), {255, 255, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(2, 5), {0, 0, 0, 0}));
  EXPECT_TRUE(near_rgba(pixel(10, 8), {0, 0, 0, 0}));
  EXPECT_TRUE(near_rgba(pixel(3, 9), {0, 0, 0, 0}));
  EXPECT_TRUE(near_rgba(pixel(3, 4), {0, 0, 0, 0}));
  // Disabled, the scissor box is ignored.
  glDisable(GL_SCISSOR_TEST);
  clear_to(0, 0, 1, 0);
  EXPECT_EQ(count_pixels({0, 0, 255, 0}), width() * height());
  expect_osmesa_buffer_matches_readback();
}

TEST_F(ClearTest, ScissorPartlyOutsideTheSurface) {
  clear_to(0, 0, 0, 0);
  glEnable(GL_SCISSOR_TEST);
  glScissor(-4, width() - 3, 10, 100);
  clear_to(1, 0, 0, 1);
  EXPECT_EQ(count_pixels({255, 0, 0, 255}), 6 * 3);
}

TEST_F(ClearTest, ColorMaskProtectsChannels) {
  clear_to(0.2f, 0.4f, 0.6f, 0.8f);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  clear_to(1, 1, 0, 1);
  EXPECT_EQ(count_pixels({255, 102, 0, 204}), width() * height());
  expect_osmesa_buffer_matches_readback();
}

TEST_F(ClearTest, DepthAndStencilClearValues) {
  glClearDepth(0.5);
  glClearStencil(0x5a);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  GLfloat depth = -1;
  glReadPixels(4, 4, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  EXPECT_NEAR(depth, 0.5f, 1.0 / (1 << 23));
  GLubyte stencil = 0;
  glReadPixels(4, 4, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &stencil);
  EXPECT_EQ(stencil, 0x5a);
  // The stencil write mask and the depth mask limit the clear.
  glStencilMask(0x0f);
  glClearStencil(0xff);
  glDepthMask(GL_FALSE);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glReadPixels(4, 4, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &stencil);
  EXPECT_EQ(stencil, 0x5f);
  glReadPixels(4, 4, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  EXPECT_NEAR(depth, 0.5f, 1.0 / (1 << 23));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ClearTest, ClearInsideBeginEndDoesNothing) {
  clear_to(0, 0, 0, 0);
  glClearColor(1, 1, 1, 1);
  glBegin(GL_POINTS);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
}

}  // namespace
}  // namespace pineda::test
