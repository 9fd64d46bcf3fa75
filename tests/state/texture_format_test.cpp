// Texture internal formats: the component sizes glGetTexLevelParameter reports for every GL
// 1.x internal format (Mesa's, with 8 where Mesa keeps more: Pineda stores RGBA8), and texels
// quantized to those sizes.
#include "tests/e2e/support/gl_test.h"

#include <GL/glext.h>

namespace pineda::test {
namespace {

// red, green, blue, alpha, luminance, intensity, depth
using Sizes = std::array<GLint, 7>;

struct FormatCase {
  GLint internal_format;
  Sizes sizes;
};

class TextureFormatTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    glBindTexture(GL_TEXTURE_2D, 1);
  }
  Sizes sizes(GLenum target = GL_TEXTURE_2D) {
    static constexpr GLenum kQueries[7] = {GL_TEXTURE_RED_SIZE,       GL_TEXTURE_GREEN_SIZE,     GL_TEXTURE_BLUE_SIZE,
                                           GL_TEXTURE_ALPHA_SIZE,     GL_TEXTURE_LUMINANCE_SIZE, GL_TEXTURE_INTENSITY_SIZE,
                                           GL_TEXTURE_DEPTH_SIZE};
    Sizes out;
    for (int i = 0; i < 7; ++i) {
      out[i] = -1;
      glGetTexLevelParameteriv(target, 0, kQueries[i], &out[i]);
    }
    return out;
  }
  // A 1x1 texture of `internal_format` from a float RGBA pixel, read back as RGBA bytes.
  Rgba stored(GLint internal_format, const float rgba[4]) {
    glTexImage2D(GL_TEXTURE_2D, 0, internal_format, 1, 1, 0, GL_RGBA, GL_FLOAT, rgba);
    uint8_t p[4] = {0, 0, 0, 0};
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, p);
    return {p[0], p[1], p[2], p[3]};
  }
};

const FormatCase kFormats[] = {
    {1, {0, 0, 0, 0, 8, 0, 0}},
    {2, {0, 0, 0, 8, 8, 0, 0}},
    {3, {8, 8, 8, 0, 0, 0, 0}},
    {4, {8, 8, 8, 8, 0, 0, 0}},
    {GL_ALPHA, {0, 0, 0, 8, 0, 0, 0}},
    {GL_ALPHA4, {0, 0, 0, 8, 0, 0, 0}},
    {GL_ALPHA8, {0, 0, 0, 8, 0, 0, 0}},
    {GL_ALPHA12, {0, 0, 0, 8, 0, 0, 0}},
    {GL_ALPHA16, {0, 0, 0, 8, 0, 0, 0}},
    {GL_LUMINANCE, {0, 0, 0, 0, 8, 0, 0}},
    {GL_LUMINANCE4, {0, 0, 0, 0, 8, 0, 0}},
    {GL_LUMINANCE8, {0, 0, 0, 0, 8, 0, 0}},
    {GL_LUMINANCE12, {0, 0, 0, 0, 8, 0, 0}},
    {GL_LUMINANCE16, {0, 0, 0, 0, 8, 0, 0}},
    {GL_LUMINANCE_ALPHA, {0, 0, 0, 8, 8, 0, 0}},
    {GL_LUMINANCE4_ALPHA4, {0, 0, 0, 4, 4, 0, 0}},
    {GL_LUMINANCE6_ALPHA2, {0, 0, 0, 8, 8, 0, 0}},
    {GL_LUMINANCE8_ALPHA8, {0, 0, 0, 8, 8, 0, 0}},
    {GL_LUMINANCE12_ALPHA4, {0, 0, 0, 8, 8, 0, 0}},
    {GL_LUMINANCE12_ALPHA12, {0, 0, 0, 8, 8, 0, 0}},
    {GL_LUMINANCE16_ALPHA16, {0, 0, 0, 8, 8, 0, 0}},
    {GL_INTENSITY, {0, 0, 0, 0, 0, 8, 0}},
    {GL_INTENSITY4, {0, 0, 0, 0, 0, 8, 0}},
    {GL_INTENSITY8, {0, 0, 0, 0, 0, 8, 0}},
    {GL_INTENSITY12, {0, 0, 0, 0, 0, 8, 0}},
    {GL_INTENSITY16, {0, 0, 0, 0, 0, 8, 0}},
    {GL_RGB, {8, 8, 8, 0, 0, 0, 0}},
    {GL_R3_G3_B2, {3, 3, 2, 0, 0, 0, 0}},
    {GL_RGB4, {4, 4, 4, 0, 0, 0, 0}},
    {GL_RGB5, {5, 5, 5, 0, 0, 0, 0}},
    {GL_RGB8, {8, 8, 8, 0, 0, 0, 0}},
    {GL_RGB10, {8, 8, 8, 0, 0, 0, 0}},
    {GL_RGB12, {8, 8, 8, 0, 0, 0, 0}},
    {GL_RGB16, {8, 8, 8, 0, 0, 0, 0}},
    {GL_RGBA, {8, 8, 8, 8, 0, 0, 0}},
    {GL_RGBA2, {4, 4, 4, 4, 0, 0, 0}},
    {GL_RGBA4, {4, 4, 4, 4, 0, 0, 0}},
    {GL_RGB5_A1, {5, 5, 5, 1, 0, 0, 0}},
    {GL_RGBA8, {8, 8, 8, 8, 0, 0, 0}},
    {GL_RGB10_A2, {8, 8, 8, 2, 0, 0, 0}},
    {GL_RGBA12, {8, 8, 8, 8, 0, 0, 0}},
    {GL_RGBA16, {8, 8, 8, 8, 0, 0, 0}},
};

