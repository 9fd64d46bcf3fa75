// glReadPixels with GL 1.2's packed types (each with RGB, RGBA or BGRA), byte swapping and
// alignment of packed pixels, stencil indices as a bitmap (LSB_FIRST, SKIP_PIXELS) and
// masked to the type, and the errors of format/type combinations.
#include <cstring>

#include "tests/e2e/support/gl_test.h"

#include <GL/glext.h>

namespace pineda::test {
namespace {

class ReadPixelsPackedTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    clear_to(0.2f, 0.4f, 0.6f, 0.8f);  // 51, 102, 153, 204
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
  }
  uint32_t read_one(GLenum format, GLenum type) {
    uint8_t bytes[8];
    std::memset(bytes, 0, sizeof bytes);
    glReadPixels(2, 3, 1, 1, format, type, bytes);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << std::hex << format << " " << type;
    uint32_t v = 0;
    std::memcpy(&v, bytes, 4);  // little-endian: a byte or short element is the low bits
    return v;
  }
};

struct PackedRead {
  GLenum format, type;
  uint32_t value;
};

// 0.2, 0.4, 0.6, 0.8 rounded to each field: 3 bits 1, 3; 2 bits 2; 4 bits 3, 6, 9, 12; 5 bits 6,
// 12, 19; 6 bits 25; 1 bit 1; 10 bits 205, 409, 614; 2 bits 2.
TEST_F(ReadPixelsPackedTest, EveryPackedTypeWritesItsBitFields) {
  const PackedRead cases[] = {
      {GL_RGB, GL_UNSIGNED_BYTE_3_3_2, 0x2E},
      {GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV, 0x99},
      {GL_RGB, GL_UNSIGNED_SHORT_5_6_5, 0x3333},
      {GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV, 0x9B26},
      {GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, 0x369C},
      {GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4_REV, 0xC963},
      {GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4, 0x963C},
      {GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4_REV, 0xC369},
      {GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, 0x3327},
      {GL_RGBA, GL_UNSIGNED_SHORT_1_5_5_5_REV, 0xCD86},
      {GL_BGRA, GL_UNSIGNED_SHORT_5_5_5_1, 0x9B0D},
      {GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, 0x336699CC},
      {GL_RGBA, GL_UNSIGNED_INT_8_8_8_8_REV, 0xCC996633},
      {GL_BGRA, GL_UNSIGNED_INT_8_8_8_8, 0x996633CC},
      {GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, 0xCC336699},
      {GL_RGBA, GL_UNSIGNED_INT_10_10_10_2, 0x3359999A},
      {GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, 0xA66664CD},
      {GL_BGRA, GL_UNSIGNED_INT_2_10_10_10_REV, 0x8CD66666},
  };
  for (const PackedRead& c : cases)
    EXPECT_EQ(read_one(c.format, c.type), c.value) << std::hex << c.format << " " << c.type;
}

TEST_F(ReadPixelsPackedTest, SwapBytesReversesWholePackedElements) {
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
  EXPECT_EQ(read_one(GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4), 0x9C36u);
  EXPECT_EQ(read_one(GL_RGBA, GL_UNSIGNED_INT_8_8_8_8), 0xCC996633u);
  EXPECT_EQ(read_one(GL_RGB, GL_UNSIGNED_BYTE_3_3_2), 0x2Eu);  // one byte: nothing to swap
}

// Three 2-byte pixels make a 6-byte row; alignment 4 pads it to 8, and ROW_LENGTH and the
// skips count whole packed pixels.
TEST_F(ReadPixelsPackedTest, PackedRowsFollowAlignmentRowLengthAndSkips) {
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  std::vector<uint16_t> out(16, 0xEEEE);
  glReadPixels(0, 0, 3, 2, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, out.data());
  EXPECT_EQ(out[0], 0x3333);
  EXPECT_EQ(out[2], 0x3333);
  EXPECT_EQ(out[3], 0xEEEE);  // padding
  EXPECT_EQ(out[4], 0x3333);  // second row at byte 8
  EXPECT_EQ(out[7], 0xEEEE);
  std::fill(out.begin(), out.end(), 0xEEEE);
  glPixelStorei(GL_PACK_ALIGNMENT, 2);
  glPixelStorei(GL_PACK_ROW_LENGTH, 5);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 1);
  glPixelStorei(GL_PACK_SKIP_ROWS, 1);
  glReadPixels(0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, out.data());
  const std::vector<uint16_t> want = {0xEEEE, 0xEEEE, 0xEEEE, 0xEEEE, 0xEEEE, 0xEEEE, 0x369C, 0x369C,
                                      0xEEEE, 0xEEEE, 0xEEEE, 0x369C, 0x369C, 0xEEEE, 0xEEEE, 0xEEEE};
  EXPECT_EQ(out, want);
}

