// Texture images in every GL 1.2 pixel type and format: packed types and their _REV forms,
// BGR and BGRA, the unpack state (SWAP_BYTES, ROW_LENGTH, SKIP_*, ALIGNMENT), read back
// with glGetTexImage; format/type mismatches.
#include <cstring>

#include "tests/e2e/support/gl_test.h"

#include <GL/glext.h>

namespace pineda::test {
namespace {

class PixelTypesTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    glBindTexture(GL_TEXTURE_2D, 1);
  }
  // A 1x1 RGBA8 texture from one client pixel, read back as RGBA bytes.
  Rgba upload(GLenum format, GLenum type, const void* pixel) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, format, type, pixel);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << std::hex << format << " " << type;
    return read_back();
  }
  Rgba read_back(int x = 0, int y = 0, int width = 1) {
    std::vector<uint8_t> out(size_t(width) * 16 * 4, 0);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    const uint8_t* p = out.data() + (size_t(y) * width + x) * 4;
    return {p[0], p[1], p[2], p[3]};
  }
};

struct PackedCase {
  GLenum format, type;
  uint32_t value;  // the client pixel as an integer of the type's size
  Rgba expected;
};

TEST_F(PixelTypesTest, EveryPackedTypeUnpacksItsBitFields) {
  const PackedCase cases[] = {
      {GL_RGB, GL_UNSIGNED_BYTE_3_3_2, 0xAB, {182, 73, 255, 255}},       // 5/7, 2/7, 3/3
      {GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV, 0xAB, {109, 182, 170, 255}},  // 3/7, 5/7, 2/3
      {GL_RGB, GL_UNSIGNED_SHORT_5_6_5, 0xF801, {255, 0, 8, 255}},
      {GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV, 0xF801, {8, 0, 255, 255}},
      {GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, 0x1234, {17, 34, 51, 68}},
      {GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4_REV, 0x1234, {68, 51, 34, 17}},
      {GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4, 0x1234, {51, 34, 17, 68}},
      {GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4_REV, 0x1234, {34, 51, 68, 17}},
      {GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, 0xF801, {255, 0, 0, 255}},
      {GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, 0x07C0, {0, 255, 0, 0}},
      {GL_RGBA, GL_UNSIGNED_SHORT_1_5_5_5_REV, 0x8001, {8, 0, 0, 255}},
      {GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV, 0x001F, {0, 0, 255, 0}},
      {GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, 0x11223344, {17, 34, 51, 68}},
      {GL_RGBA, GL_UNSIGNED_INT_8_8_8_8_REV, 0x11223344, {68, 51, 34, 17}},
      {GL_BGRA, GL_UNSIGNED_INT_8_8_8_8, 0x11223344, {51, 34, 17, 68}},
      {GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, 0x11223344, {34, 51, 68, 17}},
      {GL_RGBA, GL_UNSIGNED_INT_10_10_10_2, 0xFFC00801, {255, 0, 128, 85}},   // 1023, 0, 512, 1
      {GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, 0x800FFE00, {128, 255, 0, 170}},  // 512, 1023, 0, 2
      {GL_BGRA, GL_UNSIGNED_INT_2_10_10_10_REV, 0x800FFE00, {0, 255, 128, 170}},
  };
  for (const PackedCase& c : cases) {
    uint8_t pixel[4];
    std::memcpy(pixel, &c.value, 4);  // little-endian: a byte or short type reads the low bytes
    EXPECT_TRUE(near_rgba(upload(c.format, c.type, pixel), c.expected)) << std::hex << c.format << " " << c.type;
  }
}

TEST_F(PixelTypesTest, BgrAndBgraSwapRedAndBlue) {
  const uint8_t bgr[3] = {10, 20, 30};
  EXPECT_TRUE(near_rgba(upload(GL_BGR, GL_UNSIGNED_BYTE, bgr), {30, 20, 10, 255}));
  const uint8_t bgra[4] = {10, 20, 30, 40};
  EXPECT_TRUE(near_rgba(upload(GL_BGRA, GL_UNSIGNED_BYTE, bgra), {30, 20, 10, 40}));
  const float bgra_f[4] = {0.f, 0.2f, 1.f, 0.6f};
  EXPECT_TRUE(near_rgba(upload(GL_BGRA, GL_FLOAT, bgra_f), {255, 51, 0, 153}));
}

