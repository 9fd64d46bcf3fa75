// The secondary colour and the colour sum (GL 1.5 sections 2.7 and 3.9), and lighting's
// separate specular colour added after texturing.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include "tests/e2e/support/pixel_test.h"

namespace pineda::test {
namespace {

using SecondaryColorTest = PixelTest;

TEST_F(SecondaryColorTest, ColorSumAddsTheSecondaryColour) {
  glColor4f(0.25f, 0, 0, 0.5f);
  glSecondaryColor3f(0.5f, 0.25f, 0);
  full_quad();
  EXPECT_TRUE(near_rgba(pixel(8, 8), {64, 0, 0, 128}));  // COLOR_SUM off
  glEnable(GL_COLOR_SUM);
  full_quad();
  EXPECT_TRUE(near_rgba(pixel(8, 8), {191, 64, 0, 128}));  // alpha is not summed
  glSecondaryColor3ub(255, 255, 255);
  full_quad();
  EXPECT_TRUE(near_rgba(pixel(8, 8), {255, 255, 255, 128}));  // clamped
}

TEST_F(SecondaryColorTest, SecondaryColorArray) {
  const GLfloat pos[] = {0, 0, 16, 0, 16, 16, 0, 16};
  const GLubyte sec[] = {0, 64, 0, 0, 64, 0, 0, 64, 0, 0, 64, 0};
  glVertexPointer(2, GL_FLOAT, 0, pos);
  glSecondaryColorPointer(3, GL_UNSIGNED_BYTE, 0, sec);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  glEnable(GL_COLOR_SUM);
  glColor3f(0.25f, 0, 0);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_TRUE(near_rgba(pixel(8, 8), {64, 64, 0, 255}));
  glSecondaryColorPointer(4, GL_FLOAT, 0, sec);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLint size = 0;
  glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_SIZE, &size);
  EXPECT_EQ(size, 3);
}

TEST_F(SecondaryColorTest, CurrentSecondaryColorQuery) {
  GLfloat c[4];
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, c);
  EXPECT_EQ(c[0], 0.f);
  EXPECT_EQ(c[3], 1.f);
  glSecondaryColor3ub(255, 0, 51);
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, c);
  EXPECT_EQ(c[0], 1.f);
  EXPECT_FLOAT_EQ(c[2], 0.2f);
  glPushAttrib(GL_CURRENT_BIT);
  glSecondaryColor3f(0, 0, 0);
  glPopAttrib();
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, c);
  EXPECT_EQ(c[0], 1.f);
}

TEST_F(SecondaryColorTest, SeparateSpecularIsAddedAfterTexturing) {
  const GLubyte black[4] = {0, 0, 0, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, black);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
  const GLfloat zero[4] = {0, 0, 0, 1}, spec[4] = {0.25f, 0.75f, 0, 1}, white[4] = {1, 1, 1, 1};
  const GLfloat dir[4] = {0, 0, 1, 0};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, zero);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, zero);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, zero);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 0);
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, zero);
  glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHTING);
  glNormal3f(0, 0, 1);
  full_quad();
  EXPECT_TRUE(near_rgba(pixel(8, 8), {0, 0, 0, 255}));  // single colour: modulated away
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  full_quad();
  EXPECT_TRUE(near_rgba(pixel(8, 8), {64, 191, 0, 255}));
  GLint control = 0;
  glGetIntegerv(GL_LIGHT_MODEL_COLOR_CONTROL, &control);
  EXPECT_EQ(control, GL_SEPARATE_SPECULAR_COLOR);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_LINEAR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

}  // namespace
}  // namespace pineda::test
