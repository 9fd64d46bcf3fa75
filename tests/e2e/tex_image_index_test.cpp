// glTexImage/glTexSubImage with GL_COLOR_INDEX data (GL 1.5 spec 3.8.1: converted as glDrawPixels
// converts it): index shift and offset, the I_TO_R/G/B/A maps, SWAP_BYTES, GL_BITMAP with
// LSB_FIRST and SKIP_PIXELS, display lists, and the format/type errors.
#include "tests/e2e/support/gl_test.h"

#include <GL/glext.h>

namespace pineda::test {
namespace {

class TexImageIndexTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    glBindTexture(GL_TEXTURE_2D, 1);
    const float r[4] = {0.f, 0.25f, 0.5f, 1.f}, g[4] = {1.f, 0.75f, 0.5f, 0.f};
    const float b[4] = {0.1f, 0.2f, 0.3f, 0.4f}, a[4] = {1.f, 1.f, 0.f, 0.5f};
    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 4, r);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 4, g);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 4, b);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 4, a);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  }
  // The 4x2 level 0, row 0 first.
  std::vector<Rgba> level() {
    uint8_t p[4 * 8];
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, p);
    std::vector<Rgba> out;
    for (int i = 0; i < 8; ++i) out.push_back({p[4 * i], p[4 * i + 1], p[4 * i + 2], p[4 * i + 3]});
    return out;
  }
};

// Each index's colour from the maps (as llvmpipe stores them).
const Rgba kIndex[4] = {{0, 255, 26, 255}, {64, 191, 51, 255}, {128, 128, 76, 0}, {255, 0, 102, 128}};

std::vector<Rgba> colors_of(std::initializer_list<int> indices) {
  std::vector<Rgba> out;
  for (int i : indices) out.push_back(kIndex[i]);
  return out;
}

TEST_F(TexImageIndexTest, IndicesGoThroughTheMapsMaskedToTheirSize) {
  const uint8_t indices[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 2, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, indices);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(level(), colors_of({0, 1, 2, 3, 0, 1, 2, 3}));
}

TEST_F(TexImageIndexTest, IndexShiftAndOffsetComeFirst) {
  glPixelTransferi(GL_INDEX_SHIFT, 1);
  glPixelTransferi(GL_INDEX_OFFSET, 1);
  const uint8_t indices[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 2, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, indices);
  EXPECT_EQ(level(), colors_of({1, 3, 1, 3, 1, 3, 1, 3}));  // 2i + 1
}

TEST_F(TexImageIndexTest, ShortIndicesAreByteSwapped) {
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  const GLushort indices[8] = {3, 2, 1, 0, 0x100, 0x101, 0x102, 0x103};  // 0x300 & 3 = 0; 0x100 -> 1
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 2, 0, GL_COLOR_INDEX, GL_UNSIGNED_SHORT, indices);
  EXPECT_EQ(level(), colors_of({0, 0, 0, 0, 1, 1, 1, 1}));
}

// Rows of whole bytes (alignment 1). llvmpipe reads the rows after the first with LSB_FIRST
// inverted (its glDrawPixels of the same bitmap too); this is the spec's reading (3.6.4).
TEST_F(TexImageIndexTest, BitmapIndicesAreBitsMostSignificantFirst) {
  const uint8_t bits[2] = {0xA0, 0x50};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 2, 0, GL_COLOR_INDEX, GL_BITMAP, bits);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(level(), colors_of({1, 0, 1, 0, 0, 1, 0, 1}));
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  const uint8_t lsb[2] = {0x05, 0x0A};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 2, 0, GL_COLOR_INDEX, GL_BITMAP, lsb);
  EXPECT_EQ(level(), colors_of({1, 0, 1, 0, 0, 1, 0, 1}));
}

TEST_F(TexImageIndexTest, BitmapSkipPixelsCountsBits) {
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  const uint8_t bits[2] = {0x14, 0x0A};  // 000 1010 0 : bits 3..6 = 1, 0, 1, 0
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 2, 0, GL_COLOR_INDEX, GL_BITMAP, bits);
  EXPECT_EQ(level(), colors_of({1, 0, 1, 0, 0, 1, 0, 1}));  // 0x0A: 000 0101 0
}

TEST_F(TexImageIndexTest, SubImagesAndLuminanceFormats) {
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  const uint8_t indices[2] = {2, 3};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 0, 2, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, indices);
  const uint8_t bits[1] = {0xA0};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 1, 4, 1, GL_COLOR_INDEX, GL_BITMAP, bits);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const std::vector<Rgba> got = level();
  EXPECT_EQ(got[1], kIndex[2]);
  EXPECT_EQ(got[2], kIndex[3]);
  EXPECT_EQ(std::vector<Rgba>(got.begin() + 4, got.end()), colors_of({1, 0, 1, 0}));
  const uint8_t more[8] = {0, 1, 2, 3, 0, 1, 2, 3};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 4, 2, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, more);
  EXPECT_EQ(level()[1], (Rgba{64, 0, 0, 255}));  // the red map as luminance
}

// The bitmap is copied at compile time under the unpack state of that moment.
TEST_F(TexImageIndexTest, DisplayListsKeepBitmapsAsCompiled) {
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  const uint8_t lsb[2] = {0x05, 0x0A};
  glNewList(1, GL_COMPILE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 2, 0, GL_COLOR_INDEX, GL_BITMAP, lsb);
  glEndList();
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  glCallList(1);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(level(), colors_of({1, 0, 1, 0, 0, 1, 0, 1}));
  const uint8_t indices[8] = {3, 2, 1, 0, 0, 1, 2, 3};
  glNewList(2, GL_COMPILE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 2, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, indices);
  glEndList();
  glCallList(2);
  EXPECT_EQ(level(), colors_of({3, 2, 1, 0, 0, 1, 2, 3}));
}

// A 1x1 bitmap texture compiled and executed in a list, drawn, read back; then the list
// called again (piglit gl-1.1-read-pixels-after-display-list).
TEST_F(TexImageIndexTest, BitmapTextureFromAListDrawsItsIndexColour) {
  pixel_projection();
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  for (const uint8_t byte : {uint8_t(0x8f), uint8_t(0x7f)}) {
    clear_to(1, 1, 1, 1);
    glNewList(1, GL_COMPILE_AND_EXECUTE);
    glEnable(GL_TEXTURE_2D);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_COLOR_INDEX, GL_BITMAP, &byte);
    glRecti(0, 0, 1, 1);
    glDisable(GL_TEXTURE_2D);
    glEndList();
    const Rgba want = kIndex[byte >> 7];  // the first bit
    EXPECT_EQ(pixel(0, 0), want) << int(byte);
    clear_to(1, 1, 1, 1);
    glCallList(1);
    EXPECT_EQ(pixel(0, 0), want) << int(byte);
  }
}

TEST_F(TexImageIndexTest, FormatAndTypeErrors) {
  const uint8_t data[16] = {};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 2, 0, GL_RGBA, GL_BITMAP, data);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 2, 0, GL_COLOR_INDEX, GL_UNSIGNED_SHORT_5_6_5, data);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 2, 0, GL_COLOR_INDEX, GL_DOUBLE, data);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 4, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, data);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test