// Stencil 1 (odd) in columns 0..4 of rows 0..1, 2 (even) elsewhere: as a bitmap, each index's
// lowest bit, most significant bit first.
class ReadStencilBitmapTest : public ReadPixelsPackedTest {
 protected:
  void SetUp() override {
    ReadPixelsPackedTest::SetUp();
    glClearStencil(2);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 5, 2);
    glClearStencil(1);
    glClear(GL_STENCIL_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
  }
};

TEST_F(ReadStencilBitmapTest, BitsMostSignificantFirst) {
  uint8_t out[4] = {0x00, 0x55, 0x00, 0x55};
  glReadPixels(0, 0, 10, 2, GL_STENCIL_INDEX, GL_BITMAP, out);  // alignment 1: 2 bytes a row
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(out[0], 0xF8);  // 11111000
  EXPECT_EQ(out[1], 0x15);  // columns 8, 9 cleared; bits past the row's width kept
  EXPECT_EQ(out[2], 0xF8);
  EXPECT_EQ(out[3], 0x15);
}

TEST_F(ReadStencilBitmapTest, LsbFirstAndSkipPixels) {
  glPixelStorei(GL_PACK_LSB_FIRST, GL_TRUE);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 3);
  uint8_t out[2] = {0xFF, 0xFF};
  glReadPixels(0, 0, 6, 1, GL_STENCIL_INDEX, GL_BITMAP, out);
  // Image bits 3..8: columns 0..4 set, column 5 clear; bits 0..2 skipped, untouched.
  EXPECT_EQ(out[0], 0xFF);
  EXPECT_EQ(out[1], 0xFE);
}

TEST_F(ReadPixelsPackedTest, StencilIndicesAreMaskedToTheType) {
  glClearStencil(200);
  glClear(GL_STENCIL_BUFFER_BIT);
  GLbyte b = 0;
  glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_BYTE, &b);
  EXPECT_EQ(b, 200 & 0x7f);  // GL 1.5 table 4.7: a signed type keeps 7 bits
  glPixelTransferi(GL_INDEX_OFFSET, 100);
  GLubyte ub = 0;
  glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &ub);
  EXPECT_EQ(ub, 300 & 0xff);
  GLfloat f = 0;
  glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_FLOAT, &f);
  EXPECT_EQ(f, 300.f);
}

struct ErrorCase {
  GLenum format, type, error;
};

// As llvmpipe answers each.
TEST_F(ReadPixelsPackedTest, FormatAndTypeErrors) {
  const ErrorCase cases[] = {
      {GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, GL_INVALID_OPERATION},
      {GL_RGBA, GL_UNSIGNED_BYTE_3_3_2, GL_INVALID_OPERATION},
      {GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, GL_INVALID_OPERATION},
      {GL_BGR, GL_UNSIGNED_SHORT_5_6_5, GL_INVALID_OPERATION},
      {GL_LUMINANCE, GL_UNSIGNED_BYTE_3_3_2, GL_INVALID_OPERATION},
      {GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE_3_3_2, GL_INVALID_OPERATION},
      {GL_STENCIL_INDEX, GL_UNSIGNED_SHORT_5_6_5, GL_INVALID_OPERATION},
      {GL_COLOR_INDEX, GL_UNSIGNED_SHORT_5_6_5, GL_INVALID_OPERATION},
      {GL_COLOR_INDEX, GL_UNSIGNED_BYTE, GL_INVALID_OPERATION},  // an RGBA framebuffer has no indices
      {GL_COLOR_INDEX, GL_BITMAP, GL_INVALID_OPERATION},
      {GL_DEPTH_COMPONENT, GL_BITMAP, GL_INVALID_ENUM},
      {GL_RGBA, GL_BITMAP, GL_INVALID_ENUM},
      {GL_RGBA, GL_DOUBLE, GL_INVALID_ENUM},
      {GL_COLOR_INDEX, 0x1234, GL_INVALID_ENUM},
      {GL_BGRA, GL_UNSIGNED_INT_2_10_10_10_REV, GL_NO_ERROR},
      {GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV, GL_NO_ERROR},
  };
  for (const ErrorCase& c : cases) {
    uint8_t out[16];
    std::memset(out, 0xEE, sizeof out);
    glReadPixels(0, 0, 1, 1, c.format, c.type, out);
    EXPECT_EQ(glGetError(), c.error) << std::hex << c.format << " " << c.type;
    if (c.error != GL_NO_ERROR) {
      EXPECT_EQ(out[0], 0xEE) << "an error writes nothing";
    }
  }
}

}  // namespace
}  // namespace pineda::test
