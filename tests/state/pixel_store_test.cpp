// glPixelStore: every parameter, its type conversions and its errors.
#include <cfenv>

#include "tests/e2e/support/gl_test.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

class PixelStoreTest : public GlTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
};

TEST_F(PixelStoreTest, IntegerParametersReadBack) {
  const GLenum pnames[] = {GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS,
                           GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS};
  GLint value = 3;
  for (GLenum p : pnames) glPixelStorei(p, value++);
  value = 3;
  for (GLenum p : pnames) EXPECT_EQ(get_int(p), value++) << std::hex << p;
  glPixelStoref(GL_PACK_ROW_LENGTH, 17.f);
  EXPECT_EQ(get_int(GL_PACK_ROW_LENGTH), 17);
}

// GL 2.1 3.6.1: a float is rounded to the nearest integer, whatever the FPU rounding mode
// (piglit roundmode-pixelstore); -0.9 rounds to -1, an invalid row length.
TEST_F(PixelStoreTest, FloatValuesRoundToNearestInAnyRoundingMode) {
  const int saved = std::fegetround();
  for (int mode : {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO, FE_TONEAREST}) {
    std::fesetround(mode);
    glPixelStoref(GL_UNPACK_ROW_LENGTH, 2.2f);
    EXPECT_EQ(get_int(GL_UNPACK_ROW_LENGTH), 2) << mode;
    glPixelStoref(GL_UNPACK_ROW_LENGTH, 2.8f);
    EXPECT_EQ(get_int(GL_UNPACK_ROW_LENGTH), 3) << mode;
    glPixelStoref(GL_UNPACK_ROW_LENGTH, -0.1f);
    EXPECT_EQ(get_int(GL_UNPACK_ROW_LENGTH), 0) << mode;
    glPixelStoref(GL_PACK_ALIGNMENT, 3.9f);
    EXPECT_EQ(get_int(GL_PACK_ALIGNMENT), 4) << mode;
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    glPixelStoref(GL_UNPACK_ROW_LENGTH, -0.9f);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE)) << mode;
    EXPECT_EQ(get_int(GL_UNPACK_ROW_LENGTH), 0) << mode;
  }
  std::fesetround(saved);
  glPixelTransferf(GL_INDEX_OFFSET, -2.6f);
  EXPECT_EQ(get_int(GL_INDEX_OFFSET), -3);
  glPixelStoref(GL_UNPACK_SKIP_ROWS, 1e20f);  // clamped, not undefined
  EXPECT_EQ(get_int(GL_UNPACK_SKIP_ROWS), 2147483647);
}

TEST_F(PixelStoreTest, AlignmentAcceptsOneTwoFourEight) {
  for (GLint a : {1, 2, 8, 4}) {
    glPixelStorei(GL_PACK_ALIGNMENT, a);
    glPixelStorei(GL_UNPACK_ALIGNMENT, a);
    EXPECT_EQ(get_int(GL_PACK_ALIGNMENT), a);
    EXPECT_EQ(get_int(GL_UNPACK_ALIGNMENT), a);
  }
  glPixelStorei(GL_PACK_ALIGNMENT, 2);
  for (GLint bad : {0, 3, 16, -4}) {
    glPixelStorei(GL_PACK_ALIGNMENT, bad);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE)) << bad;
  }
  EXPECT_EQ(get_int(GL_PACK_ALIGNMENT), 2);
}

TEST_F(PixelStoreTest, BooleanParameters) {
  for (GLenum p : {GL_PACK_SWAP_BYTES, GL_PACK_LSB_FIRST, GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST}) {
    glPixelStorei(p, 5);
    EXPECT_EQ(get_bool(p), GL_TRUE) << std::hex << p;
    EXPECT_EQ(get_int(p), 1) << std::hex << p;
    glPixelStoref(p, 0.f);
    EXPECT_EQ(get_bool(p), GL_FALSE) << std::hex << p;
  }
}

TEST_F(PixelStoreTest, NegativeValuesAndUnknownNamesChangeNothing) {
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 9);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, -1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glPixelStorei(GL_PACK_SKIP_ROWS, -2);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, -3);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(get_int(GL_UNPACK_ROW_LENGTH), 9);
  EXPECT_EQ(get_int(GL_PACK_SKIP_ROWS), 0);
  EXPECT_EQ(get_int(GL_UNPACK_SKIP_PIXELS), 0);
  glPixelStorei(GL_DEPTH_FUNC, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glPixelStorei(GL_PACK_ALIGNMENT + 1, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_PACK_ALIGNMENT), 4);
}

}  // namespace
}  // namespace pineda::test
