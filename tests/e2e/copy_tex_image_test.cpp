// glCopyTexImage and glCopyTexSubImage: texels from the framebuffer.
#include "tests/e2e/support/gl_test.h"

#include <GL/glext.h>

namespace pineda::test {
namespace {

class CopyTexImageTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 1);
    // Four quadrants of distinct colours around (16, 16).
    const GLubyte colours[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
    for (int q = 0; q < 4; ++q) {
      glColor3ubv(colours[q]);
      glRecti(16 * (q % 2), 16 * (q / 2), 16 * (q % 2) + 16, 16 * (q / 2) + 16);
    }
    glBindTexture(GL_TEXTURE_2D, 1);
  }
  std::vector<uint8_t> read(int x, int y, int w, int h) {
    std::vector<uint8_t> out(size_t(w) * h * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(x, y, w, h, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    return out;
  }
  std::vector<uint8_t> texture_image(int w, int h, GLenum target = GL_TEXTURE_2D) {
    std::vector<uint8_t> out(size_t(w) * h * 4, 0xEE);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(target, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    return out;
  }
};

TEST_F(CopyTexImageTest, CopiesTheRegionAcrossQuadrants) {
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 12, 10, 8, 12, 0);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLint w = 0, h = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
  EXPECT_EQ(w, 8);
  EXPECT_EQ(h, 12);
  EXPECT_EQ(texture_image(8, 12), read(12, 10, 8, 12));
}

TEST_F(CopyTexImageTest, CopiedTextureDrawsTheSamePixels) {
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 16, 16, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  const auto source = read(8, 8, 16, 16);
  clear_to(0, 0, 0, 0);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2i(0, 0);
  glTexCoord2f(1, 0);
  glVertex2i(16, 0);
  glTexCoord2f(1, 1);
  glVertex2i(16, 16);
  glTexCoord2f(0, 1);
  glVertex2i(0, 16);
  glEnd();
  EXPECT_EQ(read(0, 0, 16, 16), source);
}

TEST_F(CopyTexImageTest, SubImageReplacesARegion) {
  const std::vector<uint8_t> grey(4 * 4 * 4, 128);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, grey.data());
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 1, 2, 15, 15, 2, 2);  // straddles all four quadrants
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const auto tex = texture_image(4, 4);
  const auto src = read(15, 15, 2, 2);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      for (int c = 0; c < 4; ++c) {
        const bool copied = x >= 1 && x < 3 && y >= 2;
        const int expected = copied ? src[((y - 2) * 2 + (x - 1)) * 4 + c] : 128;
        EXPECT_EQ(tex[(y * 4 + x) * 4 + c], expected) << x << "," << y << "," << c;
      }
}

// Rows that start left of the drawable and end right of it: the pixels inside are copied exactly
// (RGBA with alpha), the ones outside read as zero.
TEST_F(CopyTexImageTest, RowsCrossingTheDrawableEdgesCopyThePixelsInside) {
  const int w = width() + 4, h = 3;
  glColor4ub(10, 20, 30, 40);
  glRecti(0, 14, width(), 17);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -2, 14, w, h, 0);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const auto tex = texture_image(w, h);
  const auto src = read(0, 14, width(), h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 4; ++c) {
        const int fx = x - 2;
        const int expected = fx >= 0 && fx < width() ? src[(y * width() + fx) * 4 + c] : 0;
        ASSERT_EQ(tex[(y * w + x) * 4 + c], expected) << x << "," << y << "," << c;
      }
  EXPECT_EQ(src[0], 10);
  EXPECT_EQ(src[2], 30);
}

TEST_F(CopyTexImageTest, OneDimensional) {
  glBindTexture(GL_TEXTURE_1D, 2);
  glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 12, 3, 8, 0);
  EXPECT_EQ(texture_image(8, 1, GL_TEXTURE_1D), read(12, 3, 8, 1));
  glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 0, 0, 20, 2);
  const auto tex = texture_image(8, 1, GL_TEXTURE_1D);
  const auto src = read(0, 20, 2, 1);
  EXPECT_TRUE(std::equal(src.begin(), src.end(), tex.begin()));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(CopyTexImageTest, Errors) {
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, -1, 4, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glCopyTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 0, 0, 4, 4, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glCopyTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 0, 0, 4, 4, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glCopyTexImage2D(GL_TEXTURE_1D, 0, GL_RGBA, 0, 0, 4, 4, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 100000, 100000, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 2, 2);  // no image defined
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  GLint w = -1;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
  EXPECT_EQ(w, 0);
  glBegin(GL_POINTS);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 0);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

// GL 1.1 3.8.2: "internalformat may not be specified as 1, 2, 3, or 4" (piglit copyteximage).
TEST_F(CopyTexImageTest, OneToFourAreNotInternalFormatsOfCopies) {
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 0);
  for (GLenum format = 1; format <= 4; ++format) {
    glCopyTexImage2D(GL_TEXTURE_2D, 0, format, 0, 0, 2, 2, 0);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM)) << format;
    glCopyTexImage1D(GL_TEXTURE_1D, 0, format, 0, 0, 2, 0);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM)) << format;
  }
  GLint w = 0, internal = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
  EXPECT_EQ(w, 4);  // the image before the failed copies
  EXPECT_EQ(internal, GL_RGBA);
}

// GL 1.3's generic compressed formats are stored uncompressed: the level records the base
// format, as the spec says when the GL chooses no compressed format.
TEST_F(CopyTexImageTest, GenericCompressedFormatsStoreTheirBaseFormat) {
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA, 12, 10, 8, 12, 0);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(texture_image(8, 12), read(12, 10, 8, 12));
  GLint internal = 0, red = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &red);
  EXPECT_EQ(internal, GL_RGBA);
  EXPECT_EQ(red, 8);
  const GLenum generic[6][2] = {{GL_COMPRESSED_ALPHA, GL_ALPHA},
                                {GL_COMPRESSED_LUMINANCE, GL_LUMINANCE},
                                {GL_COMPRESSED_LUMINANCE_ALPHA, GL_LUMINANCE_ALPHA},
                                {GL_COMPRESSED_INTENSITY, GL_INTENSITY},
                                {GL_COMPRESSED_RGB, GL_RGB},
                                {GL_COMPRESSED_RGBA, GL_RGBA}};
  for (const auto& g : generic) {
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(g[0]), 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
    EXPECT_EQ(internal, GLint(g[1]));
  }
}

TEST_F(CopyTexImageTest, KeepsTheApplicationsUnpackState) {
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 50);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 3);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 12, 10, 8, 12, 0);
  EXPECT_EQ(texture_image(8, 12), read(12, 10, 8, 12));
  GLint row_length = 0;
  glGetIntegerv(GL_UNPACK_ROW_LENGTH, &row_length);
  EXPECT_EQ(row_length, 50);
}

}  // namespace
}  // namespace pineda::test
