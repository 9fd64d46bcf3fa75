// Level-of-detail controls: TEXTURE_BASE_LEVEL/MAX_LEVEL (and completeness with them),
// TEXTURE_MIN_LOD/MAX_LOD, the texture's and the unit's LOD bias, GL_GENERATE_MIPMAP;
// queries, errors, glPushAttrib.
#include "tests/e2e/support/gl_test.h"

#include <GL/glext.h>

namespace pineda::test {
namespace {

constexpr Rgba kRed{255, 0, 0, 255}, kGreen{0, 255, 0, 255}, kBlue{0, 0, 255, 255}, kWhite{255, 255, 255, 255};

class TextureLodTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
    glBindTexture(GL_TEXTURE_2D, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  }
  void level(int l, int size, Rgba c) {
    std::vector<uint8_t> texels;
    for (int i = 0; i < size * size; ++i)
      for (int k = 0; k < 4; ++k) texels.push_back(uint8_t(c[k]));
    glTexImage2D(GL_TEXTURE_2D, l, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  }
  // Level 0: 4x4 red, 1: 2x2 green, 2: 1x1 blue.
  void three_levels() {
    level(0, 4, kRed);
    level(1, 2, kGreen);
    level(2, 1, kBlue);
  }
  // The whole texture on a size x size square at the origin (size 4: lambda 0, size 1: lambda 2).
  Rgba draw(int size) {
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex2i(0, 0);
    glTexCoord2f(1, 0);
    glVertex2i(size, 0);
    glTexCoord2f(1, 1);
    glVertex2i(size, size);
    glTexCoord2f(0, 1);
    glVertex2i(0, size);
    glEnd();
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    return pixel(0, 0);
  }
};

TEST_F(TextureLodTest, LevelsFollowLambda) {
  three_levels();
  EXPECT_TRUE(near_rgba(draw(4), kRed));
  EXPECT_TRUE(near_rgba(draw(1), kBlue));
}

TEST_F(TextureLodTest, BaseLevelIsTheLargestLevelUsed) {
  three_levels();
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
  EXPECT_TRUE(near_rgba(draw(4), kGreen));  // lambda is relative to the 2x2 base: -1
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 2);
  EXPECT_TRUE(near_rgba(draw(4), kBlue));
}

TEST_F(TextureLodTest, MaxLevelCompletesAShortChain) {
  level(0, 4, kRed);
  level(1, 2, kGreen);
  glColor4ub(255, 255, 255, 255);
  EXPECT_TRUE(near_rgba(draw(1), kWhite));  // incomplete: no 1x1 level, texturing is off
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1);
  EXPECT_TRUE(near_rgba(draw(1), kGreen));  // lambda 2 uses the last level
}

TEST_F(TextureLodTest, BaseAboveMaxLevelIsIncomplete) {
  three_levels();
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 2);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1);
  glColor4ub(255, 255, 255, 255);
  EXPECT_TRUE(near_rgba(draw(4), kWhite));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // no mipmaps: the base level alone
  EXPECT_TRUE(near_rgba(draw(4), kBlue));
}

TEST_F(TextureLodTest, UndefinedBaseLevelIsIncomplete) {
  three_levels();
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 5);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glColor4ub(255, 255, 255, 255);
  EXPECT_TRUE(near_rgba(draw(4), kWhite));
}

TEST_F(TextureLodTest, MinAndMaxLodClampLambda) {
  three_levels();
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 1.f);
  EXPECT_TRUE(near_rgba(draw(4), kGreen));  // lambda 0 raised to 1: minification, level 1
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, -1000.f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 1.f);
  EXPECT_TRUE(near_rgba(draw(1), kGreen));  // lambda 2 lowered to 1
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 0.f);
  EXPECT_TRUE(near_rgba(draw(1), kRed));
}

