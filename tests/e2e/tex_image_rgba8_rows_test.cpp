// RGBA8 client images (bytes and 8_8_8_8 words) into RGBA8 and RGB8 textures are copied row
// by row (no per-texel conversion): every byte value, every layout, unpack row length, skips
// and alignment, borders, and the per-texel path whenever pixel transfer or a smaller format
// changes the values.
#include <cmath>
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

// Every client layout of RGBA8 that is read without conversion (state/pixels/rgba8_rows.h),
// into RGBA8 and RGB8 levels: each texel as GL 2.1 3.6.4 and table 3.11 unpack it. A width of 7
// takes both the four-pixel steps and the tail of the three-byte rows.
TEST_F(TexImageRgba8RowsTest, ByteAndWordLayoutsAreStoredAsUnpacked) {
  struct Layout {
    GLenum format, type;
    bool swap;
  };
  const Layout layouts[] = {{GL_RGBA, GL_UNSIGNED_BYTE, false},
                            {GL_BGRA, GL_UNSIGNED_BYTE, false},
                            {GL_RGB, GL_UNSIGNED_BYTE, false},
                            {GL_BGR, GL_UNSIGNED_BYTE, true},
                            {GL_RGBA, GL_UNSIGNED_INT_8_8_8_8_REV, false},
                            {GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, false},
                            {GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, true},
                            {GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, false},
                            {GL_BGRA, GL_UNSIGNED_INT_8_8_8_8, true}};
  constexpr int kWidth = 7, kHeight = 3;
  std::vector<uint8_t> image(kWidth * kHeight * 4);
  for (size_t i = 0; i < image.size(); ++i) image[i] = uint8_t(i * 29 + 3);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glBindTexture(GL_TEXTURE_2D, 1);
  for (const Layout& l : layouts)
    for (GLenum internal : {GL_RGBA8, GL_RGB8}) {
      const int n = l.format == GL_RGB || l.format == GL_BGR ? 3 : 4;
      glPixelStorei(GL_UNPACK_SWAP_BYTES, l.swap);
      glTexImage2D(GL_TEXTURE_2D, 0, internal, kWidth, kHeight, 0, l.format, l.type, image.data());
      ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
      std::vector<uint8_t> want;
      for (int p = 0; p < kWidth * kHeight; ++p) {
        uint8_t c[4] = {0, 0, 0, 255};  // the format's components, in its order
        const uint8_t* src = &image[size_t(p) * n];
        if (l.type == GL_UNSIGNED_BYTE) {
          for (int k = 0; k < n; ++k) c[k] = src[k];
        } else {
          uint32_t word = src[0] | uint32_t{src[1]} << 8 | uint32_t{src[2]} << 16 | uint32_t{src[3]} << 24;
          if (l.swap) word = __builtin_bswap32(word);
          for (int k = 0; k < 4; ++k)
            c[k] = uint8_t(word >> (l.type == GL_UNSIGNED_INT_8_8_8_8_REV ? 8 * k : 24 - 8 * k));
        }
        const bool bgr = l.format == GL_BGRA || l.format == GL_BGR;
        want.insert(want.end(), {bgr ? c[2] : c[0], c[1], bgr ? c[0] : c[2], internal == GL_RGB8 ? uint8_t(255) : c[3]});
      }
      EXPECT_EQ(stored_level(kWidth, kHeight), want)
          << std::hex << "format " << l.format << " type " << l.type << " swap " << l.swap << " internal " << internal;
    }
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
}

// One- and two-byte formats (glyph atlases) into every 8-bit base format: the client pixel as
// load_color reads it (missing colour 0, missing alpha 1, luminance in R, G and B), then the base
// format's reduction (GL 2.1 table 3.15). A width of 5 and alignment 1 leave rows unaligned. The
// texels luminance and intensity keep in G and B too (which the fill routines read) are checked
// by drawing in the next test; here they read back as glGetTexImage returns them.
TEST_F(TexImageRgba8RowsTest, OneAndTwoByteFormatsIntoEveryBaseFormat) {
  constexpr int kWidth = 5, kHeight = 3;
  std::vector<uint8_t> image(kWidth * kHeight * 2);
  for (size_t i = 0; i < image.size(); ++i) image[i] = uint8_t(i * 53 + 9);
  struct Format {
    GLenum format;
    int n;
    int from[4];  // R, G, B, A's source byte; -1: 0 for colour, 255 for alpha
  };
  const Format formats[] = {{GL_ALPHA, 1, {-1, -1, -1, 0}},         {GL_LUMINANCE, 1, {0, 0, 0, -1}},
                            {GL_LUMINANCE_ALPHA, 2, {0, 0, 0, 1}},   {GL_RED, 1, {0, -1, -1, -1}},
                            {GL_GREEN, 1, {-1, 0, -1, -1}},          {GL_BLUE, 1, {-1, -1, 0, -1}}};
  struct Internal {
    GLenum internal;
    GLenum base;
  };
  const Internal internals[] = {{GL_ALPHA8, GL_ALPHA},         {GL_LUMINANCE8, GL_LUMINANCE},
                                {GL_LUMINANCE8_ALPHA8, GL_LUMINANCE_ALPHA}, {GL_INTENSITY8, GL_INTENSITY},
                                {GL_RGB8, GL_RGB},             {GL_RGBA8, GL_RGBA}};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glBindTexture(GL_TEXTURE_2D, 1);
  for (const Format& f : formats)
    for (const Internal& in : internals) {
      glTexImage2D(GL_TEXTURE_2D, 0, in.internal, kWidth, kHeight, 0, f.format, GL_UNSIGNED_BYTE, image.data());
      ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
      std::vector<uint8_t> want;
      for (int p = 0; p < kWidth * kHeight; ++p) {
        uint8_t c[4];
        for (int k = 0; k < 4; ++k) c[k] = f.from[k] >= 0 ? image[size_t(p * f.n + f.from[k])] : k == 3 ? 255 : 0;
        // (glGetTexImage as RGBA reads luminance and intensity into R alone, intensity with alpha
        // 1: GL 2.1 table 6.1.)
        switch (in.base) {
          case GL_ALPHA: c[0] = c[1] = c[2] = 0; break;
          case GL_LUMINANCE: c[1] = c[2] = 0, c[3] = 255; break;
          case GL_LUMINANCE_ALPHA: c[1] = c[2] = 0; break;
          case GL_INTENSITY: c[1] = c[2] = 0, c[3] = 255; break;
          case GL_RGB: c[3] = 255; break;
          default: break;
        }
        want.insert(want.end(), c, c + 4);
      }
      EXPECT_EQ(stored_level(kWidth, kHeight), want) << std::hex << "format " << f.format << " internal " << in.internal;
    }
}

