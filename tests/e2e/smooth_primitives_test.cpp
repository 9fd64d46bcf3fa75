// GL_POINT_SMOOTH and GL_LINE_SMOOTH through the API: coverage in alpha, blended, restored by
// PopAttrib and compiled into display lists; GL_POLYGON_SMOOTH is kept but not rendered.
#include <vector>

#include "tests/e2e/support/pixel_test.h"

namespace pineda::test {
namespace {

class SmoothPrimitivesTest : public PixelTest {
 protected:
  void SetUp() override {
    PixelTest::SetUp();
    glColor4f(1, 1, 1, 1);
  }
  void horizontal_line(float x0, float x1, float y) {
    glBegin(GL_LINES);
    glVertex2f(x0, y);
    glVertex2f(x1, y);
    glEnd();
  }
};

TEST_F(SmoothPrimitivesTest, LineCoverageIsWrittenToAlpha) {
  glEnable(GL_LINE_SMOOTH);
  glLineWidth(1.5f);
  horizontal_line(2, 12, 8.5f);
  EXPECT_TRUE(near_rgba(pixel(5, 8), {255, 255, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(5, 7), {255, 255, 255, 64}));
  EXPECT_TRUE(near_rgba(pixel(5, 9), {255, 255, 255, 64}));
  EXPECT_TRUE(near_rgba(pixel(5, 10), {0, 0, 0, 0}));
}

TEST_F(SmoothPrimitivesTest, BlendedPointFadesWithItsCoverage) {
  glEnable(GL_POINT_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glPointSize(1.f);
  glBegin(GL_POINTS);
  glVertex2f(8.5f, 8.5f);
  glEnd();
  // Coverage pi/4: red 200 of 255 (the source alpha, 0.785, converted to 8 bits first).
  const Rgba p = pixel(8, 8);
  EXPECT_EQ(p[0], 200);
  EXPECT_EQ(p[3], 157);  // alpha blends too: 200/255 * 200/255 * 255
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), 16 * 16 - 1);
}

TEST_F(SmoothPrimitivesTest, PopAttribRestoresTheEnables) {
  glPushAttrib(GL_LINE_BIT | GL_POINT_BIT);
  glEnable(GL_LINE_SMOOTH);
  glEnable(GL_POINT_SMOOTH);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_LINE_SMOOTH), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_POINT_SMOOTH), GL_FALSE);
  glLineWidth(1.5f);
  horizontal_line(2, 12, 8.5f);  // aliased: width 1.5 rounds to 2 whole rows
  EXPECT_TRUE(near_rgba(pixel(5, 8), {255, 255, 255, 255}));
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 20);
}

TEST_F(SmoothPrimitivesTest, EnableCompiledIntoAList) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glEnable(GL_LINE_SMOOTH);
  glEndList();
  EXPECT_EQ(glIsEnabled(GL_LINE_SMOOTH), GL_FALSE);
  glCallList(list);
  EXPECT_EQ(glIsEnabled(GL_LINE_SMOOTH), GL_TRUE);
  horizontal_line(2.25f, 12.5f, 8.5f);
  EXPECT_EQ(pixel(2, 8)[3], 191);
  EXPECT_EQ(pixel(12, 8)[3], 128);
  glDeleteLists(list, 1);
}

TEST_F(SmoothPrimitivesTest, PolygonSmoothIsKeptButEdgesStayAliased) {
  glEnable(GL_POLYGON_SMOOTH);
  EXPECT_EQ(glIsEnabled(GL_POLYGON_SMOOTH), GL_TRUE);
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glVertex2f(16, 0);
  glVertex2f(0, 16);
  glEnd();
  const std::vector<uint8_t> all = read_all();
  for (size_t i = 3; i < all.size(); i += 4) ASSERT_TRUE(all[i] == 0 || all[i] == 255) << i / 4;
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 120);  // centres on the diagonal belong to no one here
}

}  // namespace
}  // namespace pineda::test