TEST_F(PixelTypesTest, SwapBytesReversesPackedElementsAndComponents) {
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  const uint8_t big_endian_565[2] = {0xF8, 0x01};
  EXPECT_TRUE(near_rgba(upload(GL_RGB, GL_UNSIGNED_SHORT_5_6_5, big_endian_565), {255, 0, 8, 255}));
  const uint8_t big_endian_8888[4] = {0x11, 0x22, 0x33, 0x44};  // 0x11223344
  EXPECT_TRUE(near_rgba(upload(GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, big_endian_8888), {17, 34, 51, 68}));
  const uint8_t big_endian_shorts[8] = {0xFF, 0xFF, 0x00, 0x00, 0x80, 0x00, 0x00, 0xFF};  // 65535, 0, 32768, 255
  EXPECT_TRUE(near_rgba(upload(GL_RGBA, GL_UNSIGNED_SHORT, big_endian_shorts), {255, 0, 128, 1}));
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
}

TEST_F(PixelTypesTest, UnpackRowLengthSkipsAndAlignment) {
  // RGB bytes, rows of 2 pixels (6 bytes) padded to 8; the 1x2 texture starts at (1, 2).
  std::vector<uint8_t> image(8 * 4, 0);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 2; ++x) {
      uint8_t* p = image.data() + 8 * y + 3 * x;
      if (x == 0) continue;
      p[0] = uint8_t(10 * y + x);
      p[1] = 100;
      p[2] = 200;
    }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 2);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 1, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, image.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_TRUE(near_rgba(read_back(0, 0), {21, 100, 200, 255}));
  EXPECT_TRUE(near_rgba(read_back(0, 1), {31, 100, 200, 255}));
}

TEST_F(PixelTypesTest, GetTexImagePacksPackedTypes) {
  const uint8_t texel[4] = {17, 34, 51, 68};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  uint16_t v16 = 0;
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, &v16);
  EXPECT_EQ(v16, 0x1234);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4_REV, &v16);
  EXPECT_EQ(v16, 0x4123);  // A R G B from the top
  uint32_t v32 = 0;
  glGetTexImage(GL_TEXTURE_2D, 0, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, &v32);
  EXPECT_EQ(v32, 0x44112233u);
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, &v32);
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
  EXPECT_EQ(v32, 0x44332211u);
  uint8_t v8 = 0;
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_BYTE_3_3_2, &v8);
  EXPECT_EQ(v8, (0 << 5) | (1 << 2) | 1);  // 17/255*7 = 0.47 -> 0, 34/255*7 = 0.93 -> 1, 51/255*3 = 0.6 -> 1
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(PixelTypesTest, GetTexImageLuminanceIsRedAlone) {
  const uint8_t texel[4] = {128, 200, 100, 60};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  uint8_t out[2] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(out[0], 128);
  EXPECT_EQ(out[1], 60);
}

TEST_F(PixelTypesTest, PackedTypesNeedAMatchingFormat) {
  const uint32_t pixel = 0;
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, &pixel);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_BGR, GL_UNSIGNED_BYTE_3_3_2, &pixel);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGB, GL_UNSIGNED_INT_8_8_8_8, &pixel);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_LUMINANCE, GL_UNSIGNED_SHORT_4_4_4_4, &pixel);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8 + 100, &pixel);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLint width = -1;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
  EXPECT_EQ(width, 0);  // nothing was defined
  uint32_t out = 0;
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE_2_3_3_REV, &out);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(PixelTypesTest, SubImageWithPackedTypes) {
  const uint32_t base[4] = {0, 0, 0, 0};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, base);
  const uint16_t texel = 0x1234;
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, &texel);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_TRUE(near_rgba(read_back(1, 1, 2), {17, 34, 51, 68}));
  EXPECT_TRUE(near_rgba(read_back(0, 1, 2), {0, 0, 0, 0}));
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, &texel);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(PixelTypesTest, DisplayListsKeepSwappedPackedImages) {
  const uint8_t big_endian_565[2] = {0xF8, 0x01};
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  glNewList(1, GL_COMPILE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, big_endian_565);
  glEndList();
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
  glCallList(1);
  EXPECT_TRUE(near_rgba(read_back(), {255, 0, 8, 255}));
}

}  // namespace
}  // namespace pineda::test
