// GL_COMBINE texture environments (GL 1.3; ARB_texture_env_combine, _crossbar, _dot3):
// every function, source, operand and scale with exact pixel values; queries, errors,
// glPushAttrib.
#include "tests/e2e/support/gl_test.h"

#include <GL/glext.h>

namespace pineda::test {
namespace {

class TexCombineTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
  }

  // A 1x1 texture on `unit`, enabled, with the COMBINE environment.
  void texel(GLenum unit, GLuint name, Rgba c, GLenum internal_format = GL_RGBA) {
    glActiveTexture(unit);
    glBindTexture(GL_TEXTURE_2D, name);
    const uint8_t t[4] = {uint8_t(c[0]), uint8_t(c[1]), uint8_t(c[2]), uint8_t(c[3])};
    glTexImage2D(GL_TEXTURE_2D, 0, internal_format, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
  }
  void env(GLenum pname, GLint value) { glTexEnvi(GL_TEXTURE_ENV, pname, value); }
  void env_color(float r, float g, float b, float a) {
    const float c[4] = {r, g, b, a};
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, c);
  }
  // The colour of a 2x2 square drawn with primary colour `c`.
  Rgba draw(Rgba c) {
    glColor4ub(GLubyte(c[0]), GLubyte(c[1]), GLubyte(c[2]), GLubyte(c[3]));
    glRectf(0, 0, 2, 2);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    return pixel(1, 1);
  }
};

TEST_F(TexCombineTest, DefaultsModulateTextureByPrevious) {
  texel(GL_TEXTURE0, 1, {128, 255, 64, 128});
  EXPECT_TRUE(near_rgba(draw({255, 0, 255, 255}), {128, 0, 64, 128}));
}

TEST_F(TexCombineTest, ReplaceWithConstant) {
  texel(GL_TEXTURE0, 1, {1, 2, 3, 4});
  env(GL_COMBINE_RGB, GL_REPLACE);
  env(GL_COMBINE_ALPHA, GL_REPLACE);
  env(GL_SOURCE0_RGB, GL_CONSTANT);
  env(GL_SOURCE0_ALPHA, GL_CONSTANT);
  env_color(0.2f, 0.4f, 0.6f, 0.8f);
  EXPECT_TRUE(near_rgba(draw({9, 9, 9, 9}), {51, 102, 153, 204}));
}

TEST_F(TexCombineTest, AddClampsToOne) {
  texel(GL_TEXTURE0, 1, {100, 150, 200, 50});
  env(GL_COMBINE_RGB, GL_ADD);
  env(GL_COMBINE_ALPHA, GL_ADD);
  EXPECT_TRUE(near_rgba(draw({100, 150, 100, 100}), {200, 255, 255, 150}));
}

TEST_F(TexCombineTest, AddSignedWithScales) {
  texel(GL_TEXTURE0, 1, {100, 200, 50, 100});
  env(GL_COMBINE_RGB, GL_ADD_SIGNED);
  env(GL_COMBINE_ALPHA, GL_ADD_SIGNED);
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.f);
  glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 4.f);
  // rgb: 2 (a + b - 0.5): 2 (160 - 127.5) = 65; 2 (300 - 127.5) > 255; 2 (80 - 127.5) < 0.
  // alpha: 4 (160 - 127.5) = 130.
  EXPECT_TRUE(near_rgba(draw({60, 100, 30, 60}), {65, 255, 0, 130}));
}

TEST_F(TexCombineTest, InterpolateByConstantAlpha) {
  texel(GL_TEXTURE0, 1, {200, 0, 100, 255});
  env(GL_COMBINE_RGB, GL_INTERPOLATE);
  env_color(0, 0, 0, 0.25f);
  // texture * 0.25 + previous * 0.75; alpha keeps MODULATE (255 * 55).
  EXPECT_TRUE(near_rgba(draw({0, 200, 100, 55}), {50, 150, 100, 55}));
}

TEST_F(TexCombineTest, SubtractClampsAtZero) {
  texel(GL_TEXTURE0, 1, {200, 100, 50, 200});
  env(GL_COMBINE_RGB, GL_SUBTRACT);
  env(GL_COMBINE_ALPHA, GL_SUBTRACT);
  EXPECT_TRUE(near_rgba(draw({50, 150, 25, 100}), {150, 0, 25, 100}));
}

