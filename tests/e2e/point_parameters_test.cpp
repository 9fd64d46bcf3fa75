// GL 1.4 point parameters: the derived size size * sqrt(1 / (a + b d + c d^2)) per vertex,
// clamped to [POINT_SIZE_MIN, POINT_SIZE_MAX], measured in pixels; in the normal and the
// reference mode (PINEDA_REFERENCE=1).
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdlib>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

constexpr Rgba kWhite = {255, 255, 255, 255};

class PointParametersTest : public GlTest, public ::testing::WithParamInterface<bool> {
 protected:
  SurfaceSpec spec() const override { return {64, 64, 24, 8}; }
  void SetUp() override {
    if (GetParam()) setenv("PINEDA_REFERENCE", "1", 1);
    GlTest::SetUp();
    unsetenv("PINEDA_REFERENCE");
    // One unit per pixel in x and y; eye z from -1 to -100 is visible.
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-32, 32, -32, 32, 0, 100);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
  }
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }

  void attenuate(float a, float b, float c) {
    const GLfloat v[3] = {a, b, c};
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, v);
  }

  // The pixels a white point of glPointSize `size` at eye depth `z` covers, centred on a pixel.
  int point_pixels(float size, float z, float x = 0.5f) {
    clear_to(0, 0, 0, 0);
    glPointSize(size);
    glColor4f(1, 1, 1, 1);
    glBegin(GL_POINTS);
    glVertex3f(x, 0.5f, z);
    glEnd();
    return count_pixels(kWhite);
  }
};

TEST_P(PointParametersTest, InitialValues) {
  GLfloat v[3] = {-1, -1, -1};
  glGetFloatv(GL_POINT_SIZE_MIN, v);
  EXPECT_EQ(v[0], 0.f);
  GLfloat range[2];
  glGetFloatv(GL_ALIASED_POINT_SIZE_RANGE, range);
  glGetFloatv(GL_POINT_SIZE_MAX, v);
  EXPECT_EQ(v[0], range[1]);
  glGetFloatv(GL_POINT_FADE_THRESHOLD_SIZE, v);
  EXPECT_EQ(v[0], 1.f);
  glGetFloatv(GL_POINT_DISTANCE_ATTENUATION, v);
  EXPECT_EQ(v[0], 1.f);
  EXPECT_EQ(v[1], 0.f);
  EXPECT_EQ(v[2], 0.f);
}

TEST_P(PointParametersTest, QuadraticAttenuationAtEyeDistances) {
  attenuate(0, 0, 1);  // size / d
  EXPECT_EQ(point_pixels(12, -1), 12 * 12);
  EXPECT_EQ(point_pixels(12, -2), 6 * 6);
  EXPECT_EQ(point_pixels(12, -4), 3 * 3);
  EXPECT_EQ(point_pixels(12, -12), 1);
  EXPECT_EQ(point_pixels(12, -48), 1);  // 0.25 is drawn as the smallest point, 1 pixel
}

TEST_P(PointParametersTest, LinearAndConstantAttenuation) {
  attenuate(0, 1, 0);  // size / sqrt(d)
  EXPECT_EQ(point_pixels(10, -25), 2 * 2);
  EXPECT_EQ(point_pixels(10, -4), 5 * 5);
  attenuate(4, 0, 0);  // size / 2 everywhere
  EXPECT_EQ(point_pixels(10, -30), 5 * 5);
  EXPECT_EQ(point_pixels(10, -3), 5 * 5);
  attenuate(1, 0, 0);  // back to no attenuation
  EXPECT_EQ(point_pixels(7, -30), 7 * 7);
}

TEST_P(PointParametersTest, DistanceIsTheEyeDepth) {
  // |z_eye|, as Mesa and piglit's point-attenuation measure it: x does not change the size.
  attenuate(0, 0, 1);
  EXPECT_EQ(point_pixels(12, -4, 20.5f), 3 * 3);
  EXPECT_EQ(point_pixels(12, -4, -20.5f), 3 * 3);
  // The modelview moves the point in eye space.
  glTranslatef(0, 0, -2);
  EXPECT_EQ(point_pixels(12, -2), 3 * 3);
}

TEST_P(PointParametersTest, ClampedToMinAndMax) {
  attenuate(0, 0, 1);
  glPointParameterf(GL_POINT_SIZE_MIN, 5);
  EXPECT_EQ(point_pixels(12, -12), 5 * 5);  // 1 -> 5
  glPointParameterf(GL_POINT_SIZE_MIN, 0);
  glPointParameterf(GL_POINT_SIZE_MAX, 3);
  EXPECT_EQ(point_pixels(12, -2), 3 * 3);  // 6 -> 3
  EXPECT_EQ(point_pixels(12, -12), 1);     // under the maximum: unchanged
  // Without attenuation the glPointSize size is clamped too (as in Mesa).
  attenuate(1, 0, 0);
  EXPECT_EQ(point_pixels(9, -1), 3 * 3);
  // A zero denominator (d = 0 with only c) gives the maximum.
  attenuate(0, 0, 1);
  glPointParameterf(GL_POINT_SIZE_MAX, 7);
  EXPECT_EQ(point_pixels(2, 0), 7 * 7);
}

