// Non-finite vertices, huge viewports and coordinates: defined outcomes, no crash.
#include <limits>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class BadInputTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
    glColor3f(1, 1, 1);
  }
};

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

TEST_F(BadInputTest, NonFiniteVerticesDrawNothing) {
  const float bad[] = {kNaN, kInf, -kInf};
  for (float b : bad) {
    // Every primitive has a non-finite vertex.
    for (GLenum mode : {GL_TRIANGLES, GL_LINES, GL_QUADS, GL_TRIANGLE_FAN, GL_POLYGON}) {
      glBegin(mode);
      glVertex2f(b, 2);
      glVertex2f(20, 2);
      glVertex2f(20, b);
      glVertex4f(10, 10, 0, b);
      glEnd();
    }
    glBegin(GL_POINTS);
    glVertex2f(b, 2);
    glVertex2f(20, b);
    glVertex4f(10, 10, 0, b);
    glVertex4f(10, 10, b, 1);
    glEnd();
    glRectf(b, 0, 10, 10);
  }
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(BadInputTest, NonFiniteVertexDoesNotDisturbOtherPrimitives) {
  glBegin(GL_TRIANGLES);
  glVertex2f(kNaN, 0);
  glVertex2f(4, 0);
  glVertex2f(0, 4);
  glVertex2f(10, 10);
  glVertex2f(14, 10);
  glVertex2f(14, 14);
  glEnd();
  EXPECT_TRUE(near_rgba(pixel(13, 11), {255, 255, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(1, 1), {0, 0, 0, 0}));
}

TEST_F(BadInputTest, NonFiniteMatrixDrawsNothing) {
  glMatrixMode(GL_MODELVIEW);
  glScalef(kInf, 1, 1);
  glRecti(0, 0, 10, 10);
  glLoadIdentity();
  glTranslatef(kNaN, 0, 0);
  glRecti(0, 0, 10, 10);
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
}

TEST_F(BadInputTest, NonFiniteColourAndTexCoordDoNotCrash) {
  glColor4f(kNaN, kInf, -kInf, kNaN);
  glTexCoord2f(kNaN, kInf);
  glNormal3f(kNaN, 0, 0);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glRecti(0, 0, 4, 4);
  glDisable(GL_LIGHTING);
  glRecti(4, 4, 8, 8);
  glFinish();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(BadInputTest, HugeCoordinatesAreClippedNotWrapped) {
  glBegin(GL_TRIANGLES);
  glVertex2f(-1e30f, -1e30f);
  glVertex2f(1e30f, -1e30f);
  glVertex2f(0, 1e30f);
  glEnd();
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), width() * height());
}

TEST_F(BadInputTest, ViewportOf16384) {
  glViewport(0, 0, 16384, 16384);
  GLint vp[4];
  glGetIntegerv(GL_VIEWPORT, vp);
  EXPECT_EQ(vp[2], 16384);
  EXPECT_EQ(vp[3], 16384);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 16384, 0, 16384, -1, 1);
  glRecti(3, 4, 10, 9);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 7 * 5);
  EXPECT_TRUE(near_rgba(pixel(3, 4), {255, 255, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(9, 8), {255, 255, 255, 255}));
  // A rectangle far outside the surface but inside the viewport draws nothing here.
  clear_to(0, 0, 0, 0);
  glRecti(10000, 10000, 16000, 16000);
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
  // Covering everything.
  glRecti(0, 0, 16384, 16384);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(BadInputTest, ViewportLargerThanTheMaximumIsClamped) {
  GLint max[2];
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, max);
  glViewport(0, 0, max[0] + 1000, max[1] + 5);
  GLint vp[4];
  glGetIntegerv(GL_VIEWPORT, vp);
  EXPECT_EQ(vp[2], max[0]);
  EXPECT_EQ(vp[3], max[1]);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(BadInputTest, NegativeViewportOriginShiftsTheImage) {
  glViewport(-16, -16, 32, 32);  // the pixel projection's (16, 16) lands on (0, 0)
  glRecti(16, 16, 20, 20);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 16);
  EXPECT_TRUE(near_rgba(pixel(0, 0), {255, 255, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(3, 3), {255, 255, 255, 255}));
}

TEST_F(BadInputTest, IndicesPastTheArrayAreNotReadOutsideTheIndexRange) {
  // DrawElements reads only the vertices its indices name.
  const GLfloat vertices[] = {0, 0, 8, 0, 0, 8};
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, vertices);
  const GLushort indices[] = {0, 1, 2};
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, indices);
  EXPECT_TRUE(near_rgba(pixel(1, 1), {255, 255, 255, 255}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

TEST_F(BadInputTest, ViewportAndScissorFarAwayDrawNothing) {
  glViewport(2147483000, -2147483000, 16384, 16384);
  glRecti(0, 0, 32, 32);
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
  glViewport(0, 0, width(), height());
  glEnable(GL_SCISSOR_TEST);
  glScissor(2147483000, 2147483000, 2147483647, 2147483647);
  glRecti(0, 0, 32, 32);
  clear_to(1, 1, 1, 1);
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
  glScissor(-2147483647, -2147483647, 2147483647, 2147483647);  // ends just below 0
  glRecti(0, 0, 32, 32);
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

// Sizes beyond the reported ranges are clamped to the range when rasterized.
TEST_F(BadInputTest, HugePointSizeAndLineWidthAreClampedToTheirRanges) {
  GLfloat point_range[2], line_range[2];
  glGetFloatv(GL_POINT_SIZE_RANGE, point_range);
  glGetFloatv(GL_LINE_WIDTH_RANGE, line_range);
  ASSERT_GE(point_range[1], 32.f);
  ASSERT_GE(line_range[1], 32.f);
  glPointSize(1e30f);
  glBegin(GL_POINTS);
  glVertex2f(16, 16);
  glEnd();
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), width() * height());
  clear_to(0, 0, 0, 0);
  glLineWidth(1e30f);
  glBegin(GL_LINES);
  glVertex2f(0, 16);
  glVertex2f(32, 16);
  glEnd();
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