TEST_F(TexCombineTest, Operands) {
  texel(GL_TEXTURE0, 1, {200, 100, 50, 60});
  env(GL_COMBINE_RGB, GL_MODULATE);
  env(GL_OPERAND0_RGB, GL_ONE_MINUS_SRC_COLOR);  // (55, 155, 205)
  env(GL_OPERAND1_RGB, GL_SRC_ALPHA);            // the primary alpha, 255
  env(GL_COMBINE_ALPHA, GL_REPLACE);
  env(GL_OPERAND0_ALPHA, GL_ONE_MINUS_SRC_ALPHA);  // 255 - 60
  EXPECT_TRUE(near_rgba(draw({1, 2, 3, 255}), {55, 155, 205, 195}));
  env(GL_OPERAND0_RGB, GL_SRC_ALPHA);  // 60 replicated
  env(GL_OPERAND1_RGB, GL_ONE_MINUS_SRC_ALPHA);  // 1 - 0 = 1
  EXPECT_TRUE(near_rgba(draw({1, 2, 3, 0}), {60, 60, 60, 195}));
}

TEST_F(TexCombineTest, Dot3RgbAndRgba) {
  texel(GL_TEXTURE0, 1, {192, 128, 128, 200});
  env(GL_COMBINE_RGB, GL_DOT3_RGB);
  // 4 ((192/255 - .5)^2 + 2 (128/255 - .5)^2) = 0.25593 -> 65; alpha: MODULATE 200 x 255.
  EXPECT_TRUE(near_rgba(draw({192, 128, 128, 255}), {65, 65, 65, 200}));
  env(GL_COMBINE_RGB, GL_DOT3_RGBA);  // the alpha function is ignored
  EXPECT_TRUE(near_rgba(draw({192, 128, 128, 255}), {65, 65, 65, 65}));
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.f);  // the ARB extension scales DOT3 results
  EXPECT_TRUE(near_rgba(draw({192, 128, 128, 255}), {131, 131, 131, 131}));
}

TEST_F(TexCombineTest, CrossbarReadsAnotherUnit) {
  texel(GL_TEXTURE0, 1, {10, 20, 30, 40});
  texel(GL_TEXTURE1, 2, {200, 200, 200, 200});
  env(GL_COMBINE_RGB, GL_REPLACE);
  env(GL_SOURCE0_RGB, GL_TEXTURE0);
  env(GL_COMBINE_ALPHA, GL_REPLACE);
  env(GL_SOURCE0_ALPHA, GL_PRIMARY_COLOR);
  // Unit 0 modulates the primary colour; unit 1 takes unit 0's raw texel and the primary alpha.
  EXPECT_TRUE(near_rgba(draw({255, 255, 255, 77}), {10, 20, 30, 77}));
}

TEST_F(TexCombineTest, CrossbarToDisabledUnitLeavesTheFragment) {
  texel(GL_TEXTURE0, 1, {10, 20, 30, 40});
  env(GL_COMBINE_RGB, GL_REPLACE);
  env(GL_SOURCE0_RGB, GL_TEXTURE2);
  EXPECT_TRUE(near_rgba(draw({1, 2, 3, 4}), {1, 2, 3, 4}));
}

TEST_F(TexCombineTest, TextureSourceFollowsTheBaseFormat) {
  texel(GL_TEXTURE0, 1, {100, 150, 200, 50}, GL_ALPHA);
  env(GL_COMBINE_RGB, GL_REPLACE);
  env(GL_COMBINE_ALPHA, GL_REPLACE);
  EXPECT_TRUE(near_rgba(draw({9, 9, 9, 9}), {0, 0, 0, 50}));
  texel(GL_TEXTURE0, 1, {100, 150, 200, 50}, GL_LUMINANCE);
  env(GL_COMBINE_RGB, GL_REPLACE);
  env(GL_COMBINE_ALPHA, GL_REPLACE);
  EXPECT_TRUE(near_rgba(draw({9, 9, 9, 9}), {100, 100, 100, 255}));
}

