// glDrawPixels, glBitmap and glPixelMap compiled into display lists copy exactly what the call
// reads: not the row-length and skip gaps of the unpack state (the client memory here is
// readable only where the pixels are), and nothing for a call whose sizes are invalid.
#include <vector>

#include "tests/e2e/support/gl_test.h"
#include "tests/e2e/support/guarded_memory.h"

namespace pineda::test {
namespace {

class ListPixelRectCopyTest : public GlTest {
 protected:
  SurfaceSpec spec() const override { return {64, 32}; }
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
  }
};

Rgba pattern(int x, int y) { return {4 * x + 3, 10 * y + 5, 7, 255}; }

// 57x18 RGBA pixels 8388608 rows past the pointer (rows of 228 bytes: 1.9 GB of skipped rows).
TEST_F(ListPixelRectCopyTest, DrawPixelsWithHugeSkipRowsCopiesOnlyItsPixels) {
  const int w = 57, h = 18, skip_rows = 8388608;
  const size_t row = size_t(w) * 4, offset = size_t(skip_rows) * row;
  GuardedMemory memory(offset + row * h + 4096, offset, row * h);
  ASSERT_TRUE(memory.ok());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 4; ++c) memory.base()[offset + y * row + 4 * x + c] = uint8_t(pattern(x, y)[c]);

  glPixelStorei(GL_UNPACK_SKIP_ROWS, skip_rows);
  glRasterPos2i(0, 0);
  glNewList(1, GL_COMPILE);
  glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, memory.base());
  glEndList();
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glCallList(1);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) ASSERT_TRUE(near_rgba(pixel(x, y), pattern(x, y))) << x << "," << y;
  EXPECT_TRUE(near_rgba(pixel(w, 0), {0, 0, 0, 0}));
  EXPECT_TRUE(near_rgba(pixel(0, h), {0, 0, 0, 0}));
}

// A 20x3 bitmap 1 << 24 rows of 4 bytes past the pointer, with ROW_LENGTH 32 and SKIP_PIXELS 5.
TEST_F(ListPixelRectCopyTest, BitmapWithHugeSkipRowsCopiesOnlyItsBits) {
  const int w = 20, h = 3, skip_rows = 1 << 24;
  const size_t row = 4, offset = size_t(skip_rows) * row;
  GuardedMemory memory(offset + row * h + 4096, offset, row * h);
  ASSERT_TRUE(memory.ok());
  // Bit i of row j (after the 5 skipped bits) is set when i + j is even.
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      if ((i + j) % 2 == 0) memory.base()[offset + j * row + (i + 5) / 8] |= uint8_t(0x80 >> ((i + 5) % 8));

  glPixelStorei(GL_UNPACK_ROW_LENGTH, 32);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 5);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, skip_rows);
  glColor3f(1, 1, 1);
  glRasterPos2i(0, 0);
  glNewList(1, GL_COMPILE);
  glBitmap(w, h, 0, 0, 0, 0, memory.base());
  glEndList();
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glCallList(1);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const Rgba expected = (i + j) % 2 == 0 ? Rgba{255, 255, 255, 255} : Rgba{0, 0, 0, 0};
      ASSERT_TRUE(near_rgba(pixel(i, j), expected)) << i << "," << j;
    }
}

TEST_F(ListPixelRectCopyTest, DrawPixelsWithNegativeWidthCopiesNothingAndIsInvalidValue) {
  const uint8_t p[16] = {};
  glNewList(1, GL_COMPILE);
  glDrawPixels(-1, 1 << 30, GL_RGBA, GL_FLOAT, p);
  glEndList();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glCallList(1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

TEST_F(ListPixelRectCopyTest, PixelMapAboveMaxTableCopiesNothingAndIsInvalidValue) {
  const GLfloat p[4] = {};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 586360086, p);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glNewList(1, GL_COMPILE_AND_EXECUTE);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 586360086, p);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glPixelMapuiv(GL_PIXEL_MAP_G_TO_G, 1 << 30, reinterpret_cast<const GLuint*>(p));
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glPixelMapusv(GL_PIXEL_MAP_I_TO_R, 3, reinterpret_cast<const GLushort*>(p));  // not a power of two
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glEndList();
  glCallList(1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLint size = 0;
  glGetIntegerv(GL_PIXEL_MAP_R_TO_R_SIZE, &size);
  EXPECT_EQ(size, 1);
}

TEST_F(ListPixelRectCopyTest, ValidPixelMapRunsFromTheListAsImmediate) {
  GLfloat values[2] = {0.25f, 0.75f};
  glNewList(1, GL_COMPILE);
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, values);
  glEndList();
  values[0] = values[1] = 0.f;  // the list holds the values of compile time
  glCallList(1);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLint size = 0;
  glGetIntegerv(GL_PIXEL_MAP_R_TO_R_SIZE, &size);
  ASSERT_EQ(size, 2);
  GLfloat back[2] = {};
  glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, back);
  EXPECT_EQ(back[0], 0.25f);
  EXPECT_EQ(back[1], 0.75f);
}

}  // namespace
}  // namespace pineda::test
