// OES_compressed_paletted_texture (core in OpenGL ES 1.1): a palette and the indices of every
// level in one glCompressedTexImage2D, decoded as llvmpipe decodes them (checked side by side:
// the first texel of a 4-bit index byte is its high nibble).
#define GL_GLEXT_PROTOTYPES
#include <GLES/gl.h>
#include <GLES/glext.h>
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "tests/es1/egl_context.h"

namespace pineda::es1_test {
namespace {

constexpr int kSize = 8;
using Pixel = std::vector<GLubyte>;

class PalettedTexture : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    glBindTexture(GL_TEXTURE_2D, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, kCorners);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, kTexCoords);
  }
  // The texture over the whole viewport (size x size at the origin).
  void draw(int size = kSize) {
    glViewport(0, 0, size, size);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  }
  Pixel pixel(int x, int y) {
    Pixel p(4, 0);
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
    return p;
  }
  static constexpr GLfloat kCorners[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
  static constexpr GLfloat kTexCoords[8] = {0, 0, 1, 0, 0, 1, 1, 1};
  Es1Context ctx{kSize, kSize};
};

// A 16-entry RGBA8 palette, entry i = (16 i, 255 - 16 i, 7, 255), followed by `indices`.
std::vector<GLubyte> palette4_rgba8(std::vector<GLubyte> indices) {
  std::vector<GLubyte> data;
  for (int i = 0; i < 16; ++i) data.insert(data.end(), {GLubyte(16 * i), GLubyte(255 - 16 * i), 7, 255});
  data.insert(data.end(), indices.begin(), indices.end());
  return data;
}

TEST_F(PalettedTexture, TheTenFormatsAreListed) {
  GLint count = 0;
  glGetIntegerv(GL_NUM_COMPRESSED_TEXTURE_FORMATS, &count);
  ASSERT_EQ(count, 10);
  std::vector<GLint> formats(10, 0);
  glGetIntegerv(GL_COMPRESSED_TEXTURE_FORMATS, formats.data());
  for (int i = 0; i < 10; ++i) EXPECT_EQ(formats[i], GL_PALETTE4_RGB8_OES + i);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(PalettedTexture, FourBitIndicesHighNibbleFirst) {
  const std::vector<GLubyte> data = palette4_rgba8({0x12, 0x34});  // 2x2: indices 1, 2 / 3, 4
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_PALETTE4_RGBA8_OES, 2, 2, 0, GLsizei(data.size()), data.data());
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  draw();
  EXPECT_EQ(pixel(1, 1), (Pixel{16, 239, 7, 255}));
  EXPECT_EQ(pixel(6, 1), (Pixel{32, 223, 7, 255}));
  EXPECT_EQ(pixel(1, 6), (Pixel{48, 207, 7, 255}));
  EXPECT_EQ(pixel(6, 6), (Pixel{64, 191, 7, 255}));
}

TEST_F(PalettedTexture, OddRowsAreNotPadded) {
  // 3x2 of 4-bit indices: six texels in three bytes, the second row starting mid-byte.
  const std::vector<GLubyte> data = palette4_rgba8({0x12, 0x34, 0x56});
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_PALETTE4_RGBA8_OES, 3, 2, 0, GLsizei(data.size()), data.data());
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 8);  // the application's unpack state does not apply
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_PALETTE4_RGBA8_OES, 3, 2, 0, GLsizei(data.size()), data.data());
  GLint alignment = 0;
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
  EXPECT_EQ(alignment, 8);
  draw(6);
  EXPECT_EQ(pixel(0, 0), (Pixel{16, 239, 7, 255}));
  EXPECT_EQ(pixel(5, 0), (Pixel{48, 207, 7, 255}));
  EXPECT_EQ(pixel(0, 5), (Pixel{64, 191, 7, 255}));
  EXPECT_EQ(pixel(5, 5), (Pixel{96, 159, 7, 255}));
}

