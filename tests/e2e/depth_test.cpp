// Depth test functions, depth writes and read-back for 16-, 24- and 32-bit depth buffers.
#include <cmath>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class DepthTest : public GlTest, public ::testing::WithParamInterface<int> {
 protected:
  SurfaceSpec spec() const override { return {16, 16, GetParam(), 0}; }
  void SetUp() override {
    GlTest::SetUp();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();  // vertices are given in NDC: window z = (z + 1) / 2
    glClearColor(0, 0, 0, 0);
    glClearDepth(0.5);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
  }
  void quad(float z, float r, float g, float b) {
    glColor3f(r, g, b);
    glBegin(GL_QUADS);
    glVertex3f(-1, -1, z);
    glVertex3f(1, -1, z);
    glVertex3f(1, 1, z);
    glVertex3f(-1, 1, z);
    glEnd();
  }
  float depth_at(int x, int y) {
    float d = -1;
    glReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &d);
    return d;
  }
};

TEST_P(DepthTest, DepthBitsAreReported) {
  GLint bits = 0;
  glGetIntegerv(GL_DEPTH_BITS, &bits);
  EXPECT_EQ(bits, GetParam());
}

TEST_P(DepthTest, EveryFunctionAgainstNearerAndFartherFragments) {
  struct Case {
    GLenum func;
    bool nearer_passes, farther_passes;
  };
  const Case cases[] = {{GL_NEVER, false, false}, {GL_LESS, true, false},    {GL_EQUAL, false, false},
                        {GL_LEQUAL, true, false}, {GL_GREATER, false, true}, {GL_NOTEQUAL, true, true},
                        {GL_GEQUAL, false, true}, {GL_ALWAYS, true, true}};
  for (const Case& c : cases) {
    glDepthMask(GL_FALSE);
    glClear(GL_COLOR_BUFFER_BIT);
    glDepthFunc(c.func);
    quad(-0.5f, 1, 0, 0);  // window depth 0.25 against 0.5
    EXPECT_TRUE(near_rgba(pixel(8, 8), c.nearer_passes ? Rgba{255, 0, 0, 255} : Rgba{0, 0, 0, 0}))
        << "func " << std::hex << c.func << " nearer";
    glClear(GL_COLOR_BUFFER_BIT);
    quad(0.5f, 0, 1, 0);  // window depth 0.75
    EXPECT_TRUE(near_rgba(pixel(8, 8), c.farther_passes ? Rgba{0, 255, 0, 255} : Rgba{0, 0, 0, 0}))
        << "func " << std::hex << c.func << " farther";
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_P(DepthTest, EqualPassesForTheSameSurfaceDrawnTwice) {
  glDepthFunc(GL_ALWAYS);
  quad(0.3f, 1, 0, 0);
  glDepthFunc(GL_EQUAL);
  quad(0.3f, 0, 0, 1);
  EXPECT_TRUE(near_rgba(pixel(3, 11), {0, 0, 255, 255}));
}

TEST_P(DepthTest, WritesStoreTheWindowDepth) {
  glDepthFunc(GL_ALWAYS);
  quad(-0.5f, 1, 1, 1);
  const double resolution = 1.0 / ((1ull << std::min(GetParam(), 24)) - 1);
  EXPECT_NEAR(depth_at(5, 5), 0.25, resolution + 1e-7);
  glDepthMask(GL_FALSE);
  quad(0.5f, 1, 1, 1);
  EXPECT_NEAR(depth_at(5, 5), 0.25, resolution + 1e-7);
}

TEST_P(DepthTest, DepthRangeMapsWindowDepth) {
  glDepthFunc(GL_ALWAYS);
  glDepthRange(0.5, 1.0);
  quad(0.0f, 1, 1, 1);
  const double resolution = 1.0 / ((1ull << std::min(GetParam(), 24)) - 1);
  EXPECT_NEAR(depth_at(5, 5), 0.75, resolution + 1e-7);
}

TEST_P(DepthTest, InterpolatedDepthOrdersIntersectingQuads) {
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
  glDepthFunc(GL_LESS);
  // A quad sloping from z = -1 (left) to z = 1 (right), crossing a flat one at z = 0.
  glColor3f(1, 0, 0);
  glBegin(GL_QUADS);
  glVertex3f(-1, -1, -1);
  glVertex3f(1, -1, 1);
  glVertex3f(1, 1, 1);
  glVertex3f(-1, 1, -1);
  glEnd();
  quad(0.0f, 0, 1, 0);
  for (int x = 0; x < 16; ++x) {
    const double sloped = (x + 0.5) / 16;  // window depth of the sloped quad at this column
    if (std::abs(sloped - 0.5) < 0.01) continue;
    EXPECT_TRUE(near_rgba(pixel(x, 7), sloped < 0.5 ? Rgba{255, 0, 0, 255} : Rgba{0, 255, 0, 255})) << x;
  }
}

TEST_P(DepthTest, DisabledDepthTestNeitherTestsNorWrites) {
  glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_NEVER);
  quad(0.5f, 1, 0, 0);
  EXPECT_TRUE(near_rgba(pixel(8, 8), {255, 0, 0, 255}));
  EXPECT_NEAR(depth_at(8, 8), 0.5, 1e-4);
}

INSTANTIATE_TEST_SUITE_P(Bits, DepthTest, ::testing::Values(16, 24, 32));

}  // namespace
}  // namespace pineda::test