TEST_F(TextureLodTest, TextureAndUnitBiasesAdd) {
  three_levels();
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 1.f);
  EXPECT_TRUE(near_rgba(draw(4), kGreen));
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 1.f);
  EXPECT_TRUE(near_rgba(draw(4), kBlue));
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, -1.f);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -1.f);
  EXPECT_TRUE(near_rgba(draw(1), kRed));  // 2 - 2
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -100.f);  // clamped to -16
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 1.f);
  EXPECT_TRUE(near_rgba(draw(1), kGreen));
  float bias = 0;
  glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &bias);
  EXPECT_EQ(bias, -100.f);
  glGetFloatv(GL_MAX_TEXTURE_LOD_BIAS, &bias);
  EXPECT_EQ(bias, 16.f);
}

TEST_F(TextureLodTest, GenerateMipmapBuildsTheChainFromTheBaseLevel) {
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  // Red channel of the 2x2 level: 0, 255, 255, 255 -> (765 + 2) / 4 = 191.
  const uint8_t texels[16] = {0, 10, 0, 255, 255, 20, 0, 255, 255, 30, 0, 255, 255, 40, 1, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  GLint width = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_WIDTH, &width);
  EXPECT_EQ(width, 1);
  uint8_t out[4] = {};
  glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_TRUE(near_rgba({out[0], out[1], out[2], out[3]}, {191, 25, 0, 255}));  // 102/4 = 25.5 -> 25
  EXPECT_TRUE(near_rgba(draw(1), {191, 25, 0, 255}));
  const uint8_t white[4] = {255, 255, 255, 255};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
  glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_TRUE(near_rgba({out[0], out[1], out[2], out[3]}, {255, 86, 64, 255}));  // (345+2)/4, (256+2)/4
}

TEST_F(TextureLodTest, GenerateMipmapOffLeavesOtherLevels) {
  three_levels();
  level(0, 4, kWhite);
  uint8_t out[16] = {};  // level 1 of the 4x4 texture is 2x2
  glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_TRUE(near_rgba({out[0], out[1], out[2], out[3]}, kGreen));
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  level(1, 2, kRed);  // not the base level: nothing is generated
  glGetTexImage(GL_TEXTURE_2D, 2, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_TRUE(near_rgba({out[0], out[1], out[2], out[3]}, kBlue));
}

TEST_F(TextureLodTest, QueriesDefaultsAndErrors) {
  struct Default { GLenum pname; float value; };
  const Default defaults[] = {{GL_TEXTURE_MIN_LOD, -1000.f}, {GL_TEXTURE_MAX_LOD, 1000.f}, {GL_TEXTURE_BASE_LEVEL, 0.f},
                              {GL_TEXTURE_MAX_LEVEL, 1000.f}, {GL_TEXTURE_LOD_BIAS, 0.f}, {GL_GENERATE_MIPMAP, 0.f}};
  glBindTexture(GL_TEXTURE_2D, 2);
  for (const Default& d : defaults) {
    float v = -1;
    glGetTexParameterfv(GL_TEXTURE_2D, d.pname, &v);
    EXPECT_EQ(v, d.value) << std::hex << d.pname;
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, -1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, -0.5f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 5);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_LOD_BIAS, 1.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLint v = -1;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 3);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, &v);
  EXPECT_EQ(v, 3);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, &v);
  EXPECT_EQ(v, GL_TRUE);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, &v);
  EXPECT_EQ(v, 0);
}

TEST_F(TextureLodTest, PushAttribRestoresLodState) {
  glPushAttrib(GL_TEXTURE_BIT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 2);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 3.f);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 2.f);
  glPopAttrib();
  GLint v = -1;
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, &v);
  EXPECT_EQ(v, 0);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, &v);
  EXPECT_EQ(v, GL_FALSE);
  float f = 0;
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, &f);
  EXPECT_EQ(f, -1000.f);
  glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &f);
  EXPECT_EQ(f, 0.f);
}

}  // namespace
}  // namespace pineda::test
