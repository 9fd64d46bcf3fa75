// The accumulation buffer: glAccum's five operations, glClearAccum, scissor, colour mask.
#include <cmath>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class AccumTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
  }
};

TEST_F(AccumTest, LoadAccumMultAddReturn) {
  clear_to(0.4f, 0.8f, 0.2f, 1.f);  // bytes 102, 204, 51, 255
  glAccum(GL_LOAD, 0.5f);
  clear_to(0, 0, 0, 0);
  glAccum(GL_RETURN, 1.f);
  // Mesa's arithmetic: trunc(0.2 * 0.5 * 32767) = 3276, and 3276 / 32767 * 255 = 25.49.
  EXPECT_EQ(pixel(3, 3), (Rgba{51, 102, 25, 127}));
  clear_to(0.4f, 0.8f, 0.2f, 1.f);
  glAccum(GL_ACCUM, 0.5f);  // the same again: the full colour
  glAccum(GL_RETURN, 1.f);
  EXPECT_EQ(pixel(3, 3), (Rgba{102, 204, 51, 255}));
  glAccum(GL_MULT, 0.25f);
  glAccum(GL_RETURN, 1.f);
  EXPECT_EQ(pixel(3, 3), (Rgba{25, 51, 13, 64}));
  glAccum(GL_ADD, 0.5f);
  glAccum(GL_RETURN, 1.f);
  EXPECT_EQ(pixel(3, 3), (Rgba{153, 178, 140, 191}));
  glAccum(GL_RETURN, 2.f);  // clamped to [0, 1]
  EXPECT_EQ(pixel(3, 3), (Rgba{255, 255, 255, 255}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Found by the API fuzzer (UBSan: NaN converted to short): an infinite value times a zero
// channel accumulates 0; times a non-zero channel the largest value.
TEST_F(AccumTest, InfiniteValueTimesZeroChannelIsZero) {
  clear_to(0.f, 1.f, 0.f, 0.f);
  glAccum(GL_LOAD, INFINITY);
  clear_to(0.2f, 0.2f, 0.2f, 0.2f);
  glAccum(GL_RETURN, 1.f);
  EXPECT_EQ(pixel(3, 3), (Rgba{0, 255, 0, 0}));
  glAccum(GL_MULT, -INFINITY);  // 0 times -inf is 0, 32767 times -inf clamped to -32768
  glAccum(GL_RETURN, 1.f);
  EXPECT_EQ(pixel(3, 3), (Rgba{0, 0, 0, 0}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(AccumTest, ClearAccumAndNegativeValues) {
  glClearAccum(0.5f, 0.f, -1.f, 2.f);  // clamped to [-1, 1]
  GLfloat v[4] = {};
  glGetFloatv(GL_ACCUM_CLEAR_VALUE, v);
  EXPECT_EQ(v[0], 0.5f);
  EXPECT_EQ(v[2], -1.f);
  EXPECT_EQ(v[3], 1.f);
  glClear(GL_ACCUM_BUFFER_BIT);
  clear_to(0, 0, 0, 0);
  glAccum(GL_RETURN, 1.f);
  EXPECT_EQ(pixel(0, 0), (Rgba{127, 0, 0, 255}));
  glAccum(GL_RETURN, -1.f);  // negative values return as 0
  EXPECT_EQ(pixel(0, 0), (Rgba{0, 0, 255, 0}));
  GLint bits = 0;
  glGetIntegerv(GL_ACCUM_RED_BITS, &bits);
  EXPECT_EQ(bits, 16);
}

TEST_F(AccumTest, ScissorLimitsEveryOperation) {
  glClearAccum(0, 0, 0, 0);
  glClear(GL_ACCUM_BUFFER_BIT);
  clear_to(1, 1, 1, 1);
  glEnable(GL_SCISSOR_TEST);
  glScissor(4, 4, 8, 2);
  glAccum(GL_LOAD, 1.f);
  glDisable(GL_SCISSOR_TEST);
  clear_to(0, 0, 1, 0);
  glAccum(GL_RETURN, 1.f);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 8 * 2);
  EXPECT_EQ(pixel(5, 5), (Rgba{255, 255, 255, 255}));
  EXPECT_EQ(pixel(5, 6), (Rgba{0, 0, 0, 0}));  // the accumulation buffer held 0 there
  clear_to(0, 0, 1, 0);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 5, 32);
  glAccum(GL_RETURN, 1.f);  // only x < 5 is written
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 1 * 2);
  EXPECT_EQ(pixel(7, 4), (Rgba{0, 0, 255, 0}));
}

TEST_F(AccumTest, ReturnHonoursTheColorMask) {
  clear_to(1, 1, 1, 1);
  glAccum(GL_LOAD, 1.f);
  clear_to(0, 0, 0, 0);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  glAccum(GL_RETURN, 1.f);
  EXPECT_EQ(pixel(9, 9), (Rgba{255, 0, 255, 0}));
}

TEST_F(AccumTest, AccumulatesDrawingsAsMotionBlur) {
  glClear(GL_ACCUM_BUFFER_BIT);
  for (int frame = 0; frame < 4; ++frame) {
    clear_to(0, 0, 0, 0);
    glColor3f(1, 1, 1);
    glRecti(frame * 4, 0, frame * 4 + 8, 8);  // moves right by 4 each frame
    glAccum(GL_ACCUM, 0.25f);
  }
  glAccum(GL_RETURN, 1.f);
  EXPECT_EQ(pixel(1, 1)[0], 64);    // covered in 1 of 4 frames: trunc(0.25 * 32767) = 8191
  EXPECT_EQ(pixel(5, 1)[0], 127);   // 2 of 4: 16382 / 32767 * 255 = 127.49
  EXPECT_EQ(pixel(13, 1)[0], 127);  // frames 2 and 3
  EXPECT_EQ(pixel(17, 1)[0], 64);   // frame 3 only
  EXPECT_EQ(pixel(21, 1)[0], 0);
}

TEST_F(AccumTest, ErrorsAttribStackAndDisplayLists) {
  glAccum(GL_ADD + 1000, 1.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glBegin(GL_POINTS);
  glAccum(GL_LOAD, 1.f);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));

  glClearAccum(0.25f, 0.25f, 0.25f, 0.25f);
  glPushAttrib(GL_ACCUM_BUFFER_BIT);
  glClearAccum(1, 1, 1, 1);
  glPopAttrib();
  GLfloat v[4] = {};
  glGetFloatv(GL_ACCUM_CLEAR_VALUE, v);
  EXPECT_EQ(v[0], 0.25f);

  clear_to(1, 1, 1, 1);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glAccum(GL_LOAD, 1.f);
  glEndList();
  clear_to(0, 0, 0, 0);
  glCallList(list);  // loads the black buffer
  clear_to(1, 0, 0, 1);
  glAccum(GL_RETURN, 1.f);
  EXPECT_EQ(pixel(2, 2), (Rgba{0, 0, 0, 0}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
