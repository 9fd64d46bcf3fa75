// RGBA / UNSIGNED_BYTE images into RGBA8 textures are copied row by row (no per-texel
// conversion): every byte value, unpack row length, skips and alignment, borders, and the
// per-texel path whenever pixel transfer or a smaller format changes the values.
#include <cstdint>
#include <vector>

#include "tests/e2e/support/pixel_test.h"

namespace pineda::test {
namespace {

class TexImageRgba8RowsTest : public PixelTest {};

std::vector<uint8_t> every_byte_value() {  // 8x8 RGBA texels holding 0..255
  std::vector<uint8_t> bytes(8 * 8 * 4);
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = uint8_t(i * 7 % 256);
  return bytes;
}

std::vector<uint8_t> stored_level(int width, int height) {
  std::vector<uint8_t> out(size_t(width) * height * 4, 0xee);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  return out;
}

TEST_F(TexImageRgba8RowsTest, EveryByteValueIsStoredAsGiven) {
  const std::vector<uint8_t> image = every_byte_value();
  glBindTexture(GL_TEXTURE_2D, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  EXPECT_EQ(stored_level(8, 8), image);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(TexImageRgba8RowsTest, SubImageHonoursRowLengthSkipsAndAlignment) {
  const std::vector<uint8_t> image = every_byte_value();
  glBindTexture(GL_TEXTURE_2D, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  std::vector<uint8_t> zero(8 * 8 * 4, 0);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, zero.data());
  // A 3x2 region of the 8x8 image, from its pixel (2, 1), into the level at (4, 5).
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 8);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 5, 3, 2, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  std::vector<uint8_t> want(8 * 8 * 4, 0);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x)
      for (int c = 0; c < 4; ++c)
        want[((5 + y) * 8 + 4 + x) * 4 + c] = image[((1 + y) * 8 + 2 + x) * 4 + c];
  EXPECT_EQ(stored_level(8, 8), want);
}

TEST_F(TexImageRgba8RowsTest, BorderTexelsAreSkipped) {
  // A 4x4 image with a one-texel border is a 2x2 level 0 holding the inner texels.
  std::vector<uint8_t> image(4 * 4 * 4);
  for (size_t i = 0; i < image.size(); ++i) image[i] = uint8_t(i);
  glBindTexture(GL_TEXTURE_2D, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  std::vector<uint8_t> want;
  for (int y = 1; y < 3; ++y)
    for (int x = 1; x < 3; ++x)
      for (int c = 0; c < 4; ++c) want.push_back(image[(y * 4 + x) * 4 + c]);
  EXPECT_EQ(stored_level(2, 2), want);
}

TEST_F(TexImageRgba8RowsTest, PixelTransferAndSmallerFormatsStillConvert) {
  const uint8_t texel[4] = {200, 100, 50, 255};
  glBindTexture(GL_TEXTURE_2D, 1);
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  glPixelTransferf(GL_RED_SCALE, 1.f);
  EXPECT_EQ(stored_level(1, 1), (std::vector<uint8_t>{100, 100, 50, 255}));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA4, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  // 4 bits: 200/255*15 = 11.76 -> 12 -> 204; 100 -> 5.88 -> 6 -> 102; 50 -> 2.94 -> 3 -> 51.
  EXPECT_EQ(stored_level(1, 1), (std::vector<uint8_t>{204, 102, 51, 255}));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, (const uint8_t[4]){200, 100, 50, 7});
  EXPECT_EQ(stored_level(1, 1), (std::vector<uint8_t>{200, 100, 50, 255}));  // no alpha: reads 1
}

}  // namespace
}  // namespace pineda::test