// Drawn one texel per pixel with REPLACE: a luminance texture uploaded as bytes gives (L, L, L)
// and the fragment's alpha, an intensity one I in all four.
TEST_F(TexImageRgba8RowsTest, LuminanceAndIntensityBytesDrawAsThemselves) {
  std::vector<uint8_t> image(16 * 16);
  for (size_t i = 0; i < image.size(); ++i) image[i] = uint8_t(i * 53 + 9);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glBindTexture(GL_TEXTURE_2D, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  glColor4f(1.f, 1.f, 1.f, 0.4f);
  for (const GLenum internal : {GL_LUMINANCE8, GL_INTENSITY8}) {
    glTexImage2D(GL_TEXTURE_2D, 0, internal, 16, 16, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, image.data());
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0), glVertex2f(0, 0);
    glTexCoord2f(1, 0), glVertex2f(16, 0);
    glTexCoord2f(1, 1), glVertex2f(16, 16);
    glTexCoord2f(0, 1), glVertex2f(0, 16);
    glEnd();
    std::vector<uint8_t> pixels(16 * 16 * 4);
    glReadPixels(0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    std::vector<uint8_t> want;
    for (const uint8_t l : image) want.insert(want.end(), {l, l, l, internal == GL_INTENSITY8 ? l : uint8_t(102)});
    EXPECT_EQ(pixels, want) << std::hex << internal;
  }
  glDisable(GL_TEXTURE_2D);
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

// Float texels into 8-bit formats (to_texels): clamped to [0, 1], NaN as 0, rounded to nearest
// with ties to even (Mesa's float_to_ubyte: 0.3f * 255 is 76.5 and stores 76); into RGBA4,
// rounded to 4 bits with ties away from zero and widened back; into LUMINANCE8, red alone.
TEST_F(TexImageRgba8RowsTest, FloatTexelsClampRoundAndReduce) {
  const float texels[2][4] = {{0.3f, std::nanf(""), INFINITY, -1.f}, {0.5f / 255.f, 1.5f / 255.f, 2.5f / 255.f, 1.f}};
  struct Case {
    GLenum internal;
    uint8_t want[2][4];
  };
  // RGBA4: 0.3 * 15 = 4.5 rounds to 5 (widened 85), 1.5 / 255 * 15 = 0.09 to 0.
  const Case cases[] = {{GL_RGBA8, {{76, 0, 255, 0}, {0, 2, 2, 255}}},
                        {GL_RGBA4, {{85, 0, 255, 0}, {0, 0, 0, 255}}},
                        {GL_LUMINANCE8, {{76, 0, 0, 255}, {0, 0, 0, 255}}}};
  // The pair three times over: the first 16 components are converted 16 at a time, the rest one by one.
  constexpr int kWidth = 6;
  float row[kWidth][4];
  for (int p = 0; p < kWidth; ++p) std::copy(texels[p % 2], texels[p % 2] + 4, row[p]);
  glBindTexture(GL_TEXTURE_2D, 1);
  for (const Case& c : cases) {
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(c.internal), kWidth, 1, 0, GL_RGBA, GL_FLOAT, row);
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    const std::vector<uint8_t> got = stored_level(kWidth, 1);
    for (int p = 0; p < kWidth; ++p)
      for (int k = 0; k < 4; ++k)
        EXPECT_EQ(got[size_t(4 * p + k)], c.want[p % 2][k]) << std::hex << c.internal << " texel " << p << " component " << k;
  }
}

}  // namespace
}  // namespace pineda::test
