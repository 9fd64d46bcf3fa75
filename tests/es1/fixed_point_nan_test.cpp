// The GLfixed queries of float state that OpenGL ES 1.1 stores as given, NaN among it: NaN reads
// as 0 and values beyond the 16.16 range saturate, never converted with undefined behaviour.
#include <GLES/gl.h>
#include <GLES/glext.h>
#include <gtest/gtest.h>

#include <climits>
#include <limits>

#include "tests/es1/egl_context.h"

namespace pineda::es1_test {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

TEST(FixedPointNan, CurrentColourAndNormal) {
  Es1Context ctx;
  ASSERT_TRUE(ctx.ok()) << ctx.error();
  glColor4f(kNaN, 1e30f, -1e30f, 0.5f);
  glNormal3f(kNaN, 0, 1);
  GLfixed v[4] = {1, 1, 1, 1};
  glGetFixedv(GL_CURRENT_COLOR, v);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(v[0], 0);
  EXPECT_EQ(v[3], 32768);
  glGetFixedv(GL_CURRENT_NORMAL, v);
  EXPECT_EQ(v[0], 0);
  EXPECT_EQ(v[2], 65536);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(FixedPointNan, LightAndClipPlane) {
  Es1Context ctx;
  ASSERT_TRUE(ctx.ok()) << ctx.error();
  const GLfloat ambient[4] = {kNaN, 1e30f, -1e30f, 1};
  glLightfv(GL_LIGHT0, GL_AMBIENT, ambient);
  GLfixed v[4] = {1, 1, 1, 1};
  glGetLightxv(GL_LIGHT0, GL_AMBIENT, v);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(v[0], 0);
  EXPECT_EQ(v[1], INT_MAX);
  EXPECT_EQ(v[2], INT_MIN);
  EXPECT_EQ(v[3], 65536);
  // The plane goes through the inverse modelview matrix: 0 * NaN makes every coefficient NaN.
  const GLfloat plane[4] = {kNaN, 0, 0.5f, 0};
  glClipPlanef(GL_CLIP_PLANE0, plane);
  glGetClipPlanex(GL_CLIP_PLANE0, v);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  for (GLfixed c : v) EXPECT_EQ(c, 0);
}

}  // namespace
}  // namespace pineda::es1_test