TEST_P(PointParametersTest, FadeThresholdDoesNotWidenOrFadeWithoutMultisampling) {
  // GL 1.5 3.3: the threshold and the alpha fade apply only under multisample rasterization,
  // which a single-sampled framebuffer never has (as llvmpipe): 3x3 of full alpha.
  attenuate(0, 0, 1);
  glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 10);
  EXPECT_EQ(point_pixels(12, -4), 3 * 3);
  EXPECT_EQ(pixel(32, 32), kWhite);
}

TEST_P(PointParametersTest, EachVertexOfADrawHasItsOwnSize) {
  attenuate(0, 0, 1);
  clear_to(0, 0, 0, 0);
  glPointSize(12);
  glBegin(GL_POINTS);
  glVertex3f(-20.5f, 0.5f, -2);  // 6x6
  glVertex3f(0.5f, 0.5f, -4);    // 3x3
  glVertex3f(20.5f, 0.5f, -12);  // 1x1
  glEnd();
  EXPECT_EQ(count_pixels(kWhite), 36 + 9 + 1);
  // A polygon drawn as points: each vertex is sized by its own depth.
  clear_to(0, 0, 0, 0);
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glBegin(GL_TRIANGLES);
  glVertex3f(-20.5f, -20.5f, -2);
  glVertex3f(20.5f, -20.5f, -4);
  glVertex3f(0.5f, 20.5f, -12);
  glEnd();
  EXPECT_EQ(count_pixels(kWhite), 36 + 9 + 1);
}

TEST_P(PointParametersTest, Errors) {
  glPointParameterf(GL_POINT_SIZE_MIN, -1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glPointParameterf(GL_POINT_SIZE_MAX, -0.5f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glPointParameteri(GL_POINT_FADE_THRESHOLD_SIZE, -2);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glPointParameterf(GL_POINT_SIZE, 2);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLfloat v = -1;
  glGetFloatv(GL_POINT_SIZE_MIN, &v);
  EXPECT_EQ(v, 0.f);
  glGetFloatv(GL_POINT_FADE_THRESHOLD_SIZE, &v);
  EXPECT_EQ(v, 1.f);
}

TEST_P(PointParametersTest, IntegerAndAliasForms) {
  const GLint atten[3] = {2, 3, 4};
  glPointParameteriv(GL_POINT_DISTANCE_ATTENUATION, atten);
  GLfloat v[3];
  glGetFloatv(GL_POINT_DISTANCE_ATTENUATION, v);
  EXPECT_EQ(v[0], 2.f);
  EXPECT_EQ(v[1], 3.f);
  EXPECT_EQ(v[2], 4.f);
  glPointParameterfARB(GL_POINT_SIZE_MIN, 2.5f);
  glGetFloatv(GL_POINT_SIZE_MIN, v);
  EXPECT_EQ(v[0], 2.5f);
  glPointParameterfEXT(GL_POINT_SIZE_MAX, 9.f);
  glGetFloatv(GL_POINT_SIZE_MAX, v);
  EXPECT_EQ(v[0], 9.f);
  const GLfloat fade = 3.f;
  glPointParameterfvEXT(GL_POINT_FADE_THRESHOLD_SIZE, &fade);
  glGetFloatv(GL_POINT_FADE_THRESHOLD_SIZE, v);
  EXPECT_EQ(v[0], 3.f);
}

TEST_P(PointParametersTest, PointBitAndDisplayLists) {
  GLfloat atten[3] = {0, 0, 1};
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, atten);
  glPointParameterf(GL_POINT_SIZE_MIN, 2);
  glEndList();
  atten[2] = 5;  // the list keeps its own copy
  glPushAttrib(GL_POINT_BIT);
  glCallList(list);
  GLfloat v[3];
  glGetFloatv(GL_POINT_DISTANCE_ATTENUATION, v);
  EXPECT_EQ(v[2], 1.f);
  glGetFloatv(GL_POINT_SIZE_MIN, v);
  EXPECT_EQ(v[0], 2.f);
  glPopAttrib();
  glGetFloatv(GL_POINT_DISTANCE_ATTENUATION, v);
  EXPECT_EQ(v[0], 1.f);
  EXPECT_EQ(v[2], 0.f);
  glGetFloatv(GL_POINT_SIZE_MIN, v);
  EXPECT_EQ(v[0], 0.f);
  glDeleteLists(list, 1);
}

INSTANTIATE_TEST_SUITE_P(Modes, PointParametersTest, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& info) { return info.param ? "Reference" : "Fast"; });

}  // namespace
}  // namespace pineda::test
