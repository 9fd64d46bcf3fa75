// A rectangle texture (ARB_texture_rectangle) as a framebuffer object's colour attachment:
// rendered into, read back, then sampled at texel coordinates; only level 0 attaches.
#include "tests/framebuffers/fbo_test.h"

namespace pineda::test {
namespace {

using RectangleTextureTargetTest = FboTest;

TEST_F(RectangleTextureTargetTest, RenderIntoThenSample) {
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_RECTANGLE_ARB, tex);
  glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, 6, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  make_fbo();
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_RECTANGLE_ARB, tex, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_RECTANGLE_ARB, tex, 0);
  ASSERT_EQ(status(), GLenum(GL_FRAMEBUFFER_COMPLETE));
  GLint attached = 0;
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
                                        &attached);
  EXPECT_EQ(GLuint(attached), tex);
  glViewport(0, 0, 6, 3);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 6, 0, 3, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  clear_to(0, 0, 1, 1);
  glColor4f(1, 0, 0, 1);
  draw_rect(0, 0, 2, 3);  // columns 0 and 1 red
  glColor4f(0, 1, 0, 1);
  draw_rect(5, 2, 6, 3);  // the top right texel green
  EXPECT_EQ(pixel(1, 2), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(pixel(5, 2), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(pixel(3, 1), (Rgba{0, 0, 255, 255}));

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, 16, 16);
  pixel_projection();
  clear_to(0, 0, 0, 0);
  glColor4f(1, 1, 1, 1);
  glEnable(GL_TEXTURE_RECTANGLE_ARB);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_QUADS);  // 2x magnified: window pixel (x, y) reads texel (x / 2, y / 2)
  glTexCoord2f(0, 0); glVertex2f(0, 0);
  glTexCoord2f(6, 0); glVertex2f(12, 0);
  glTexCoord2f(6, 3); glVertex2f(12, 6);
  glTexCoord2f(0, 3); glVertex2f(0, 6);
  glEnd();
  glDisable(GL_TEXTURE_RECTANGLE_ARB);
  EXPECT_EQ(pixel(3, 5), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(pixel(4, 5), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(pixel(11, 5), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(pixel(11, 3), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(pixel(12, 5), (Rgba{0, 0, 0, 0}));
  glDeleteTextures(1, &tex);
}

}  // namespace
}  // namespace pineda::test
