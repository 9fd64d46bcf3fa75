// User clip planes (GL 1.5 section 2.12): eye-space planes fixed by the modelview of their
// specification; triangles and lines are cut, points culled; state, errors, attributes.
#include "tests/e2e/support/pixel_test.h"

namespace pineda::test {
namespace {

constexpr Rgba kWhite{255, 255, 255, 255};

class ClipPlaneTest : public PixelTest {
 protected:
  void SetUp() override {
    PixelTest::SetUp();
    glColor3f(1, 1, 1);
  }
};

TEST_F(ClipPlaneTest, KeepsTheNonNegativeSide) {
  const GLdouble keep_right[4] = {1, 0, 0, -8};  // x >= 8
  glClipPlane(GL_CLIP_PLANE0, keep_right);
  glEnable(GL_CLIP_PLANE0);
  full_quad();
  EXPECT_EQ(count_pixels(kWhite), 8 * 16);
  EXPECT_TRUE(near_rgba(pixel(7, 4), {0, 0, 0, 0}));
  EXPECT_TRUE(near_rgba(pixel(8, 4), kWhite));
}

TEST_F(ClipPlaneTest, TwoPlanesIntersect) {
  const GLdouble right[4] = {1, 0, 0, -8}, below[4] = {0, -1, 0, 4};  // x >= 8 and y <= 4
  glClipPlane(GL_CLIP_PLANE2, right);
  glClipPlane(GL_CLIP_PLANE5, below);
  glEnable(GL_CLIP_PLANE2);
  glEnable(GL_CLIP_PLANE5);
  full_quad();
  EXPECT_EQ(count_pixels(kWhite), 8 * 4);
}

TEST_F(ClipPlaneTest, PlaneIsFixedByTheModelviewAtSpecification) {
  glTranslatef(4, 0, 0);
  const GLdouble p[4] = {1, 0, 0, -8};  // object x >= 8, eye x >= 12
  glClipPlane(GL_CLIP_PLANE1, p);
  glLoadIdentity();
  glEnable(GL_CLIP_PLANE1);
  full_quad();
  EXPECT_EQ(count_pixels(kWhite), 4 * 16);
  GLdouble eq[4];
  glGetClipPlane(GL_CLIP_PLANE1, eq);
  EXPECT_EQ(eq[0], 1.0);
  EXPECT_EQ(eq[1], 0.0);
  EXPECT_EQ(eq[2], 0.0);
  EXPECT_EQ(eq[3], -12.0);
}

TEST_F(ClipPlaneTest, PointsAreCulledLinesCut) {
  const GLdouble keep_right[4] = {1, 0, 0, -8};
  glClipPlane(GL_CLIP_PLANE0, keep_right);
  glEnable(GL_CLIP_PLANE0);
  glBegin(GL_POINTS);
  glVertex2f(3.5f, 3.5f);
  glVertex2f(10.5f, 3.5f);
  glEnd();
  EXPECT_EQ(count_pixels(kWhite), 1);
  EXPECT_TRUE(near_rgba(pixel(10, 3), kWhite));
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_LINES);
  glVertex2f(0, 10.5f);
  glVertex2f(16, 10.5f);
  glEnd();
  EXPECT_EQ(count_pixels(kWhite), 8);
  EXPECT_TRUE(near_rgba(pixel(8, 10), kWhite));
  EXPECT_TRUE(near_rgba(pixel(7, 10), {0, 0, 0, 0}));
}

TEST_F(ClipPlaneTest, DisabledPlaneDoesNothing) {
  const GLdouble nothing[4] = {0, 0, 0, -1};  // clips everything
  glClipPlane(GL_CLIP_PLANE3, nothing);
  full_quad();
  EXPECT_EQ(count_pixels(kWhite), 16 * 16);
  glEnable(GL_CLIP_PLANE3);
  glClear(GL_COLOR_BUFFER_BIT);
  full_quad();
  EXPECT_EQ(count_pixels(kWhite), 0);
}

TEST_F(ClipPlaneTest, ErrorsAndLimits) {
  GLint max = 0;
  glGetIntegerv(GL_MAX_CLIP_PLANES, &max);
  EXPECT_EQ(max, 6);
  const GLdouble p[4] = {1, 2, 3, 4};
  glClipPlane(GL_CLIP_PLANE0 + 6, p);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLdouble eq[4] = {9, 9, 9, 9};
  glGetClipPlane(GL_CLIP_PLANE0 + 6, eq);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(eq[0], 9.0);
  glGetClipPlane(GL_CLIP_PLANE4, eq);  // initially all zero
  EXPECT_EQ(eq[0], 0.0);
  EXPECT_EQ(eq[3], 0.0);
  glEnable(GL_CLIP_PLANE0 + 6);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glBegin(GL_TRIANGLES);
  glClipPlane(GL_CLIP_PLANE0, p);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(ClipPlaneTest, PushPopTransformBit) {
  const GLdouble a[4] = {1, 0, 0, -8}, b[4] = {-1, 0, 0, 2};
  glClipPlane(GL_CLIP_PLANE0, a);
  glEnable(GL_CLIP_PLANE0);
  glPushAttrib(GL_TRANSFORM_BIT);
  glClipPlane(GL_CLIP_PLANE0, b);
  glDisable(GL_CLIP_PLANE0);
  glPopAttrib();
  EXPECT_TRUE(glIsEnabled(GL_CLIP_PLANE0));
  GLdouble eq[4];
  glGetClipPlane(GL_CLIP_PLANE0, eq);
  EXPECT_EQ(eq[3], -8.0);
  full_quad();
  EXPECT_EQ(count_pixels(kWhite), 8 * 16);
}

TEST_F(ClipPlaneTest, CompiledIntoDisplayLists) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  const GLdouble keep_right[4] = {1, 0, 0, -8};
  glClipPlane(GL_CLIP_PLANE0, keep_right);
  glEnable(GL_CLIP_PLANE0);
  glEndList();
  EXPECT_FALSE(glIsEnabled(GL_CLIP_PLANE0));
  glCallList(list);
  full_quad();
  EXPECT_EQ(count_pixels(kWhite), 8 * 16);
  glDeleteLists(list, 1);
}

}  // namespace
}  // namespace pineda::test