TEST_F(PalettedTexture, SixteenBitEntriesAreNativeShorts) {
  std::vector<GLushort> palette(256, 0);
  palette[5] = 0xF800;  // R5_G6_B5 red
  std::vector<GLubyte> data(512 + 1);
  std::memcpy(data.data(), palette.data(), 512);
  data[512] = 5;
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_PALETTE8_R5_G6_B5_OES, 1, 1, 0, GLsizei(data.size()), data.data());
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  draw();
  EXPECT_EQ(pixel(3, 3), (Pixel{255, 0, 0, 255}));
  palette[5] = 0x000F | 0x00F0;  // RGBA4: blue 15, alpha 15
  std::memcpy(data.data(), palette.data(), 512);
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_PALETTE8_RGBA4_OES, 1, 1, 0, GLsizei(data.size()), data.data());
  draw();
  EXPECT_EQ(pixel(3, 3), (Pixel{0, 0, 255, 255}));
}

TEST_F(PalettedTexture, NegativeLevelLoadsEveryMipmapLevel) {
  std::vector<GLubyte> data;
  for (int i = 0; i < 256; ++i) data.insert(data.end(), {GLubyte(i), GLubyte(i), GLubyte(i), 255});
  data.insert(data.end(), {1, 2, 3, 4, 9});  // level 0 (2x2), then level 1 (1x1)
  glCompressedTexImage2D(GL_TEXTURE_2D, -1, GL_PALETTE8_RGBA8_OES, 2, 2, 0, GLsizei(data.size()), data.data());
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  draw(1);  // minified to 1x1: level 1
  EXPECT_EQ(pixel(0, 0), (Pixel{9, 9, 9, 255}));
}

TEST_F(PalettedTexture, ErrorsAsSpecified) {
  const std::vector<GLubyte> data = palette4_rgba8({0x12, 0x34, 0, 0});
  const auto upload = [&](GLint level, GLsizei w, GLsizei h, GLint border, GLsizei size) {
    glCompressedTexImage2D(GL_TEXTURE_2D, level, GL_PALETTE4_RGBA8_OES, w, h, border, size, data.data());
    return glGetError();
  };
  EXPECT_EQ(upload(1, 2, 2, 0, 66), GLenum(GL_INVALID_VALUE));   // levels are 0 or negative
  EXPECT_EQ(upload(-20, 2, 2, 0, 68), GLenum(GL_INVALID_VALUE)); // beyond the last possible level
  EXPECT_EQ(upload(0, 2, 2, 1, 66), GLenum(GL_INVALID_VALUE));   // border
  EXPECT_EQ(upload(0, 2, 2, 0, 65), GLenum(GL_INVALID_VALUE));   // imageSize one short
  EXPECT_EQ(upload(0, 2, 2, 0, 67), GLenum(GL_INVALID_VALUE));   // and one over
  EXPECT_EQ(upload(0, -2, 2, 0, 66), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(upload(0, 1 << 30, 1 << 30, 0, 66), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(upload(-1, 2, 2, 0, 67), GLenum(GL_NO_ERROR));       // 2x2 and 1x1
  EXPECT_EQ(upload(-2, 2, 2, 0, 68), GLenum(GL_NO_ERROR));       // a third 1x1 level, as Mesa takes it
  EXPECT_EQ(upload(0, 3, 1, 0, 66), GLenum(GL_NO_ERROR));
  glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_PALETTE4_RGBA8_OES, 66, data.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, 66, data.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

TEST_F(PalettedTexture, NullDataDefinesTheLevels) {
  glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_PALETTE4_RGB8_OES, 2, 2, 0, 16 * 3 + 2, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const std::vector<GLubyte> texels(2 * 2 * 3, 200);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGB, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  draw();
  EXPECT_EQ(pixel(4, 4), (Pixel{200, 200, 200, 255}));
}

}  // namespace
}  // namespace pineda::es1_test
