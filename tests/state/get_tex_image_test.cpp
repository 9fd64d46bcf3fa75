// glGetTexImage: levels read back through the pack pixel store.
#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class GetTexImageTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    glBindTexture(GL_TEXTURE_2D, 1);
  }
};

TEST_F(GetTexImageTest, RgbaRoundTripsExactly) {
  std::vector<uint8_t> image(3 * 2 * 4);
  for (size_t i = 0; i < image.size(); ++i) image[i] = uint8_t(i * 11 + 3);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 3, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  std::vector<uint8_t> out(image.size() + 8, 0xEE);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  EXPECT_TRUE(std::equal(image.begin(), image.end(), out.begin()));
  EXPECT_EQ(out[image.size()], 0xEE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(GetTexImageTest, FormatsTypesAndPackAlignment) {
  const uint8_t image[2 * 2 * 4] = {10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120, 130, 140, 150, 160};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, image);
  // BGR bytes: 6 per row, padded to 8 by the default alignment of 4.
  uint8_t bgr[16];
  std::fill(bgr, bgr + 16, 0xEE);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_BGR, GL_UNSIGNED_BYTE, bgr);
  const uint8_t expected[16] = {30, 20, 10, 70, 60, 50, 0xEE, 0xEE, 110, 100, 90, 150, 140, 130, 0xEE, 0xEE};
  for (int i = 0; i < 14; ++i) EXPECT_EQ(bgr[i], expected[i]) << i;
  GLfloat alpha[4];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_ALPHA, GL_FLOAT, alpha);
  EXPECT_FLOAT_EQ(alpha[0], 40 / 255.f);
  EXPECT_FLOAT_EQ(alpha[3], 160 / 255.f);
  GLushort red[4];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RED, GL_UNSIGNED_SHORT, red);
  EXPECT_EQ(red[1], 50 * 257);
}

TEST_F(GetTexImageTest, LuminanceAndIntensityReturnInRed) {
  const uint8_t la[2 * 2] = {200, 100, 50, 25};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);  // rows of 2 bytes
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 1, 2, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, la);
  uint8_t out[2 * 4];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  const uint8_t expected[8] = {200, 0, 0, 100, 50, 0, 0, 25};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(out[i], expected[i]) << i;
  uint8_t lum[2] = {0, 0};
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
  EXPECT_EQ(lum[0], 200);
  EXPECT_EQ(lum[1], 50);
  const uint8_t i8 = 77;
  glTexImage2D(GL_TEXTURE_2D, 1, GL_INTENSITY, 1, 1, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, &i8);
  uint8_t rgba[4];
  glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  EXPECT_EQ(rgba[0], 77);
  EXPECT_EQ(rgba[1], 0);
  EXPECT_EQ(rgba[2], 0);
  EXPECT_EQ(rgba[3], 255);
}

TEST_F(GetTexImageTest, OneDimensionalAndErrors) {
  const uint8_t rgb[3 * 3] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  glBindTexture(GL_TEXTURE_1D, 2);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 3, 0, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  uint8_t out[3 * 4];
  glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(out[4], 4);
  EXPECT_EQ(out[7], 255);
  uint8_t untouched[4] = {9, 9, 9, 9};
  glGetTexImage(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, GL_UNSIGNED_BYTE, untouched);  // faces only
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetTexImage(GL_TEXTURE_1D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, untouched);  // depth of a colour texture
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_BITMAP, untouched);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetTexImage(GL_TEXTURE_1D, -1, GL_RGBA, GL_UNSIGNED_BYTE, untouched);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glGetTexImage(GL_TEXTURE_1D, 40, GL_RGBA, GL_UNSIGNED_BYTE, untouched);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glGetTexImage(GL_TEXTURE_1D, 3, GL_RGBA, GL_UNSIGNED_BYTE, untouched);  // undefined level: nothing written
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  for (uint8_t v : untouched) EXPECT_EQ(v, 9);
  glBegin(GL_POINTS);
  glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, untouched);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  for (uint8_t v : untouched) EXPECT_EQ(v, 9);
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

TEST_F(GetTexImageTest, UnpackSwapBytes) {
  // 0x1234 is stored byte-swapped as 0x3412 in client memory.
  const GLushort rgba[4] = {0x3412, 0xFFFF, 0x0000, 0x00FF};
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_SHORT, rgba);
  GLushort out[4];
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_SHORT, out);
  EXPECT_EQ(out[0], 0x1212);  // 0x1234 / 65535 kept as the byte 0x12, read back as 0x12 * 257
  EXPECT_EQ(out[1], 0xFFFF);
  EXPECT_EQ(out[2], 0);
  EXPECT_EQ(out[3], 254 * 257);  // 0xFF00 / 65535 * 255 = 254.01: kept as the byte 254
}

}  // namespace
}  // namespace pineda::test