TEST_F(TextureFormatTest, EveryFormatReportsItsStoredSizesAndItself) {
  for (const FormatCase& f : kFormats) {
    glTexImage2D(GL_TEXTURE_2D, 0, f.internal_format, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << std::hex << f.internal_format;
    EXPECT_EQ(sizes(), f.sizes) << std::hex << f.internal_format;
    GLint internal = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
    EXPECT_EQ(internal, f.internal_format);
  }
}

TEST_F(TextureFormatTest, ProxyLevelsReportTheSameSizes) {
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGB5_A1, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(sizes(GL_PROXY_TEXTURE_2D), (Sizes{5, 5, 5, 1, 0, 0, 0}));
}

// Mesa answers depth and stencil sizes (0 for colour formats) without an error; piglit's
// sized-texture-format-channels reads them.
TEST_F(TextureFormatTest, DepthAndStencilSizesOfColourFormatsAreZero) {
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  GLint depth = -1, stencil = -1;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &depth);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE, &stencil);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(depth, 0);
  EXPECT_EQ(stencil, 0);
}

// Values as llvmpipe stores them (probed with glGetTexImage): 0.3 * 15 = 4.5 rounds to 5 (x17
// = 85); 0.3 * 255 = 76.5 rounds to 76 (ties to even, as Mesa's float_to_ubyte).
TEST_F(TextureFormatTest, TexelsAreQuantizedToTheReportedBits) {
  const float c[4] = {0.3f, 0.55f, 0.8f, 0.123f};
  EXPECT_EQ(stored(GL_RGBA8, c), (Rgba{76, 140, 204, 31}));
  EXPECT_EQ(stored(GL_RGBA4, c), (Rgba{85, 136, 204, 34}));   // 5, 8, 12, 2 of 15
  EXPECT_EQ(stored(GL_RGBA2, c), (Rgba{85, 136, 204, 34}));   // stored as RGBA4
  EXPECT_EQ(stored(GL_RGB5_A1, c), (Rgba{74, 140, 206, 0}));  // 9, 17, 25 of 31; alpha 0 of 1
  EXPECT_EQ(stored(GL_R3_G3_B2, c), (Rgba{73, 146, 170, 255}));  // 2, 4 of 7; 2 of 3
  EXPECT_EQ(stored(GL_RGB10_A2, c), (Rgba{76, 140, 204, 0}));    // alpha 0.369 of 3 -> 0
  const float high_alpha[4] = {0.3f, 0.f, 0.f, 0.9f};
  EXPECT_EQ(stored(GL_RGB10_A2, high_alpha), (Rgba{76, 0, 0, 255}));  // 2.7 of 3 -> 3
  EXPECT_EQ(stored(GL_LUMINANCE4_ALPHA4, c), (Rgba{85, 0, 0, 34}));
  EXPECT_EQ(stored(GL_RGB16, c), (Rgba{76, 140, 204, 255}));
}

// Generated mipmaps keep the base level's bits: the average of 0 and 15 (of 15) in RGBA4 is
// 7.5/15, stored as 8/15 = 136 rather than the 8-bit average 128.
TEST_F(TextureFormatTest, GeneratedLevelsAreQuantizedToo) {
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  const uint8_t texels[2 * 4] = {0, 0, 0, 0, 255, 255, 255, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA4, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  uint8_t p[4] = {0, 0, 0, 0};
  glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  EXPECT_EQ((Rgba{p[0], p[1], p[2], p[3]}), (Rgba{136, 136, 136, 136}));
}

}  // namespace
}  // namespace pineda::test
