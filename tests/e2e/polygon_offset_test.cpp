// glPolygonOffset: the units term moves depth by the smallest resolvable difference.
#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class PolygonOffsetTest : public GlTest {
 protected:
  SurfaceSpec spec() const override { return {16, 16, 24, 0}; }
  void SetUp() override {
    GlTest::SetUp();
    glClearDepth(1.0);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
  }
  void quad(float z) {
    glBegin(GL_QUADS);
    glVertex3f(-1, -1, z);
    glVertex3f(1, -1, z);
    glVertex3f(1, 1, z);
    glVertex3f(-1, 1, z);
    glEnd();
  }
  // The 24-bit depth step at pixel (8, 8).
  uint32_t depth_step() {
    GLuint d = 0;
    glReadPixels(8, 8, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &d);
    return d >> 8;
  }
};

TEST_F(PolygonOffsetTest, NegativeUnitsPullACoplanarPolygonInFront) {
  glColor3f(1, 0, 0);
  quad(0.2f);
  glColor3f(0, 1, 0);
  quad(0.2f);  // coplanar, GL_LESS: hidden
  EXPECT_TRUE(near_rgba(pixel(8, 8), {255, 0, 0, 255}));
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(0, -2);
  quad(0.2f);
  EXPECT_TRUE(near_rgba(pixel(8, 8), {0, 255, 0, 255}));
}

// r, the depth one unit moves, is two depth-buffer steps (as llvmpipe): one step is not
// resolvable for float positions near the near plane (piglit gl-1.4-polygon-offset).
TEST_F(PolygonOffsetTest, OneUnitIsTwoDepthSteps) {
  glDepthFunc(GL_ALWAYS);
  quad(0.0f);
  const uint32_t base = depth_step();
  EXPECT_EQ(base, 8388608u);  // 0.5 * (2^24 - 1), rounded
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(0, 1);
  quad(0.0f);
  EXPECT_EQ(depth_step(), base + 2);
  glPolygonOffset(0, -3);
  quad(0.0f);
  EXPECT_EQ(depth_step(), base - 6);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(PolygonOffsetTest, OffsetAppliesOnlyToEnabledModes) {
  glColor3f(1, 0, 0);
  quad(0.2f);
  glEnable(GL_POLYGON_OFFSET_LINE);  // not FILL
  glPolygonOffset(0, -2);
  glColor3f(0, 1, 0);
  quad(0.2f);
  EXPECT_TRUE(near_rgba(pixel(8, 8), {255, 0, 0, 255}));
}

TEST_F(PolygonOffsetTest, FactorScalesWithTheSlope) {
  // A quad sloping in depth across x, drawn twice: the second time pushed back by factor 1.
  auto sloped = [] {
    glBegin(GL_QUADS);
    glVertex3f(-1, -1, -0.5f);
    glVertex3f(1, -1, 0.5f);
    glVertex3f(1, 1, 0.5f);
    glVertex3f(-1, 1, -0.5f);
    glEnd();
  };
  glColor3f(1, 0, 0);
  sloped();
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1, 0);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_FALSE);
  glColor3f(0, 0, 1);
  sloped();  // behind the first everywhere: passes GL_GREATER
  EXPECT_TRUE(near_rgba(pixel(3, 8), {0, 0, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(12, 8), {0, 0, 255, 255}));
}

}  // namespace
}  // namespace pineda::test
