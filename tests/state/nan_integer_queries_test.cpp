// Integer queries of float state that GL stores as given, NaN among it: NaN reads as 0 and
// values beyond GLint are clamped, never converted with undefined behaviour. The API fuzzer
// found each of these (UBSan); its inputs are seeds in tests/fuzz/corpus/api/.
#include <cmath>
#include <limits>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

using NanIntegerQueriesTest = GlTest;

TEST_F(NanIntegerQueriesTest, TexGenPlane) {
  const GLfloat plane[4] = {kNaN, 1e30f, -1e30f, 2.5f};
  glTexGenfv(GL_S, GL_OBJECT_PLANE, plane);
  GLint v[4] = {1, 1, 1, 1};
  glGetTexGeniv(GL_S, GL_OBJECT_PLANE, v);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(v[0], 0);
  EXPECT_EQ(v[1], 2147483647);
  EXPECT_EQ(v[2], -2147483647 - 1);
  EXPECT_EQ(v[3], 3);  // rounded
}

// The following were found by reading the code after the fuzzer's findings above, not by it.
TEST_F(NanIntegerQueriesTest, LightParameters) {
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, kNaN);
  glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, kNaN);
  const GLfloat ambient[4] = {kNaN, 0.5f, 2.f, -1.f};
  glLightfv(GL_LIGHT0, GL_AMBIENT, ambient);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLint v[4] = {1, 1, 1, 1};
  glGetLightiv(GL_LIGHT0, GL_SPOT_EXPONENT, v);
  EXPECT_EQ(v[0], 0);
  glGetLightiv(GL_LIGHT0, GL_CONSTANT_ATTENUATION, v);
  EXPECT_EQ(v[0], 0);
  glGetLightiv(GL_LIGHT0, GL_AMBIENT, v);
  EXPECT_EQ(v[0], 0);
  EXPECT_EQ(v[1], 1073741823);  // 0.5 of the int range
  EXPECT_EQ(v[2], 2147483647);  // clamped to 1
  EXPECT_EQ(v[3], -2147483647);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(NanIntegerQueriesTest, MaterialShininessAndColour) {
  const GLfloat diffuse[4] = {kNaN, 0.f, 0.f, 1.f};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialf(GL_FRONT, GL_SHININESS, kNaN);
  GLint v[4] = {1, 1, 1, 1};
  glGetMaterialiv(GL_FRONT, GL_DIFFUSE, v);
  EXPECT_EQ(v[0], 0);
  EXPECT_EQ(v[3], 2147483647);
  glGetMaterialiv(GL_FRONT, GL_SHININESS, v);
  EXPECT_EQ(v[0], 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(NanIntegerQueriesTest, TexEnvLodBiasAndColour) {
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, kNaN);
  GLint v[4] = {1, 1, 1, 1};
  glGetTexEnviv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, v);
  EXPECT_EQ(v[0], 0);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 1e30f);
  glGetTexEnviv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, v);
  EXPECT_EQ(v[0], 2147483647);
  const GLfloat colour[4] = {kNaN, 1.f, 0.f, 0.f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, colour);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, v);
  EXPECT_EQ(v[0], 0);
  EXPECT_EQ(v[1], 2147483647);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(NanIntegerQueriesTest, TextureBorderColour) {
  const GLfloat colour[4] = {kNaN, 1.f, 0.f, 0.f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, colour);
  GLint v[4] = {1, 1, 1, 1};
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, v);
  EXPECT_EQ(v[0], 0);
  EXPECT_EQ(v[1], 2147483647);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Found by reading the code after the fuzzer's new glGetPixelMapuiv/usv entries: an index map
// holds its values as given, so a NaN index converted to GLuint or GLushort.
TEST_F(NanIntegerQueriesTest, PixelMaps) {
  const GLfloat indices[2] = {kNaN, 1e30f};
  glPixelMapfv(GL_PIXEL_MAP_I_TO_I, 2, indices);
  GLuint ui[2] = {1, 1};
  glGetPixelMapuiv(GL_PIXEL_MAP_I_TO_I, ui);
  EXPECT_EQ(ui[0], 0u);
  EXPECT_EQ(ui[1], 4294967295u);
  GLushort us[2] = {1, 1};
  glGetPixelMapusv(GL_PIXEL_MAP_I_TO_I, us);
  EXPECT_EQ(us[0], 0);
  EXPECT_EQ(us[1], 65535);
  GLfloat f[2] = {1, 1};
  glGetPixelMapfv(GL_PIXEL_MAP_I_TO_I, f);
  EXPECT_TRUE(std::isnan(f[0]));  // the float query returns the value as given
  const GLfloat colours[2] = {kNaN, 0.5f};
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 2, colours);
  glGetPixelMapuiv(GL_PIXEL_MAP_I_TO_R, ui);
  EXPECT_EQ(ui[0], 0u);
  EXPECT_EQ(ui[1], 2147483648u);  // 0.5 of the range, rounded
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