TEST_F(TexCombineTest, QueriesReturnDefaultsAndSetValues) {
  glActiveTexture(GL_TEXTURE1);
  struct Default { GLenum pname; GLint value; };
  const Default defaults[] = {
      {GL_COMBINE_RGB, GL_MODULATE}, {GL_COMBINE_ALPHA, GL_MODULATE},
      {GL_SOURCE0_RGB, GL_TEXTURE}, {GL_SOURCE1_RGB, GL_PREVIOUS}, {GL_SOURCE2_RGB, GL_CONSTANT},
      {GL_SOURCE0_ALPHA, GL_TEXTURE}, {GL_SOURCE1_ALPHA, GL_PREVIOUS}, {GL_SOURCE2_ALPHA, GL_CONSTANT},
      {GL_OPERAND0_RGB, GL_SRC_COLOR}, {GL_OPERAND1_RGB, GL_SRC_COLOR}, {GL_OPERAND2_RGB, GL_SRC_ALPHA},
      {GL_OPERAND0_ALPHA, GL_SRC_ALPHA}, {GL_OPERAND1_ALPHA, GL_SRC_ALPHA}, {GL_OPERAND2_ALPHA, GL_SRC_ALPHA},
      {GL_RGB_SCALE, 1}, {GL_ALPHA_SCALE, 1}};
  for (const Default& d : defaults) {
    GLint v = -1;
    glGetTexEnviv(GL_TEXTURE_ENV, d.pname, &v);
    EXPECT_EQ(v, d.value) << std::hex << d.pname;
  }
  env(GL_SOURCE2_ALPHA, GL_TEXTURE3);
  env(GL_OPERAND2_RGB, GL_ONE_MINUS_SRC_COLOR);
  glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 4.f);
  GLint v = 0;
  glGetTexEnviv(GL_TEXTURE_ENV, GL_SOURCE2_ALPHA, &v);
  EXPECT_EQ(v, GL_TEXTURE3);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_OPERAND2_RGB, &v);
  EXPECT_EQ(v, GL_ONE_MINUS_SRC_COLOR);
  float f = 0;
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_ALPHA_SCALE, &f);
  EXPECT_EQ(f, 4.f);
  glActiveTexture(GL_TEXTURE0);  // other units keep their defaults
  glGetTexEnviv(GL_TEXTURE_ENV, GL_SOURCE2_ALPHA, &v);
  EXPECT_EQ(v, GL_CONSTANT);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(TexCombineTest, InvalidValuesAreRejectedAndChangeNothing) {
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 3.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  env(GL_COMBINE_ALPHA, GL_DOT3_RGB);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  env(GL_OPERAND0_ALPHA, GL_SRC_COLOR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  env(GL_SOURCE0_RGB, GL_TEXTURE4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  env(GL_COMBINE_RGB, GL_DECAL);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexEnvi(GL_TEXTURE_2D, GL_COMBINE_RGB, GL_ADD);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLint v = 0;
  glGetTexEnviv(GL_TEXTURE_ENV, GL_RGB_SCALE, &v);
  EXPECT_EQ(v, 1);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, &v);
  EXPECT_EQ(v, GL_MODULATE);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, &v);
  EXPECT_EQ(v, GL_SRC_ALPHA);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_SOURCE0_RGB, &v);
  EXPECT_EQ(v, GL_TEXTURE);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_COMBINE_RGB, &v);
  EXPECT_EQ(v, GL_MODULATE);
}

TEST_F(TexCombineTest, PushAttribRestoresCombineState) {
  glPushAttrib(GL_TEXTURE_BIT);
  env(GL_TEXTURE_ENV_MODE, GL_COMBINE);
  env(GL_COMBINE_RGB, GL_DOT3_RGBA);
  glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.f);
  glPopAttrib();
  GLint v = 0;
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
  EXPECT_EQ(v, GL_MODULATE);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_COMBINE_RGB, &v);
  EXPECT_EQ(v, GL_MODULATE);
  glGetTexEnviv(GL_TEXTURE_ENV, GL_RGB_SCALE, &v);
  EXPECT_EQ(v, 1);
}

TEST_F(TexCombineTest, CompiledIntoDisplayLists) {
  texel(GL_TEXTURE0, 1, {100, 150, 200, 50});
  glNewList(1, GL_COMPILE);
  env(GL_COMBINE_RGB, GL_REPLACE);
  env(GL_SOURCE0_RGB, GL_PRIMARY_COLOR);
  glEndList();
  GLint v = 0;
  glGetTexEnviv(GL_TEXTURE_ENV, GL_COMBINE_RGB, &v);
  EXPECT_EQ(v, GL_MODULATE);
  glCallList(1);
  EXPECT_TRUE(near_rgba(draw({7, 8, 9, 255}), {7, 8, 9, 50}));
}

}  // namespace
}  // namespace pineda::test
