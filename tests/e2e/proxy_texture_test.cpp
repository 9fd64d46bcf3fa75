// Proxy textures (GL 1.1 PROXY_TEXTURE_1D/2D): glTexImage on a proxy target records what the
// image would be, or zeros when it is too large, without errors or effects on real textures.
#include "tests/e2e/support/gl_test.h"

#include <GL/glext.h>

namespace pineda::test {
namespace {

class ProxyTextureTest : public GlTest {
 protected:
  GLint level_param(GLenum target, GLenum pname, GLint level = 0) {
    GLint v = -1;
    glGetTexLevelParameteriv(target, level, pname, &v);
    return v;
  }
};

TEST_F(ProxyTextureTest, FittingImageSetsTheProxyState) {
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGB8, 64, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, GL_TEXTURE_WIDTH), 64);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, GL_TEXTURE_HEIGHT), 32);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, GL_TEXTURE_INTERNAL_FORMAT), GL_RGB8);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, GL_TEXTURE_RED_SIZE), 8);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, GL_TEXTURE_ALPHA_SIZE), 0);
  EXPECT_EQ(level_param(GL_TEXTURE_2D, GL_TEXTURE_WIDTH), 0);  // the real texture is untouched
  glTexImage1D(GL_PROXY_TEXTURE_1D, 2, GL_ALPHA, 18, 1, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_1D, GL_TEXTURE_WIDTH, 2), 18);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_1D, GL_TEXTURE_HEIGHT, 2), 1);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_1D, GL_TEXTURE_BORDER, 2), 1);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_1D, GL_TEXTURE_ALPHA_SIZE, 2), 8);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ProxyTextureTest, TooLargeImageZeroesTheProxyWithoutError) {
  GLint max = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, max * 2, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, GL_TEXTURE_WIDTH), 0);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, GL_TEXTURE_HEIGHT), 0);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, GL_TEXTURE_RED_SIZE), 0);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, max, max, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, GL_TEXTURE_WIDTH), max);
}

TEST_F(ProxyTextureTest, LevelsAboveZeroHaveSmallerLimits) {
  GLint max = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 1, GL_RGBA, max / 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, GL_TEXTURE_WIDTH, 1), max / 2);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 1, GL_RGBA, max, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, GL_TEXTURE_WIDTH, 1), 0);
  glBindTexture(GL_TEXTURE_2D, 1);
  glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, max, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexImage1D(GL_TEXTURE_1D, 3, GL_RGBA, max / 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

TEST_F(ProxyTextureTest, ArgumentErrorsStillApply) {
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, -1, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, 77, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexImage1D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glBindTexture(GL_PROXY_TEXTURE_2D, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexParameteri(GL_PROXY_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  const uint8_t texel[4] = {};
  glTexSubImage2D(GL_PROXY_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

struct FormatTypeError {
  GLenum format, type, error;
};

// A packed type the format does not fit is INVALID_OPERATION whatever the format, depth
// included (piglit proxy-texture); an unknown format or type, or BITMAP with a colour format,
// INVALID_ENUM. Each leaves the proxy as it was (as llvmpipe answers each).
TEST_F(ProxyTextureTest, FormatTypeMismatchesAreErrorsThatChangeNothing) {
  const FormatTypeError cases[] = {
      {GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_8_8_8_8, GL_INVALID_OPERATION},
      {GL_STENCIL_INDEX, GL_UNSIGNED_BYTE_3_3_2, GL_INVALID_OPERATION},
      {GL_LUMINANCE, GL_UNSIGNED_SHORT_5_6_5, GL_INVALID_OPERATION},
      {GL_RGBA, GL_UNSIGNED_BYTE_3_3_2, GL_INVALID_OPERATION},
      {GL_BGR, GL_UNSIGNED_SHORT_5_6_5, GL_INVALID_OPERATION},
      {GL_RGBA, GL_BITMAP, GL_INVALID_ENUM},
      {GL_RGBA, 0x1234, GL_INVALID_ENUM},
      {0x1234, GL_UNSIGNED_BYTE, GL_INVALID_ENUM},
  };
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_FLOAT, nullptr);
  for (const FormatTypeError& c : cases) {
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, c.format, c.type, nullptr);
    EXPECT_EQ(glGetError(), c.error) << std::hex << c.format << " " << c.type;
    EXPECT_EQ(level_param(GL_PROXY_TEXTURE_2D, GL_TEXTURE_WIDTH), 8);
    const uint8_t texel[16] = {};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, c.format, c.type, texel);
    EXPECT_EQ(glGetError(), c.error) << std::hex << c.format << " " << c.type;
  }
}

}  // namespace
}  // namespace pineda::test
